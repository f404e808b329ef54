// Scene description files (.json, format version 1; docs/scene-file.md): model files and
// built-in scenes to include, procedural shapes, materials, lights, camera and render options,
// so a shadow scene is set up without code. `loadScene(path)` reads them by extension.
#pragma once

#include <string>

#include "gnomon/Options.h"
#include "gnomon/Scene.h"

namespace gnomon {

// Reads a scene file and what it includes. The file's "options" become Scene::options, so
// rendering with them reproduces the scene as authored. Throws gnomon::Error: Io when the
// file cannot be read; InvalidInput naming the file and the JSON path of what is wrong
// (unknown keys, wrong types, bad names, out-of-range values, include cycles), e.g.
// `room.json: lights[2].type: expected one of directional, spot, point, area, got "sun"`.
Scene loadSceneFile(const std::string& path);

// The same from the file's text already in memory: `path` names it in messages and relative
// paths in it resolve against its folder (the fuzz target's entry point).
Scene parseSceneFile(const std::string& text, const std::string& path);

// Writes (atomically) a scene file that includes `source` (a built-in scene name, or a model
// or scene file, written relative to the output file's folder) without its lights and camera,
// followed by `scene`'s lights, camera and ambient and every field of `options`: what a viewer
// saves so `gnomon render --scene saved.json` reproduces what was tuned. `ground` writes
// "ground": true (the scene had addGround() applied over its source); `up` other than Y, the
// include's "up" (the model file was loaded with --up). Throws gnomon::Error (Io when it
// cannot write, InvalidInput for a value JSON cannot hold, such as NaN).
void saveSceneFile(const std::string& path, const std::string& source, const Scene& scene,
                   const RenderOptions& options, bool ground = false, UpAxis up = UpAxis::Y);

}  // namespace gnomon
