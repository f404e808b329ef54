// What the web page's address asks for: `#scene=NAME&OPTION=VALUE&...`, with the CLI's option
// names and spellings (gnomon/OptionSchema.h) plus `scene`, `preset`, `ground`, `picture`, `ui`,
// the CLI's camera and sun edits and the page's own camera, ambient and light edits, read into a
// scene and its options; and written back from a view the user edited, so a link reproduces it
// (docs/web.md lists the keys). Anything wrong is refused in the CLI's words, so a link that does
// not work says why as `gnomon render` would. No GL and no browser: the native check of the
// page (tests/web) reads the same address with the same code.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "gnomon/Options.h"
#include "gnomon/Scene.h"

namespace gnomon::web {

struct PageRequest {
    std::string scene = "book-triangle";  // a built-in scene, or a model in the page's bundle
    Preset preset = Preset::Default;      // where options start, as --preset
    bool ground = false;                  // as --ground: a floor under a model without one
    // picture=render (the renderer's frame), truth (the ray-traced picture, TruthPicture.h)
    // or score (gnomon score's error map of the frame against the traced reference).
    enum class Picture { Render, Truth, Score } picture = Picture::Render;
    bool ui = true;                              // ui=off: the page shows no controls
    std::map<std::string, std::string> options;  // schema name -> text as given
    // Scene edits by key, text as given: camera-eye, camera-target, camera-fov and sun (the
    // CLI's flags), camera-projection, camera-box, camera-depth and ambient (the page's own).
    std::map<std::string, std::string> edits;
    // light<N>=FIELD:VALUE;...: light index -> field -> text as given ("pos" -> "1,4,2").
    std::map<int, std::map<std::string, std::string>> lights;
};

// Reads "#key=value&key=value" (the '#' may be left out; %XX escapes and '+' decoded).
// Throws gnomon::Error (InvalidInput) for a key the address does not take (naming the
// nearest), a key given twice, a bad preset, ground, picture or ui value, or a light key
// whose fields are not FIELD:VALUE;... of known fields. Edit and option values are checked
// when the scene loads.
PageRequest parseAddress(const std::string& address);

struct PageScene {
    Scene scene;
    RenderOptions options;
    std::vector<std::string> warnings;  // the loader's and the options', one sentence each
};

// The scene the request names and its options: a built-in scene by name, else a model under
// `bundle` (the page's packaged models): a folder there stands for the one glTF in it
// ("Duck"), or a path inside it ("Duck/Duck.glb"). Then the preset's options, the given
// options over them (applyOptionTexts), the ground, and the scene edits (the CLI's camera and
// sun first, as `gnomon render` applies its flags; then the camera's and ambient's own keys;
// then the lights'). Throws gnomon::Error with the CLI's words ("--map-size: expected an
// integer, got 'abc'"; "unknown scene ..., did you mean"), or naming the page's key
// ("light2: pos: expected X,Y,Z such as 1,4,2, got '1,4'").
PageScene loadRequest(const PageRequest& request, const std::string& bundle);
// What loadRequest loads for the address's scene `name`: a model's path in `bundle`, else
// `name` itself (a built-in scene, or a file the page was given).
std::string sceneSource(const std::string& name, const std::string& bundle);

// The address of a view: `base` is the request the view was loaded from (its scene as the
// address named it, preset, ground, picture, ui and edits), `loaded` the scene loadRequest
// made of it, `edited` that scene as the user has changed it (camera, ambient, lights; as
// many lights), `options` the options now. Writes "#scene=NAME", then, in a fixed order, the
// rest of `base` that is not the default, each camera and ambient key and each light field
// whose value differs from `loaded`'s or that `base` gave, `base`'s sun, and each schema
// option whose text (formatOption) differs from presetOptions(loaded, base.preset); `size`
// only when `withSize` (a view sized to its window leaves it out). parseAddress and
// loadRequest of the result give `edited` and `options` back: floats exactly, `time` to a
// float's precision. Throws gnomon::Error when `edited` has another number of lights.
std::string writeAddress(const PageRequest& base, const Scene& loaded, const Scene& edited,
                         const RenderOptions& options, bool withSize);

}  // namespace gnomon::web
