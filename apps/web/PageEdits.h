// The page address's scene edits, read and written by one table each: the camera's and the
// ambient light's keys that the CLI has no flag for (camera-projection, camera-box,
// camera-depth, ambient) and the fields of a light key (light2=pos:1,4,2;int:3). Reading
// (PageRequest.cpp) and writing (PageAddress.cpp) share them, so what is written reads back.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "PageRequest.h"
#include "gnomon/Scene.h"

namespace gnomon::web {

// A key of the address that sets part of the scene: its text in a scene, and that text read
// back into a scene (false when `text` is not of the form `expected` names).
struct SceneKey {
    const char* name;
    const char* expected;  // for messages: "NEAR,FAR with 0 < near < far, such as 0.1,100"
    std::string (*format)(const Scene& scene);
    bool (*parse)(const std::string& text, Scene& scene);
};
// camera-projection, camera-box, camera-depth and ambient, in the address's order.
const std::vector<SceneKey>& sceneKeys();

// A field of a light key ("pos" in light2=pos:1,4,2), as SceneKey is for the scene.
struct LightField {
    const char* name;
    const char* expected;
    std::string (*format)(const Light& light);
    bool (*parse)(const std::string& text, Light& light);
};
// on, shadows, type, pos, dir, colour, int, att, range, cone, map, and the shadow camera's
// cam, proj, target, fov, box and depth, in the address's order.
const std::vector<LightField>& lightFields();

// The light index a key names ("light2" -> 2); -1 for any other key, "light02" included (so
// no light is named twice by two spellings).
int lightKeyIndex(const std::string& key);
// A light key's value as field -> text ("pos:1,4,2;int:3"); throws gnomon::Error naming the
// key for a part without ':', an unknown field (with the nearest) or a field given twice.
std::map<std::string, std::string> parseLightFields(const std::string& key,
                                                    const std::string& value);

// The request's scene edits applied to `scene` in the address's order: camera-eye,
// camera-target, camera-fov and sun as the CLI applies its flags, then sceneKeys(), then each
// light's fields. Throws gnomon::Error naming the key: the CLI's words for the CLI's keys,
// "light5: the scene has 2 lights (light0..light1)" for a light it does not have.
void applySceneEdits(const PageRequest& request, Scene& scene);

// The shortest text that reads back as the same float (shortestText: "0.1", "50", "1e06"),
// without the '+' of an exponent, which an address would have to escape.
std::string numberText(float v);
// `text` as the address carries it: %XX for every byte but letters, digits and -._~,:;/
std::string encodedValue(const std::string& text);

}  // namespace gnomon::web
