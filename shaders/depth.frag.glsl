#version 450 core
// Depth-only: the rasteriser writes gl_FragCoord.z into the depth attachment. ALPHA_TEST
// (masked and dithered blended casters) discards the fragments their alpha removes.
#ifdef ALPHA_TEST
#include "alpha_test.glsl"
#endif

void main() {
#ifdef ALPHA_TEST
    alphaTest();
#endif
}
