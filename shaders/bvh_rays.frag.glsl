#version 450 core
// One ray per pixel through the BVH (bvh_trace.glsl), for the ray-rate benchmark: the ray of
// the pixel at (x, y) is texel (x, y) of uRayOrigins (xyz, tfar) and uRayDirections (xyz, 1
// for a shadow ray that stops at any caster), images of the target's size. Writes the hit
// distance, -1 for none.
#include "bvh_trace.glsl"

layout(binding = 14) uniform highp sampler2D uRayOrigins;
layout(binding = 15) uniform highp sampler2D uRayDirections;

layout(location = 0) out vec4 fHit;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 o = texelFetch(uRayOrigins, p, 0), d = texelFetch(uRayDirections, p, 0);
    int hit;
    fHit = vec4(bvhTrace(o.xyz, d.xyz, 0.0, o.w, d.w > 0.5, -1, hit), 0.0, 0.0, 1.0);
}
