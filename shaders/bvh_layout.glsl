// How the shadow rays' textures lay out their texels, declared once for GLSL and C++
// (render/RayScene.h includes it): texel k of a texture at (k mod kBvhRowTexels,
// k / kBvhRowTexels). A power of two, so the shaders find a texel by a mask and a shift: an
// integer division is one instruction per lane on a CPU driver, and it ran for every pixel
// however few traced. 2048 is WebGL2's least texture size.
const int kBvhRowLog2 = 11;
const int kBvhRowTexels = 1 << kBvhRowLog2;
