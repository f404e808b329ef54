// The ray jobs' numbering (render/RayMarks.h): the pixels the main pass's first draw marked,
// numbered 0..N-1 so that a pass of N fragments traces one marked pixel each with every lane
// of a vector busy.
// OpenGL 4.5: a list. A pass over the marks (ray_list.frag.glsl) counts them with an image
// atomic in texel (0, 0) and writes each marked pixel, x | y << 16, at its number's
// rayAnswerTexel.
// OpenGL ES 3.0 (WebGL2), which has no image stores: a histogram pyramid (Ziegler, Tevs,
// Theobalt and Seidel, "On-the-fly Point Clouds through Histogram Pyramids", 2006), in a fixed
// order, from which a marked pixel also finds its number again. Level 1 holds, per 2x2 block of
// pixels, a mask of the marked ones (bit (y & 1) * 2 + (x & 1)); each level above, per 2x2
// block of the one below, their count; the top level L, one texel, the total. The levels lie
// side by side in one R32UI texture: level l, (P >> l) texels square, from column
// P - (P >> (l - 1)); from row P / 2 the rays' answers follow (ray_answers.glsl).
#include "ray_answers.glsl"
layout(binding = 14) uniform highp usampler2D uRayPyramid;

#ifndef GNOMON_GLES
int rayJobCount() {
    return int(texelFetch(uRayPyramid, ivec2(0), 0).r);
}

// The marked pixel numbered j (below rayJobCount()).
ivec2 rayJobPixel(int j) {
    uint v = texelFetch(uRayPyramid, rayAnswerTexel(j), 0).r;
    return ivec2(int(v & 0xffffu), int(v >> 16));
}
#else

ivec2 rayPyramidTexel(int level, ivec2 c) {
    return ivec2(uRayPyramidSize.x - (uRayPyramidSize.x >> (level - 1)) + c.x, c.y);
}

int rayMaskCount(uint m) {
    return int((m & 1u) + ((m >> 1) & 1u) + ((m >> 2) & 1u) + ((m >> 3) & 1u));
}

// The marked pixels under texel c of `level`.
int rayPyramidCount(int level, ivec2 c) {
    uint v = texelFetch(uRayPyramid, rayPyramidTexel(level, c), 0).r;
    return level == 1 ? rayMaskCount(v) : int(v);
}

int rayJobCount() {
    return rayPyramidCount(uRayPyramidSize.y, ivec2(0));
}

// The number of marked pixel p: how many marked pixels come before it.
int rayJobOf(ivec2 p) {
    ivec2 c = p >> 1;
    uint mask = texelFetch(uRayPyramid, rayPyramidTexel(1, c), 0).r;
    int j = rayMaskCount(mask & ((1u << uint((p.y & 1) * 2 + (p.x & 1))) - 1u));
    for (int level = 2; level <= uRayPyramidSize.y; ++level) {
        int i = (c.y & 1) * 2 + (c.x & 1);
        ivec2 first = c & ivec2(~1);
        if (i > 0) j += rayPyramidCount(level - 1, first);
        if (i > 1) j += rayPyramidCount(level - 1, first + ivec2(1, 0));
        if (i > 2) j += rayPyramidCount(level - 1, first + ivec2(0, 1));
        c >>= 1;
    }
    return j;
}

// The marked pixel numbered j (below rayJobCount()): down from the top, into the child whose
// count holds it.
ivec2 rayJobPixel(int j) {
    ivec2 c = ivec2(0);
    for (int level = uRayPyramidSize.y; level >= 2; --level) {
        c *= 2;
        int n = rayPyramidCount(level - 1, c);
        if (j >= n) {
            j -= n;
            c.x += 1;
            n = rayPyramidCount(level - 1, c);
            if (j >= n) {
                j -= n;
                c += ivec2(-1, 1);
                n = rayPyramidCount(level - 1, c);
                if (j >= n) {
                    j -= n;
                    c.x += 1;
                }
            }
        }
    }
    uint mask = texelFetch(uRayPyramid, rayPyramidTexel(1, c), 0).r;
    int bit = 0;
    for (int i = 0; i < 4; ++i) {
        if ((mask & (1u << uint(i))) != 0u) {
            if (j == 0) bit = i;
            --j;
        }
    }
    return 2 * c + ivec2(bit & 1, bit >> 1);
}
#endif
