#version 450 core
// Shadow pass for colour formats: the fragment's window depth gl_FragCoord.z,
// encoded into an RGBA8 target (a depth attachment still does the depth test).
#include "depth_packing.glsl"
#ifdef ALPHA_TEST
#include "alpha_test.glsl"
#endif

layout(location = 0) out vec4 encodedDepth;

void main() {
#ifdef ALPHA_TEST
    alphaTest();
#endif
    encodedDepth = packDepth(gl_FragCoord.z);
}
