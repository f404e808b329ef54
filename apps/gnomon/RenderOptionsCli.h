// Command-line flags for RenderOptions, made from the option schema (gnomon/OptionSchema.h):
// one flag per option in its help group, with its doc, range and the library's default.
// Flags the user did not give keep the scene's authored value.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdio>
#include <map>
#include <string>

#include "gnomon/OptionSchema.h"
#include "gnomon/Options.h"
#include "gnomon/Scene.h"

namespace gnomon::cli {

// A loaded scene's warnings (what the loader ignored or repaired), one line each on stderr.
inline void printWarnings(const Scene& scene) {
    for (const std::string& w : scene.warnings)
        std::fprintf(stderr, "gnomon: warning: %s\n", w.c_str());
}

struct RenderFlags {
    std::string preset;
    // One text per option of the schema (gnomon/OptionSchema.h), by name: what was given.
    std::map<std::string, std::string> values;
    bool ground = false;
    std::string up = "y";  // --up: the model file's up axis, a load setting
    // Scene edits: the camera, and one sun instead of the scene's lights.
    std::string cameraEye, cameraTarget, sun;
    float cameraFov = 0.0f;
    CLI::App* app = nullptr;

    // Declares the flags on `app`.
    void add(CLI::App& app);
    // --up as an axis; throws gnomon::Error for anything but x, y or z.
    UpAxis upAxis() const;
    // The options for `scene`: the --preset's (default: the scene's own), then every flag
    // given applied over them. Throws gnomon::Error for bad values.
    RenderOptions resolve(const Scene& scene) const;
    // Scene edits the flags ask for (--ground, --camera-*, --sun); throws gnomon::Error for
    // bad values.
    void editScene(Scene& scene) const;
    // editScene, then the scene's warnings on stderr: after the edits, since --sun drops the
    // warning about the sun a loader added.
    void editSceneAndWarn(Scene& scene) const {
        editScene(scene);
        printWarnings(scene);
    }
    // The same without --ground (the viewer loads the ground with its scene).
    void placeCameraAndSun(Scene& scene) const;
    // Applies the given flags over `options`; throws gnomon::Error for bad values.
    void apply(RenderOptions& options) const;
    // Whether the option's flag was given (optionAt names one: given(optionAt(o, &o.width))).
    bool given(const OptionSpec& spec) const;
};

}  // namespace gnomon::cli
