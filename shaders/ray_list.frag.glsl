#version 450 core
// OpenGL 4.5's numbering of the marked pixels (ray_pyramid.glsl's list): drawn at depth 0 over
// the marks' depth target with LESS, so that only the marked pixels (ray_marks.frag.glsl) run
// it, each taking the next number with an image atomic on texel (0, 0) and writing itself,
// x | y << 16, where its answer will lie. The test runs before the shader: on llvmpipe image
// operations cost every pixel of a vector, marked or not.
layout(early_fragment_tests) in;
#include "ray_answers.glsl"
layout(r32ui, binding = 0) uniform coherent uimage2D uRayListImage;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    int j = int(imageAtomicAdd(uRayListImage, ivec2(0), 1u));
    imageStore(uRayListImage, rayAnswerTexel(j), uvec4(uint(p.x) | (uint(p.y) << 16)));
}
