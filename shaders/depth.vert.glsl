#version 450 core
// Shadow pass (SPEC S1): scene casters seen from the light camera; only depth is written.
#include "scene_data.glsl"

layout(location = 0) in vec3 msPosition;
layout(location = 1) uniform mat4 uClipFromWorld;  // the light camera

void main() {
    gl_Position = uClipFromWorld * (objects[uObject].worldFromModel * vec4(msPosition, 1.0));
}
