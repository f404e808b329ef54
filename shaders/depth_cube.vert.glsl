#version 450 core
// Point-light shadow pass: the cube's faces in one instanced draw; instance i renders face
// uFace[i] into layer uBaseLayer + uFace[i] of the cube-map array (gl_Layer written here, not
// in a geometry shader: those are slow on llvmpipe). Only the faces the view looks up are
// drawn. Only depth is written.
#extension GL_ARB_shader_viewport_layer_array : require
#include "scene_data.glsl"

layout(location = 0) in vec3 msPosition;
layout(location = 1) uniform mat4 uFaceClipFromWorld[6];
layout(location = 7) uniform int uBaseLayer;
layout(location = 8) uniform int uFace[6];

#ifdef ALPHA_TEST
#include "alpha_test_vertex.glsl"
#endif

void main() {
    ObjectData o = objectAt(OBJECT_INDEX);
    vec4 wsPosition = o.worldFromModel * vec4(msPosition, 1.0);
#ifdef ALPHA_TEST
    passAlphaRule(o);
#endif
    int face = uFace[gl_InstanceID];
    gl_Position = uFaceClipFromWorld[face] * wsPosition;
    gl_Layer = uBaseLayer + face;
}
