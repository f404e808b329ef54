#version 450 core
// The view depth pass's reduction: each output texel holds the nearest and farthest covered
// depth of its uBlock x uBlock block of the full-resolution depth buffer (the clear value 1
// is nothing: a block with nothing keeps (1, 1)). Every pixel the view draws then lies in its
// block's frustum between those two depths, which is what fitted shadow maps must hold.
// Read 2x2 texels at a time by textureGather, a quarter of the reads of one texelFetch per
// texel.
#include "texel_gather.glsl"
layout(binding = 0) uniform sampler2D uDepth;
layout(location = 0) uniform ivec2 uBlock;  // block size in pixels
layout(location = 1) uniform ivec2 uSize;   // the depth buffer's size
layout(location = 0) out vec2 oRange;

void main() {
    ivec2 first = ivec2(gl_FragCoord.xy) * uBlock;
    ivec2 last = min(first + uBlock, uSize) - 1;
    vec2 texel = 1.0 / vec2(uSize);
    vec4 nearest = vec4(1.0), farthest = vec4(0.0);
    for (int y = first.y; y <= last.y; y += 2) {
        for (int x = first.x; x <= last.x; x += 2) {
            // Texels (x, y + 1), (x + 1, y + 1), (x + 1, y), (x, y): those past the block's
            // last row or column (an odd block, the buffer's edge) count as nothing.
            vec4 d = GATHER_2D(uDepth, x, y, texel);
            bool right = x + 1 <= last.x, up = y + 1 <= last.y;
            d = mix(vec4(1.0), d, bvec4(up, right && up, right, true));
            bvec4 covered = lessThan(d, vec4(1.0));
            nearest = min(nearest, d);
            farthest = max(farthest, mix(vec4(0.0), d, covered));
        }
    }
    float n = min(min(nearest.x, nearest.y), min(nearest.z, nearest.w));
    float f = max(max(farthest.x, farthest.y), max(farthest.z, farthest.w));
    oRange = f > 0.0 || n < 1.0 ? vec2(n, f) : vec2(1.0);
}
