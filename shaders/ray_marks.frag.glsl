#version 450 core
// The pixels a shadow ray decides, as a depth target (render/RayMarks.h): where the main
// pass's first draw left alpha 0 (a lookup it was unsure of, SHADOW_RAYS_MARK), that pixel's
// depth, above 0 even at the near plane (ray_list.frag.glsl passes only there); elsewhere 0,
// which no surface drawn with LEQUAL passes.
layout(binding = 14) uniform sampler2D uColour;
layout(binding = 15) uniform highp sampler2D uDepth;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    bool marked = texelFetch(uColour, p, 0).a == 0.0;
    gl_FragDepth = marked ? max(texelFetch(uDepth, p, 0).r, 1e-30) : 0.0;
}
