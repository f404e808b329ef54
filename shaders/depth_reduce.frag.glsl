#version 450 core
// The view depth pass's reduction: each output texel holds the nearest and farthest covered
// depth of its uBlock x uBlock block of the full-resolution depth buffer (the clear value 1
// is nothing: a block with nothing keeps (1, 1)). Every pixel the view draws then lies in its
// block's frustum between those two depths, which is what fitted shadow maps must hold.
layout(binding = 0) uniform sampler2D uDepth;
layout(location = 0) uniform ivec2 uBlock;  // block size in pixels
layout(location = 1) uniform ivec2 uSize;   // the depth buffer's size
layout(location = 0) out vec2 oRange;

void main() {
    ivec2 first = ivec2(gl_FragCoord.xy) * uBlock;
    ivec2 last = min(first + uBlock, uSize) - 1;
    float nearest = 1.0, farthest = 0.0;
    for (int y = first.y; y <= last.y; ++y) {
        for (int x = first.x; x <= last.x; ++x) {
            float d = texelFetch(uDepth, ivec2(x, y), 0).r;
            if (d < 1.0) {
                nearest = min(nearest, d);
                farthest = max(farthest, d);
            }
        }
    }
    oRange = farthest > 0.0 || nearest < 1.0 ? vec2(nearest, farthest) : vec2(1.0);
}
