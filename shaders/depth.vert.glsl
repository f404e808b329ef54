#version 450 core
// Shadow pass: scene casters seen from the light camera; only depth is written.
// ALPHA_TEST: also the texture coordinates and alpha rule of masked and blended casters.
#include "scene_data.glsl"

layout(location = 0) in vec3 msPosition;
layout(location = 1) uniform mat4 uClipFromWorld;  // the light camera

#ifdef ALPHA_TEST
#include "alpha_test_vertex.glsl"
#endif

void main() {
    ObjectData o = objects[aObject];
    gl_Position = uClipFromWorld * (o.worldFromModel * vec4(msPosition, 1.0));
#ifdef ALPHA_TEST
    passAlphaRule(o);
#endif
}
