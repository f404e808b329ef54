// What the web page's address asks for: `#scene=NAME&OPTION=VALUE&...`, with the CLI's option
// names and spellings (gnomon/OptionSchema.h) plus `scene`, `preset`, `ground` and `picture`, read
// into a scene and its options. Anything wrong is refused in the CLI's words, so a link that does
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
    std::map<std::string, std::string> options;  // schema name -> text as given
};

// Reads "#key=value&key=value" (the '#' may be left out; %XX escapes and '+' decoded).
// Throws gnomon::Error (InvalidInput) for a key that is neither an option nor scene, preset
// or ground (naming the nearest), a key given twice, or a bad preset or ground value.
PageRequest parseAddress(const std::string& address);

struct PageScene {
    Scene scene;
    RenderOptions options;
    std::vector<std::string> warnings;  // the loader's and the options', one sentence each
};

// The scene the request names and its options: a built-in scene by name, else a model under
// `bundle` (the page's packaged models): a folder there stands for the one glTF in it
// ("Duck"), or a path inside it ("Duck/Duck.glb"). Then the preset's options, the given
// options over them (applyOptionTexts) and the ground. Throws gnomon::Error with the CLI's
// words ("--map-size: expected an integer, got 'abc'"; "unknown scene ..., did you mean").
PageScene loadRequest(const PageRequest& request, const std::string& bundle);

}  // namespace gnomon::web
