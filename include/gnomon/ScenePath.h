// Camera and light paths: a scene seen over a run of frames, to measure whether its shadows
// hold still (gnomon score --path). Each frame is a small step, as from one frame to the next
// of an interactive view, so a shadow that jumps between two frames is flicker, not motion.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "gnomon/Scene.h"

namespace gnomon {

struct ScenePath {
    std::string name;             // "orbit", "dolly", "sun", "still", or the file's path
    std::vector<Camera> cameras;  // one per frame
    // One per frame when the path moves the lights: every light's direction (empty: the
    // lights stay as the scene has them).
    std::vector<std::vector<glm::vec3>> lightDirections;
    int frames() const { return int(cameras.size()); }
};

// The built-in paths, from the scene's camera and lights, `frames` frames (2..10000):
// - "orbit": the eye turns about the camera's centre, around its up axis, 0.5 degree a frame;
// - "dolly": the eye moves towards the centre by 0.5 % of its first distance a frame;
// - "sun": the camera stays; directional and area lights turn about the vertical (+y),
//   0.25 degree a frame (a time-of-day sweep);
// - "still": nothing moves (what the flicker metric must call 0).
// Anything else is a path file (docs/tune.md): {"gnomon-path": 1, "cameras": [camera, ...]}
// with cameras written as in scene files, one frame each; `frames` then takes the first
// frames of the file (0: all of them).
// Throws gnomon::Error (InvalidInput) for an unknown name, a bad file or a bad frame count.
ScenePath makeScenePath(const std::string& spec, const Scene& scene, int frames);

// Puts frame `frame` of `path` into `scene`: its camera and, for light paths, the lights'
// directions.
void applyPathFrame(const ScenePath& path, int frame, Scene& scene);

}  // namespace gnomon
