// The Views and Measure panels: the camera's view with the score's error overlay beside the
// shadow map, pass times, and the ground-truth score with its progress.
#include <algorithm>
#include <cfloat>
#include <cstdint>
#include <cstdio>
#include <string>

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
        mViewRect = {origin.x, origin.y, size.x, size.y};
        const bool hovered = ImGui::IsItemHovered();
        if (mOverlay && mOverlayTexture) {
            ImGui::GetWindowDrawList()->AddImage(
                imguiTexture(mOverlayTexture), origin, {origin.x + size.x, origin.y + size.y},
                {0, 0}, {1, 1}, IM_COL32(255, 255, 255, int(255 * mOverlayOpacity)));
        }
        mouseOnView(hovered, size.y, lightIcons(origin, size, hovered));
    }
    if (mState.side == view::SideView::ShadowMap) {
        ImGui::SetCursorScreenPos({origin.x + mainW, origin.y});
        if (mSideTexture) {
            const ImVec2 sideOrigin = ImGui::GetCursorScreenPos();
            const ImVec2 sideSize(float(mSideTexture.width) / io.DisplayFramebufferScale.x,
                                  float(mSideTexture.height) / io.DisplayFramebufferScale.y);
            ImGui::Image(imguiTexture(mSideTexture), sideSize, {0, 1}, {1, 0});
            cubeFaceLabels(sideOrigin, sideSize);
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

// Where a directional light's icon goes: towards the light from the view's centre, as far as
// it is seen, else at the view's border in that direction (a sun over the camera's shoulder
// is behind it). False when the view's centre itself does not project.
template <typename Project>
bool sunOnView(const Camera& cam, const glm::vec3& direction, const Project& project,
               const ImVec2& origin, const ImVec2& size, ImVec2& out) {
    const float reach = 0.5f * glm::length(cam.centre - cam.eye);
    const glm::vec3 toSun = -glm::normalize(direction);
    const float margin = 22.0f;
    const auto inside = [&](const ImVec2& q) {
        return q.x >= origin.x + margin && q.x <= origin.x + size.x - margin &&
               q.y >= origin.y + margin && q.y <= origin.y + size.y - margin;
    };
    if (project(cam.centre + toSun * reach, out) && inside(out)) return true;
    ImVec2 c, q;
    if (!project(cam.centre, c) || !project(cam.centre + toSun * (0.01f * reach), q)) return false;
    float dx = q.x - c.x, dy = q.y - c.y;
    const float length = std::sqrt(dx * dx + dy * dy);
    if (length < 1e-4f) {
        dx = 0.0f;  // straight at the camera: the top edge
        dy = -1.0f;
    } else {
        dx /= length;
        dy /= length;
    }
    const float inf = 1e9f;
    const float tx = dx > 0.0f   ? (origin.x + size.x - margin - c.x) / dx
                     : dx < 0.0f ? (origin.x + margin - c.x) / dx
                                 : inf;
    const float ty = dy > 0.0f   ? (origin.y + size.y - margin - c.y) / dy
                     : dy < 0.0f ? (origin.y + margin - c.y) / dy
                                 : inf;
    const float t = std::max(0.0f, std::min(tx, ty));
    out = {c.x + dx * t, c.y + dy * t};
    return true;
}

// Each light as an icon over the camera's view, in its colour, ringed when selected: a disc at
// a point, spot or area light's position (a spot's with a stroke along its axis), a sun
// (disc and rays) towards a directional light from the view's centre (sunOnView). Returns the
// light whose icon the mouse is over, or -1.
int Viewer::lightIcons(const ImVec2& origin, const ImVec2& size, bool hovered) {
    const Camera& cam = mState.scene.camera;
    const glm::mat4 clipFromWorld = cameraClipFromWorld(cam, size.x / std::max(size.y, 1.0f));
    const auto project = [&](const glm::vec3& p, ImVec2& out) {
        const glm::vec4 c = clipFromWorld * glm::vec4(p, 1.0f);
        if (!(c.w > 0.0f)) return false;
        out = {origin.x + (0.5f + 0.5f * c.x / c.w) * size.x,
               origin.y + (0.5f - 0.5f * c.y / c.w) * size.y};
        return true;
    };
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->PushClipRect(origin, {origin.x + size.x, origin.y + size.y}, true);
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    const float reach = 0.5f * glm::length(cam.centre - cam.eye);
    const float radius = 7.0f;
    int under = -1;
    for (std::size_t i = 0; i < mState.scene.lights.size(); ++i) {
        const Light& l = mState.scene.lights[i];
        const bool sun = l.type == LightType::Directional;
        ImVec2 p;
        if (sun ? !sunOnView(cam, l.direction, project, origin, size, p) : !project(l.position, p))
            continue;
        // The light's hue at full brightness: dim colours still read as icons.
        const float peak = std::max({l.colour.r, l.colour.g, l.colour.b, 1e-6f});
        const glm::vec3 c = glm::clamp(l.colour / peak, 0.0f, 1.0f);
        const ImU32 colour =
            IM_COL32(int(255 * c.r), int(255 * c.g), int(255 * c.b), l.enabled ? 255 : 90);
        const ImU32 edge = IM_COL32(20, 20, 24, 220);
        if (sun) {
            for (int k = 0; k < 8; ++k) {
                const float a = float(k) * 0.785398f;
                draw->AddLine(
                    {p.x + 1.5f * radius * std::cos(a), p.y + 1.5f * radius * std::sin(a)},
                    {p.x + 2.1f * radius * std::cos(a), p.y + 2.1f * radius * std::sin(a)}, colour,
                    2.0f);
            }
        } else if (l.type == LightType::Spot) {
            ImVec2 tip;
            if (project(l.position + glm::normalize(l.direction) * (0.25f * reach), tip))
                draw->AddLine(p, tip, colour, 2.0f);
        }
        draw->AddCircleFilled(p, radius, colour);
        draw->AddCircle(p, radius, edge, 0, 1.5f);
        if (int(i) == mState.selectedLight)
            draw->AddCircle(p, radius + 4.0f, IM_COL32(255, 255, 160, 255), 0, 2.0f);
        const float dx = mouse.x - p.x, dy = mouse.y - p.y;
        if (hovered && dx * dx + dy * dy <= (radius + 4.0f) * (radius + 4.0f)) {
            under = int(i);
            tooltip("light " + std::to_string(i) + ": " + l.name + " (" + toString(l.type) +
                    "); drag to move it");
        }
    }
    draw->PopClipRect();
    return under;
}

// A point light's six faces, as the side view lays them out (DebugPass: two rows of three
// square panels, centred): +X -X +Y over -Y +Z -Z.
void Viewer::cubeFaceLabels(const ImVec2& origin, const ImVec2& size) {
    const int light = mState.selectedLight;
    if (light < 0 || light >= int(mState.scene.lights.size()) ||
        mState.scene.lights[std::size_t(light)].type != LightType::Point) {
        return;
    }
    static const char* const kFaces[6] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
    const float panel = std::min(size.x / 3.0f, size.y / 2.0f);
    const float x0 = origin.x + 0.5f * (size.x - 3.0f * panel);
    const float y0 = origin.y + 0.5f * (size.y - 2.0f * panel);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    for (int face = 0; face < 6; ++face) {
        const ImVec2 at(x0 + float(face % 3) * panel + 5.0f, y0 + float(face / 3) * panel + 4.0f);
        draw->AddRectFilled({at.x - 3, at.y - 1}, {at.x + 24, at.y + 17}, IM_COL32(0, 0, 0, 150));
        draw->AddText(at, IM_COL32(255, 255, 160, 255), kFaces[face]);
    }
}

void Viewer::measurePanel(float x, float y, float width, float height) {
    ImGui::SetNextWindowPos({x, y});
    ImGui::SetNextWindowSize({width, height});
    ImGui::Begin("Measure", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
    ImGui::Columns(2, nullptr, true);
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::TextWrapped("%.1f fps   %dx%d   %d map(s), %d rendered, %.1f MiB", io.Framerate,
                       mDrawnWidth, mDrawnHeight, mStats.shadowMaps, mStats.shadowPasses,
                       double(mStats.shadowMapBytes) / (1024.0 * 1024.0));
    if (mMeasure) {
        passTimes();
    } else {
        ImGui::TextDisabled("pass timing off (Scene > Animation and view > measure passes)");
    }
    ImGui::NextColumn();
    scorePanel();
    tunePanel();
    ImGui::Columns(1);
    ImGui::End();
}

// The frame's passes in little room: the passes other than shadow maps on one line, the shadow
// passes as their total and slowest, the history as two plots, and each shadow pass in a
// table of as many columns as fit, folded by default (mixed-lights has sixteen).
void Viewer::passTimes() {
    std::string others;
    double shadow = 0.0, slowest = 0.0;
    std::string slowestName;
    int shadowPasses = 0;
    for (const PassTiming& p : mStats.passes) {
        if (p.light < 0) {
            char part[96];
            std::snprintf(part, sizeof part, "%s%s %.2f", others.empty() ? "" : "  ·  ",
                          p.name.c_str(), p.milliseconds);
            others += part;
            continue;
        }
        shadow += p.milliseconds;
        ++shadowPasses;
        if (p.milliseconds >= slowest) {
            slowest = p.milliseconds;
            slowestName = p.name;
        }
    }
    ImGui::TextWrapped("%s ms", others.c_str());
    if (shadowPasses > 0) {
        ImGui::TextWrapped("%d shadow pass(es) %.2f ms, slowest %s %.2f ms", shadowPasses, shadow,
                           slowestName.c_str(), slowest);
    }
    if (!mMainMs.empty()) {
        ImGui::PlotLines("main ms", mMainMs.data(), int(mMainMs.size()), 0, nullptr, 0.0f, FLT_MAX,
                         {0, 30});
        ImGui::PlotLines("shadow ms", mShadowMs.data(), int(mShadowMs.size()), 0, nullptr, 0.0f,
                         FLT_MAX, {0, 30});
    }
    if (shadowPasses == 0 || !ImGui::TreeNode("each shadow pass")) return;
    const int columns = std::clamp(int(ImGui::GetContentRegionAvail().x / 150.0f), 1, 4);
    if (ImGui::BeginTable("passes", columns, ImGuiTableFlags_SizingStretchSame)) {
        for (const PassTiming& p : mStats.passes) {
            if (p.light < 0) continue;
            ImGui::TableNextColumn();
            ImGui::Text("%s %.2f", p.name.c_str() + (p.name.rfind("shadow ", 0) == 0 ? 7 : 0),
                        p.milliseconds);
        }
        ImGui::EndTable();
    }
    ImGui::TreePop();
}

void Viewer::scorePanel() {
    if (mJob) {
        const int rows = std::max(1, mJob->task->rows());
        ImGui::ProgressBar(float(mJob->task->rowsDone()) / float(rows), {-1, 0},
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
    ImGui::TextWrapped("misclassified %.2f%%   mean |error| %.3f   (traced in %.2f s)",
                       100.0 * o.misclassified, o.meanAbsError, mScore->traceSeconds);
    ImGui::TextWrapped("false shadow %.2f%%   leak %.2f%%", 100.0 * o.falseShadow, 100.0 * o.leak);
    ImGui::TextWrapped("away from edges: false shadow %.2f%%, leak %.2f%%",
                       100.0 * o.falseShadowOutsideBand, 100.0 * o.leakOutsideBand);
    const ErrorCauses& k = mScore->causes;
    if (k.falseShadowGrazing + k.falseShadowOther + k.leakGrazing + k.leakContact + k.leakOther >
        0) {
        ImGui::TextWrapped(
            "  of them, pixels: false shadow %ld grazed, %ld other; leak %ld grazed, %ld at "
            "contacts, %ld other",
            k.falseShadowGrazing, k.falseShadowOther, k.leakGrazing, k.leakContact, k.leakOther);
        tooltip(
            "grazed: the surface within 5.7 degrees of edge-on to the light (the map's "
            "resolution limit); at contacts: the occluder within 4 map texels of the surface; "
            "gnomon score writes every error to errors.csv");
    }
    if (mScore->tint.cells > 0) {
        ImGui::TextWrapped(
            "tinted light (coloured shadows): off by %.2f/255 on average, its colour %.2f/255",
            255.0 * mScore->tint.meanError, 255.0 * mScore->tint.meanColourError);
        tooltip(
            "the light blended casters let through against the reference's, over the "
            "pixels they tint (gnomon score writes tint-errors.png); its colour: where both "
            "let light past the opaque casters");
    }
    if (mScore->contactRange > 0.0f) {
        ImGui::TextWrapped("at contacts: %.2f%% of %ld shadowed pixels lit", 100.0 * o.contactLeak,
                           o.contactPixels);
        tooltip(
            "the leak over the pixels whose occluder lies within the contact shadows' march "
            "(gnomon score --contact-range)");
    }
    if (mScore->otherSurfacePixels > 0) {
        ImGui::TextWrapped("not scored: %ld pixels", mScore->otherSurfacePixels);
        tooltip(
            "where the render drew another surface than the reference sees, or none (a part "
            "seen edge-on, an alpha mask at another mip level)");
    }
    if (!mOverlayTexture) {
        ImGui::TextDisabled("error overlay: dropped with the frame it scored (F5 scores again)");
        return;
    }
    ImGui::Checkbox("error overlay", &mOverlay);
    tooltip("red: false shadow (acne), blue: light leak; pale inside the aliasing band");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(120);
    ImGui::SliderFloat("opacity", &mOverlayOpacity, 0.0f, 1.0f);
}

void Viewer::tunePanel() {
    ImGui::Separator();
    if (mTuneJob) {
        std::string latest;
        {
            const std::lock_guard<std::mutex> lock(mTuneJob->mutex);
            latest = mTuneJob->latest;
        }
        ImGui::Text("tuning: trial %d", mTuneJob->trials.load() + 1);
        ImGui::TextWrapped("last: %s", latest.c_str());
        if (ImGui::Button("Stop tuning")) mTuneJob->cancelled = true;
        tooltip("keeps the best found so far");
        return;
    }
    if (ImGui::Button("Tune settings vs truth")) guarded([&] { startTune(); });
    tooltip(
        "gnomon tune for this view: searches filter, map size, tolerances and cascades for the "
        "least error against the ray-traced reference within this view's frame time, at up to "
        "384 pixels, in the background");
    if (!mTuneError.empty()) ImGui::TextColored({1, 0.4f, 0.4f, 1}, "%s", mTuneError.c_str());
    if (!mTune) return;
    const TuneTrial& start = mTune->trials.front();
    if (mTune->best <= 0) {
        ImGui::TextWrapped(
            "%zu trials: the settings tuned were already the best within %.1f ms "
            "(%.3f%% misclassified)",
            mTune->trials.size(), mTune->budgetMs, 100.0 * start.misclassified);
        return;
    }
    const TuneTrial& best = mTune->trials[std::size_t(mTune->best)];
    ImGui::TextWrapped("%zu trials; best within %.1f ms: %s", mTune->trials.size(), mTune->budgetMs,
                       best.flags.c_str());
    ImGui::TextWrapped("misclassified %.3f%% (from %.3f%%), %.1f ms", 100.0 * best.misclassified,
                       100.0 * start.misclassified, best.frameMs);
    if (mTune->shifted.done && !mTune->shifted.holds) {
        ImGui::TextWrapped(
            "not borne out with the view moved half a pixel: the gain is the pixel grid's, so "
            "Apply keeps the current settings");
    }
    if (mTunedRevision != mState.revision)
        ImGui::TextColored({1, 0.8f, 0.3f, 1}, "(settings changed since this tune)");
    if (ImGui::Button("Apply")) guarded([&] { applyTune(); });
}

}  // namespace gnomon::cli::viewer
