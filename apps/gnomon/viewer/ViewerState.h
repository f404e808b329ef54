// What `gnomon view` holds and does, without a window (unit-tested): the scene being edited,
// the render options, the view toggles, and how they become the options of each frame;
// presets; camera and light dragging; the --script language. The window and Dear ImGui side
// is Viewer.cpp.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gnomon/Options.h"
#include "gnomon/Scene.h"

namespace gnomon::view {

// What the view beside the camera's shows.
enum class SideView {
    ShadowMap,  // the selected light's maps in grey, darker = nearer (cubes unfolded)
    None,       // nothing: the camera's view alone
};

struct State {
    std::string source;     // what was loaded: a built-in name or a file path
    bool ground = false;    // addGround() over the source (--ground)
    UpAxis up = UpAxis::Y;  // the model file's up axis it was loaded with (--up)
    Scene scene;            // as loaded, then edited: camera, lights, ambient
    RenderOptions options;  // every render option; width/height used when !fitView
    bool fitView = true;    // render at the size of the view's area in the window
    int selectedLight = 0;  // whose maps the side view shows, whose controls are open
    bool frusta = false;    // light frusta drawn as lines over the camera's view
    SideView side = SideView::ShadowMap;
    bool playing = false;        // animation time advances with the clock
    double speed = 1.0;          // animation seconds per second of wall time
    std::uint64_t revision = 0;  // bumped by every edit that changes what a score measures
    // Bumped by view-only toggles (light frusta, debug views): the views redraw, a score of
    // the frame still holds.
    std::uint64_t viewRevision = 0;
};

// One entry of the presets menu: `args` are flags of `gnomon render` (--scene included).
struct PresetEntry {
    std::string name;
    std::string group;
    std::vector<std::string> args;
};
// "default" and "textbook" (on the current scene), then the technique docs' examples
// (examples/presets.txt, embedded at build time), in order.
const std::vector<PresetEntry>& presets();
const PresetEntry* findPreset(const std::string& name);

// Loads `source` (anything `gnomon render --scene` takes, a model file turned so that `up`
// stands up) with its authored options; keeps the view toggles and, unless fitView is off,
// the size. Throws gnomon::Error.
void load(State& state, const std::string& source, bool ground, UpAxis up = UpAxis::Y);
// The same for a scene loaded elsewhere (the web page's loader) from `source`.
void show(State& state, Scene scene, const std::string& source, bool ground, UpAxis up);
// Applies flags spelled as `gnomon render` spells them ({"--map-size", "64", ...}) over the
// state: --scene and --up (load first), --ground, --preset (options restart from it), then every
// other flag; --size also turns fitView off. Throws gnomon::Error naming the bad flag.
void applyFlags(State& state, const std::vector<std::string>& args);
void applyPreset(State& state, const PresetEntry& preset);

// The options of the camera's view when its area in the window is width x height.
RenderOptions mainViewOptions(const State& state, int width, int height);

// Mouse-driven camera moves, about the camera's centre. Orbit angles in degrees (yaw about
// the up vector, pitch kept short of the poles); pan in fractions of the view's height; zoom
// multiplies the distance to the centre (orthographic cameras: the volume).
void orbit(Camera& camera, float yawDegrees, float pitchDegrees);
void pan(Camera& camera, float dx, float dy);
void zoom(Camera& camera, float factor);
// Drags a light about `pivot` as orbit() moves a camera (yaw about world up, pitch about
// the horizontal axis facing the viewer): directions turn; positions move round the pivot.
void orbitLight(Light& light, const glm::vec3& pivot, const glm::vec3& viewRight, float yawDegrees,
                float pitchDegrees);

// --script: one command per line, `#` comments. Each command runs on a frame; `wait N`
// lets N frames pass. See docs/viewer.md for the verbs.
struct Command {
    int line = 0;
    std::string verb;
    std::vector<std::string> args;
};
// Throws gnomon::Error (InvalidInput) naming `path` and the line of an unknown verb or a
// wrong argument count.
std::vector<Command> parseScript(const std::string& text, const std::string& path);
// `repeat N VERB ARGS...`: VERB ARGS, once per frame on N frames.
Command repeatedCommand(const Command& repeat);
// Runs a command that edits the state (set, preset, scene, light, camera, orbit, pan, zoom,
// select-light, side, frusta, play, pause, speed); returns false, doing nothing, for the
// viewer's own verbs (wait, screenshot, save...). Throws gnomon::Error naming the line.
bool applyCommand(State& state, const Command& command);

}  // namespace gnomon::view
