// The Views and Measure panels: the camera's view with the score's error overlay beside the
// shadow map, pass times, and the ground-truth score with its progress.
#include <algorithm>
#include <cfloat>
#include <cstdint>

#include "ViewerApp.h"
#include "ViewerWidgets.h"

namespace gnomon::cli::viewer {
namespace {

// Dear ImGui's OpenGL backend takes a texture's GL name as its ImTextureID.
ImTextureID imguiTexture(unsigned name) {
    return reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(name));
}
ImTextureID imguiTexture(const GlTexture& texture) {
    return imguiTexture(texture.glName);
}
ImTextureID imguiTexture(const gl::Texture& texture) {
    return imguiTexture(texture.id());
}

}  // namespace

void Viewer::views(float x, float mainW, float viewW, float viewH) {
    ImGui::SetNextWindowPos({x, 0});
    ImGui::SetNextWindowSize({viewW, viewH});
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, {0, 0});
    ImGui::Begin("Views", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_NoBringToFrontOnFocus);
    ImGui::PopStyleVar();
    const ImGuiIO& io = ImGui::GetIO();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    if (!mFrameError.empty()) {
        ImGui::PushTextWrapPos(origin.x + mainW - 10);
        ImGui::TextColored({1, 0.4f, 0.4f, 1}, "%s", mFrameError.c_str());
        ImGui::PopTextWrapPos();
    } else if (const GlTexture frame = mRenderer.frameTexture()) {
        const ImVec2 size(float(mDrawnWidth) / io.DisplayFramebufferScale.x,
                          float(mDrawnHeight) / io.DisplayFramebufferScale.y);
        ImGui::Image(imguiTexture(frame), size, {0, 1}, {1, 0});
        const bool hovered = ImGui::IsItemHovered();
        if (mOverlay && mOverlayTexture) {
            ImGui::GetWindowDrawList()->AddImage(
                imguiTexture(mOverlayTexture), origin, {origin.x + size.x, origin.y + size.y},
                {0, 0}, {1, 1}, IM_COL32(255, 255, 255, int(255 * mOverlayOpacity)));
        }
        mouseOnView(hovered, size.y);
    }
    if (mState.side == view::SideView::ShadowMap) {
        ImGui::SetCursorScreenPos({origin.x + mainW, origin.y});
        if (mSideTexture) {
            ImGui::Image(imguiTexture(mSideTexture),
                         {float(mSideTexture.width) / io.DisplayFramebufferScale.x,
                          float(mSideTexture.height) / io.DisplayFramebufferScale.y},
                         {0, 1}, {1, 0});
        } else {
            ImGui::TextDisabled(
                "light %d has no shadow map in this frame\n(off, not "
                "casting, or nothing in view to shadow)",
                mState.selectedLight);
        }
        ImGui::SetCursorScreenPos({origin.x + mainW + 6, origin.y + 4});
        ImGui::TextColored({1, 1, 0.6f, 1}, "light %d: shadow map (darker = nearer)",
                           mState.selectedLight);
    }
    ImGui::End();
}

void Viewer::measurePanel(float x, float y, float width, float height) {
    ImGui::SetNextWindowPos({x, y});
    ImGui::SetNextWindowSize({width, height});
    ImGui::Begin("Measure", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
    ImGui::Columns(2, nullptr, true);
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::Text("%.1f fps   %dx%d   %d map(s), %d rendered, %.1f MiB", io.Framerate, mDrawnWidth,
                mDrawnHeight, mStats.shadowMaps, mStats.shadowPasses,
                double(mStats.shadowMapBytes) / (1024.0 * 1024.0));
    if (mMeasure) {
        for (const PassTiming& p : mStats.passes)
            ImGui::Text("%-28s %7.2f ms", p.name.c_str(), p.milliseconds);
        if (!mMainMs.empty()) {
            ImGui::PlotLines("main ms", mMainMs.data(), int(mMainMs.size()), 0, nullptr, 0.0f,
                             FLT_MAX, {0, 34});
            ImGui::PlotLines("shadow ms", mShadowMs.data(), int(mShadowMs.size()), 0, nullptr, 0.0f,
                             FLT_MAX, {0, 34});
        }
    } else {
        ImGui::TextDisabled("pass timing off (Animation and view > measure passes)");
    }
    ImGui::NextColumn();
    scorePanel();
    ImGui::Columns(1);
    ImGui::End();
}

void Viewer::scorePanel() {
    if (mJob) {
        const int rows = std::max(1, mJob->progress.rows.load());
        ImGui::ProgressBar(float(mJob->progress.rowsDone.load()) / float(rows), {-1, 0},
                           "tracing the reference...");
        if (ImGui::Button("Cancel")) mJob.reset();
        return;
    }
    if (ImGui::Button("Score vs ray-traced truth (F5)")) guarded([&] { startScore(); });
    tooltip(
        "gnomon score's engine: each pixel's shadow against an Embree reference of this "
        "frame (runs in the background)");
    if (!mScoreError.empty()) ImGui::TextColored({1, 0.4f, 0.4f, 1}, "%s", mScoreError.c_str());
    if (!mScore) return;
    const ShadowScore& o = mScore->overall;
    if (mScoredRevision != mState.revision)
        ImGui::TextColored({1, 0.8f, 0.3f, 1}, "(settings changed since this score)");
    ImGui::Text("misclassified %.2f%%   mean |error| %.3f   (traced in %.2f s)",
                100.0 * o.misclassified, o.meanAbsError, mScore->traceSeconds);
    ImGui::Text("false shadow %.2f%%   leak %.2f%%", 100.0 * o.falseShadow, 100.0 * o.leak);
    ImGui::Text("away from edges: false shadow %.2f%%, leak %.2f%%",
                100.0 * o.falseShadowOutsideBand, 100.0 * o.leakOutsideBand);
    ImGui::Checkbox("error overlay", &mOverlay);
    tooltip("red: false shadow (acne), blue: light leak; pale inside the aliasing band");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(120);
    ImGui::SliderFloat("opacity", &mOverlayOpacity, 0.0f, 1.0f);
}

}  // namespace gnomon::cli::viewer
