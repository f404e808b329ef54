// The Controls panel: the scene, camera and lights being edited and every render option, each
// change bumping the state's revision so the views redraw.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ViewerApp.h"
#include "ViewerWidgets.h"

namespace gnomon::cli::viewer {

// The controls in four tabs, each short enough for a 1280x720 or 800x600 window without
// scrolling (the script's `expect-fits` checks it): the scene, the view and the Output
// options; the lights; then the options' other groups under headers of their help titles,
// each group in the tab tabOf() gives it.
void Viewer::controls(float width, float height) {
    ImGui::SetNextWindowPos({0, 0});
    ImGui::SetNextWindowSize({width, height});
    ImGui::Begin("Controls", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                     ImGuiWindowFlags_NoTitleBar);
    ImGui::PushItemWidth(width * 0.5f);
    if (ImGui::BeginTabBar("controls")) {
        for (int tab = 0; tab < 4; ++tab) {
            const ImGuiTabItemFlags flags =
                mSelectTab == tab ? ImGuiTabItemFlags_SetSelected : ImGuiTabItemFlags_None;
            if (!ImGui::BeginTabItem(kControlTabs[tab], nullptr, flags)) continue;
            mTab = tab;
            if (tab == 0) {
                sceneControls();
                cameraControls();
                outputControls();
            } else if (tab == 1) {
                lightControls();
            } else {
                groupControls(tab);
            }
            ImGui::EndTabItem();
        }
        ImGui::EndTabBar();
    }
    mSelectTab = -1;
    ImGui::PopItemWidth();
    mControlsOverflow = ImGui::GetScrollMaxY();  // 0 when the tab fits
    ImGui::End();
}

// The tab holding `group`'s options: the Output group's with the view's toggles, the map's
// and its tolerances on Shadows, the lookup's and the shading's on Filter.
int Viewer::tabOf(OptionGroup group) {
    switch (group) {
        case OptionGroup::Output:
            return 0;
        case OptionGroup::ShadowMaps:
        case OptionGroup::Tolerances:
            return 2;
        case OptionGroup::Filtering:
        case OptionGroup::Cascades:
        case OptionGroup::Shading:
            return 3;
    }
    return 3;
}

// Each group of `tab` under a header of its title, its options in schema order.
void Viewer::groupControls(int tab) {
    const OptionSpec* previous = nullptr;
    for (const OptionSpec& spec : optionSchema()) {
        const bool first = !previous || previous->group != spec.group;
        previous = &spec;
        if (!first || tabOf(spec.group) != tab) continue;
        if (!ImGui::CollapsingHeader(toString(spec.group), ImGuiTreeNodeFlags_DefaultOpen))
            continue;
        optionControls(spec.group);
        if (spec.group == OptionGroup::Shading) {
            changed(ImGui::ColorEdit3("ambient", &mState.scene.ambient.x));
            tooltip("the scene's ambient light colour, times each material's colour");
            ImGui::TextDisabled("shininess: per material, from the scene");
        }
    }
}

void Viewer::optionControls(OptionGroup group) {
    for (const OptionSpec& spec : optionSchema()) {
        if (spec.group == group) optionControl(spec);
    }
}

// The schema's widget (optionWidget), but for the few options whose control needs more
// than their range: the size beside the fit-to-window toggle, the map size as a power of two
// over each light's own, a light index within the scene's; and the debug view, which
// changes only what is drawn (a score of the frame still holds).
void Viewer::optionControl(const OptionSpec& spec) {
    const RenderOptions& o = mState.options;
    const void* field = spec.field(o);
    if (field == &o.width) {
        sizeControl(spec);
    } else if (field == &o.shadow.mapSize) {
        mapSizeControl(spec);
    } else if (field == &o.lightOnly) {
        lightOnlyControl(spec);
    } else if (field == &o.debugView) {
        if (option(spec)) ++mState.viewRevision;
    } else {
        changed(option(spec));
    }
}

int Viewer::tabIndex(const std::string& name) {
    for (int tab = 0; tab < 4; ++tab)
        if (name == kControlTabs[tab]) return tab;
    return -1;
}

// The option's one-line doc as the last item's tooltip, looked up only while hovered.
void Viewer::flagTip(const OptionSpec& spec) {
    if (ImGui::IsItemHovered()) tooltip(mDocs("--" + std::string(spec.name)));
}

// The option's widget, its range the schema's, with its flag's doc as the tooltip. Dimmed,
// still editable, when the other options make it pointless (and its tooltip says what it
// needs).
bool Viewer::option(const OptionSpec& spec) {
    const bool pointless = spec.matters && !spec.matters(mState.options);
    if (pointless) ImGui::PushStyleVar(ImGuiStyleVar_Alpha, 0.45f);
    const bool c = optionWidget(spec, mState.options);
    if (pointless) ImGui::PopStyleVar();
    if (ImGui::IsItemHovered()) {
        tooltip(mDocs("--" + std::string(spec.name)) +
                (pointless
                     ? std::string("\n(no effect now: applies only with ") + spec.onlyWith + ")"
                     : std::string()));
    }
    return c;
}

void Viewer::changed(bool c) {
    if (c) ++mState.revision;
}

void Viewer::guarded(const std::function<void()>& action) {
    try {
        action();
        mUiError.clear();
    } catch (const Error& e) {
        // Shown in the panel, and said where scripts and logs see it: a failed screenshot or
        // save fails a script.
        mUiError = e.what();
        if (mScripted) {
            fail(e.what());
        } else {
            std::fprintf(stderr, "gnomon view: error: %s\n", e.what());
        }
    }
}

void Viewer::sceneControls() {
    if (mState.source != mShownSource) {  // loaded by a preset, a script or Load
        mShownSource = mSourceField = mState.source;
        mSavePath = mState.scene.name + "-tuned.json";
    }
    if (!ImGui::CollapsingHeader("Scene", ImGuiTreeNodeFlags_DefaultOpen)) return;
    // The combo names a built-in scene; a file loaded instead shows in the field below.
    static const std::vector<SceneInfo> builtins = builtinScenes();  // fixed: read once
    const bool isBuiltin = std::any_of(builtins.begin(), builtins.end(),
                                       [&](const SceneInfo& s) { return s.name == mState.source; });
    if (ImGui::BeginCombo("built-in", isBuiltin ? mState.source.c_str() : "(a file, below)")) {
        for (const SceneInfo& s : builtins) {
            if (ImGui::Selectable(s.name.c_str(), s.name == mState.source)) {
                guarded([&] { view::applyFlags(mState, {"--scene", s.name}); });
            }
            tooltip(s.description);
        }
        ImGui::EndCombo();
    }
    tooltip("a built-in scene; for a scene file or a model file, type its path below");
    inputText("file", mSourceField);
    ImGui::SameLine();
    if (ImGui::Button("Load"))
        guarded([&] { view::applyFlags(mState, {"--scene", mSourceField}); });
    bool ground = mState.ground;
    if (ImGui::Checkbox("ground", &ground)) {
        guarded([&] { view::load(mState, mState.source, ground); });
    }
    if (ImGui::IsItemHovered())
        tooltip(mDocs("--ground") + " (reloads the scene: its lights and camera restart)");
    if (ImGui::BeginCombo("preset", "choose...")) {
        std::string group;
        for (const view::PresetEntry& p : view::presets()) {
            if (p.group != group) {
                group = p.group;
                ImGui::TextDisabled("%s", group.c_str());
            }
            if (ImGui::Selectable(p.name.c_str())) guarded([&] { view::applyPreset(mState, p); });
            std::string flags;
            for (const std::string& a : p.args)
                flags += (flags.empty() ? "" : " ") + a;
            tooltip(flags);
        }
        ImGui::EndCombo();
    }
    tooltip(
        "Start from gnomon's defaults, the textbook's numbers for this scene, or one of "
        "docs/techniques.md's examples (which load their scene).");
    inputText("save as", mSavePath);
    ImGui::SameLine();
    if (ImGui::Button("Save")) guarded([&] { save(mSavePath); });
    tooltip(
        "Write a scene file (docs/scene-file.md) that `gnomon render --scene FILE` "
        "renders exactly as this view");
    if (ImGui::Button("Screenshot (F12)")) guarded([&] { screenshot(nextScreenshotPath()); });
    if (!mUiError.empty()) ImGui::TextColored({1, 0.4f, 0.4f, 1}, "%s", mUiError.c_str());
    if (!mLastWritten.empty()) ImGui::TextDisabled("wrote %s", mLastWritten.c_str());
}

void Viewer::cameraControls() {
    if (!ImGui::CollapsingHeader("Camera")) return;
    Camera& c = mState.scene.camera;
    ImGui::TextDisabled("drag: orbit, shift+drag or middle: pan, wheel: zoom");
    changed(ImGui::DragFloat3("eye", &c.eye.x, 0.05f));
    changed(ImGui::DragFloat3("centre", &c.centre.x, 0.05f));
    int projection = c.projection == Projection::Perspective ? 0 : 1;
    if (ImGui::Combo("projection", &projection, "perspective\0orthographic\0")) {
        c.projection = projection == 0 ? Projection::Perspective : Projection::Orthographic;
        changed(true);
    }
    if (c.projection == Projection::Perspective) {
        changed(ImGui::SliderFloat("fovy", &c.fovyDegrees, 5.0f, 120.0f, "%.1f deg"));
    } else {
        changed(ImGui::DragFloat4("l r b t", &c.left, 0.05f));
    }
    changed(ImGui::DragFloat("near", &c.near, 0.01f, 0.001f, c.far * 0.999f, "%.3f"));
    changed(ImGui::DragFloat("far", &c.far, 0.5f, c.near * 1.001f, 1e6f, "%.1f"));
}

void Viewer::lightControls() {
    ImGui::Spacing();
    std::vector<Light>& lights = mState.scene.lights;
    if (lights.empty()) {
        ImGui::TextDisabled("this scene has no lights");
        return;
    }
    mState.selectedLight = std::clamp(mState.selectedLight, 0, int(lights.size()) - 1);
    auto labelOf = [&](int i) {
        const Light& l = lights[std::size_t(i)];
        return std::to_string(i) + ": " + (l.name.empty() ? toString(l.type) : l.name);
    };
    if (ImGui::BeginCombo("light", labelOf(mState.selectedLight).c_str())) {
        for (int i = 0; i < int(lights.size()); ++i) {
            if (ImGui::Selectable(labelOf(i).c_str(), i == mState.selectedLight))
                mState.selectedLight = i;
        }
        ImGui::EndCombo();
    }
    tooltip("The light whose controls are below and whose shadow map the side view shows");
    Light& l = lights[std::size_t(mState.selectedLight)];
    ImGui::TextDisabled("right-drag in the view: move this light");
    changed(ImGui::Checkbox("on", &l.enabled));
    ImGui::SameLine();
    changed(ImGui::Checkbox("casts shadows", &l.castsShadows));
    int type = int(l.type);
    if (ImGui::Combo("type", &type, "directional\0spot\0point\0area\0")) {
        l.type = LightType(type);
        changed(true);
    }
    if (l.type != LightType::Directional)
        changed(ImGui::DragFloat3("position", &l.position.x, 0.05f));
    if (l.type != LightType::Point) changed(ImGui::DragFloat3("direction", &l.direction.x, 0.01f));
    changed(ImGui::ColorEdit3("colour", &l.colour.x));
    changed(ImGui::DragFloat("intensity", &l.intensity, 0.01f, 0.0f, 1e6f));
    if (l.type != LightType::Directional) {
        changed(ImGui::DragFloat3("attenuation", &l.attenuation.constant, 0.001f, 0.0f, 100.0f,
                                  "%.4f"));
        tooltip("1 / (constant + linear d + quadratic d^2)");
        changed(ImGui::DragFloat("range", &l.range, 0.1f, 0.0f, 1e6f));
        tooltip("point and spot lights end here (0: unlimited)");
    }
    if (l.type == LightType::Spot) {
        changed(ImGui::SliderFloat("inner cone", &l.innerConeDegrees, 0.0f, l.outerConeDegrees,
                                   "%.1f deg"));
        changed(ImGui::SliderFloat("outer cone", &l.outerConeDegrees, l.innerConeDegrees, 89.0f,
                                   "%.1f deg"));
    }
    int mapSizeLog = int(std::lround(std::log2(shadowMapSizeOf(l))));
    if (ImGui::SliderInt("map size", &mapSizeLog, 6, 13, "")) {
        l.shadowMapSize = 1 << mapSizeLog;
        changed(true);
    }
    ImGui::SameLine();
    const bool cubeDefault = l.type == LightType::Point && l.shadowMapSize == 0 &&
                             l.shadowCamera.policy == ShadowCameraPolicy::Fit;
    if (cubeDefault)
        ImGui::Text("%d (%d per cube face)", shadowMapSizeOf(l), kDefaultCubeFaceSize);
    else
        ImGui::Text("%d", shadowMapSizeOf(l));
    tooltip("this light's shadow map, texels per side (--map-size overrides every light)");
    ShadowCamera& sc = l.shadowCamera;
    int policy = int(sc.policy);
    if (ImGui::Combo("light camera", &policy, "fit\0manual\0course\0")) {
        sc.policy = ShadowCameraPolicy(policy);
        changed(true);
    }
    if (ImGui::IsItemHovered())
        tooltip(std::string("how the shadow camera is placed: ") + toString(sc.policy) +
                ". fit: around what can be shadowed; manual: the numbers below; course: "
                "looking at the view's centre");
    if (sc.policy != ShadowCameraPolicy::Fit) {
        int proj = sc.projection == Projection::Perspective ? 0 : 1;
        if (ImGui::Combo("light projection", &proj, "perspective\0orthographic\0")) {
            sc.projection = proj == 0 ? Projection::Perspective : Projection::Orthographic;
            changed(true);
        }
        if (sc.policy == ShadowCameraPolicy::Manual)
            changed(ImGui::DragFloat3("target", &sc.target.x, 0.05f));
        if (sc.projection == Projection::Perspective) {
            changed(ImGui::SliderFloat("light fovy", &sc.fovyDegrees, 1.0f, 170.0f));
        } else {
            changed(ImGui::DragFloat4("light l r b t", &sc.left, 0.05f));
        }
        changed(ImGui::DragFloat("light near", &sc.near, 0.01f, 0.001f, sc.far * 0.999f));
        changed(ImGui::DragFloat("light far", &sc.far, 0.1f, sc.near * 1.001f, 1e6f));
    }
}

void Viewer::mapSizeControl(const OptionSpec& spec) {
    ShadowOptions& s = mState.options.shadow;
    bool override = s.mapSize > 0;
    if (ImGui::Checkbox("##override", &override)) {
        s.mapSize = override ? firstCasterMapSize(mState.scene, s) : 0;
        changed(true);
    }
    tooltip("override every light's map size");
    ImGui::SameLine();
    if (override) {
        int log = int(std::lround(std::log2(std::max(s.mapSize, 64))));
        if (ImGui::SliderInt(spec.name, &log, 6, 13, "")) {
            s.mapSize = 1 << log;
            changed(true);
        }
        ImGui::SameLine();
        ImGui::Text("%d", s.mapSize);
    } else {
        ImGui::TextDisabled("%s: each light's own", spec.name);
    }
    flagTip(spec);
}

// The animation's clock, the Output options and the view's own toggles.
void Viewer::outputControls() {
    if (!ImGui::CollapsingHeader(toString(OptionGroup::Output), ImGuiTreeNodeFlags_DefaultOpen))
        return;
    if (ImGui::Button(mState.playing ? "Pause (space)" : "Play (space)"))
        mState.playing = !mState.playing;
    ImGui::SameLine();
    ImGui::SetNextItemWidth(100);
    float speed = float(mState.speed);
    if (ImGui::DragFloat("speed", &speed, 0.05f, -10.0f, 10.0f)) mState.speed = speed;
    tooltip("animation seconds per second");
    optionControls(OptionGroup::Output);
    // View-only: they redraw but leave a score current.
    if (ImGui::Checkbox("light frusta (F)", &mState.frusta)) ++mState.viewRevision;
    tooltip("draw every shadow camera's volume as lines over the camera's view");
    bool side = mState.side == view::SideView::ShadowMap;
    if (ImGui::Checkbox("side view: shadow map", &side))
        mState.side = side ? view::SideView::ShadowMap : view::SideView::None;
    if (ImGui::Checkbox("measure passes", &mMeasure)) mRenderer.setPassTiming(mMeasure);
    tooltip("time each pass as gnomon bench does (a glFinish between passes)");
}

// The size of the camera's view: the window's area for it, or the size set here.
void Viewer::sizeControl(const OptionSpec& spec) {
    RenderOptions& o = mState.options;
    if (ImGui::Checkbox("fit view to window", &mState.fitView)) changed(true);
    if (mState.fitView) return;
    int size[2] = {o.width, o.height};
    if (ImGui::DragInt2(spec.name, size, 1.0f, 16, 4096)) {
        o.width = std::clamp(size[0], 1, 16384);
        o.height = std::clamp(size[1], 1, 16384);
        changed(true);
    }
    flagTip(spec);
}

void Viewer::lightOnlyControl(const OptionSpec& spec) {
    RenderOptions& o = mState.options;
    int lightOnly = o.lightOnly;
    if (ImGui::SliderInt(spec.name, &lightOnly, -1, int(mState.scene.lights.size()) - 1,
                         lightOnly < 0 ? "all" : "%d")) {
        o.lightOnly = lightOnly;
        changed(true);
    }
    flagTip(spec);
}

void Viewer::inputText(const char* label, std::string& value) {
    char buffer[1024];
    std::snprintf(buffer, sizeof buffer, "%s", value.c_str());
    if (ImGui::InputText(label, buffer, sizeof buffer)) value = buffer;
}

}  // namespace gnomon::cli::viewer
