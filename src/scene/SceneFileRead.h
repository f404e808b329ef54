// Reading the parts of a scene file: transforms, shapes, materials, lights, camera and render
// options, each from its JSON value with errors naming the file and the JSON path.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gnomon/Options.h"
#include "gnomon/Scene.h"
#include "scene/SceneFileJson.h"

namespace gnomon::scenefile {

// ---- Transforms: {"matrix": [16]} or {"translate", "rotate", "scale"} as T*R*S, or a list of
// those multiplied in order (the first outermost).
glm::mat4 readTransform(const Reader& r, const Json& j, const std::string& path);
glm::vec3 transformPoint(const glm::mat4& m, const glm::vec3& p);
// An include's "up": "x", "y" or "z".
UpAxis readUpAxis(const Reader& r, const Json& j, const std::string& path);

// ---- Shapes: "box", "quad", "triangle" or "mesh", and the keys each takes.
const std::vector<std::string>& shapeNames();
std::vector<std::string> shapeKeys(const std::string& shape);
// The object's "shape" if it has one (checked against shapeNames()), else "".
std::string peekShape(const Reader& r, const Json& j, const std::string& path);
// The mesh of `shape` from the fields `f` (whose keys were checked against shapeKeys(shape)).
Mesh readShape(const Fields& f, const std::string& shape, const std::string& name);

// The text of a JSON file of `what` kind ("scene file"), refused past kMaxFileBytes; Error
// naming the file when it is missing or unreadable.
std::string readFileText(const std::string& path, const std::string& what);

// ---- Materials, lights, camera, options
Material readMaterial(const Reader& r, const Json& j, const std::string& path,
                      const std::string& name);
Light readLight(const Reader& r, const Json& j, const std::string& path, std::size_t index);
// The keys `j` gives over `start` (a scene file's camera starts from the default one).
Camera readCamera(const Reader& r, const Json& j, const std::string& path,
                  const Camera& start = Camera{});
// The near and far planes the file's own cameras leave out, fitted to the finished scene (its
// ground included): the view camera's (`camera`, its JSON; null when the file has none of its
// own) and the manual and course shadow cameras of the file's `lights` (null: none; read into
// `out.lights` in order). The defaults 1 and 100 would cut away a model in millimetres whole,
// or clip a city. A plane given is kept.
void fitPlanesLeftOut(const Json* camera, const Json* lights, Scene& out);
// The keys given in `j` applied over `o`; RenderOptions::validate()'s sentences as errors.
void applyOptions(const Reader& r, const Json& j, const std::string& path, RenderOptions& o);

}  // namespace gnomon::scenefile
