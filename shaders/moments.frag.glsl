#version 450 core
// The moment pass: one map's square of a layer, box-blurred in two passes. ROWS: stored
// depth to moments (moments.glsl), averaged along x into a scratch texture; COLUMNS: the
// scratch averaged along y into the moments array's layer. Taps stay inside the square
// (clamped to its edge): neighbouring maps in the layer are other lights' or cascades'. Each
// tap reads its texel's centre through a NEAREST sampler, where llvmpipe runs texelFetch slower.
#include "moments.glsl"

#if defined(ROWS)
layout(binding = 0) uniform sampler2DArray uDepths;  // the shadow maps, NEAREST, no comparison
#else
layout(binding = 0) uniform sampler2D uRows;  // the ROWS pass's output
#endif
layout(location = 0) uniform ivec4 uSquare;  // origin x, y, size, layer
// MOMENT_RADIUS (injected): the box's half width in texels. A constant, so the taps are
// written out: llvmpipe keeps what a loop changes in memory behind its mask, which a uniform
// radius would cost even the default pass of one tap.
layout(location = 2) uniform vec3 uDepthRange;  // near, far, 1 for a perspective map
layout(location = 0) out vec4 oMoments;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 lo = uSquare.xy, hi = uSquare.xy + uSquare.z - 1;
    vec4 sum = vec4(0.0);
#if defined(ROWS)
    vec2 texel = 1.0 / vec2(textureSize(uDepths, 0).xy);
#else
    vec2 texel = 1.0 / vec2(textureSize(uRows, 0));
#endif
    for (int k = -MOMENT_RADIUS; k <= MOMENT_RADIUS; ++k) {
#if defined(ROWS)
        ivec2 q = ivec2(clamp(p.x + k, lo.x, hi.x), p.y);
        float stored = texture(uDepths, vec3((vec2(q) + 0.5) * texel, uSquare.w)).r;
        sum += depthMoments(
            momentDepth(stored, uDepthRange.x, uDepthRange.y, uDepthRange.z > 0.5));
#else
        ivec2 q = ivec2(p.x, clamp(p.y + k, lo.y, hi.y));
        sum += texture(uRows, (vec2(q) + 0.5) * texel);
#endif
    }
    oMoments = sum / float(2 * MOMENT_RADIUS + 1);
}
