#version 450 core
// Shadow pass for colour formats (SPEC S10): the fragment's window depth gl_FragCoord.z,
// encoded into an RGBA8 target (a depth attachment still does the depth test).
#include "depth_packing.glsl"

layout(location = 0) out vec4 encodedDepth;

void main() {
    encodedDepth = packDepth(gl_FragCoord.z);
}
