// The ray jobs' numbering (render/RayMarks.h): a histogram pyramid (Ziegler, Tevs, Theobalt and
// Seidel, "On-the-fly Point Clouds through Histogram Pyramids", 2006) over the pixels the main
// pass's first draw marked. It numbers them 0..N-1 in a fixed order, so that a pass of N
// fragments traces one marked pixel each with every lane of a vector busy, and a marked pixel
// finds its number again. Level 1 holds, per 2x2 block of pixels, a mask of the marked ones
// (bit (y & 1) * 2 + (x & 1)); each level above, per 2x2 block of the one below, their count;
// the top level L, one texel, the total. The levels lie side by side in one R32UI texture:
// level l, (P >> l) texels square, from column P - (P >> (l - 1)); from row P / 2 the rays'
// answers follow (ray_trace.frag.glsl, rayAnswerTexel).
layout(binding = 14) uniform highp usampler2D uRayPyramid;
layout(location = 17) uniform ivec2 uRayPyramidSize;  // P (a power of two), L = log2 P

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

// Where job j's answer lies, from row P / 2 of the pyramid's texture: sixteen jobs to a 4x4
// block of texels, the block llvmpipe shades at once (neighbours in the numbering lie near each
// other on screen, and their rays take about as long), P / 4 blocks to a row.
ivec2 rayAnswerTexel(int j) {
    int block = j >> 4, blocksPerRow = uRayPyramidSize.x >> 2;
    return ivec2((block % blocksPerRow) * 4 + (j & 3),
                 uRayPyramidSize.x / 2 + (block / blocksPerRow) * 4 + ((j >> 2) & 3));
}

// The job whose answer lies at texel t of the answers (their row 0 at the pyramid's P / 2).
int rayJobAt(ivec2 t) {
    return ((t.y >> 2) * (uRayPyramidSize.x >> 2) + (t.x >> 2)) * 16 + (t.y & 3) * 4 + (t.x & 3);
}
