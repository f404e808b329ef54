#version 450 core
// Point-light shadow pass: all six cube faces in one instanced draw; instance i
// renders face i into layer uBaseLayer + i of the cube-map array (gl_Layer written here, not
// in a geometry shader: those are slow on llvmpipe). Only depth is written.
#extension GL_ARB_shader_viewport_layer_array : require
#include "scene_data.glsl"

layout(location = 0) in vec3 msPosition;
layout(location = 1) uniform mat4 uFaceClipFromWorld[6];
layout(location = 7) uniform int uBaseLayer;

#ifdef ALPHA_TEST
#include "alpha_test_vertex.glsl"
#endif

void main() {
    ObjectData o = objects[aObject];
    vec4 wsPosition = o.worldFromModel * vec4(msPosition, 1.0);
#ifdef ALPHA_TEST
    passAlphaRule(o);
#endif
    gl_Position = uFaceClipFromWorld[gl_InstanceID] * wsPosition;
    gl_Layer = uBaseLayer + gl_InstanceID;
}
