// Where the rays' pass of render/RayMarks.h lays its jobs: job j's answer (and, on OpenGL 4.5,
// its pixel in the list) at rayAnswerTexel(j), from row rayAnswerRow() of a texture P texels
// wide.
layout(location = 17) uniform ivec2 uRayPyramidSize;  // P (a power of two), L = log2 P

// The jobs' first row: under the list's count in texel (0, 0) on OpenGL 4.5, under the
// pyramid's levels (rows 0 to P / 2) on ES 3.0. A multiple of 4: the jobs' blocks (below) are
// llvmpipe's.
int rayAnswerRow() {
#ifdef GNOMON_GLES
    return uRayPyramidSize.x / 2;
#else
    return 4;
#endif
}

// Where job j's answer lies: sixteen jobs to a 4x4 block of texels, the block llvmpipe shades at
// once (neighbours in the numbering lie near each other on screen, and their rays take about as
// long), P / 4 blocks to a row.
ivec2 rayAnswerTexel(int j) {
    int block = j >> 4, blocksPerRow = uRayPyramidSize.x >> 2;
    return ivec2((block % blocksPerRow) * 4 + (j & 3),
                 rayAnswerRow() + (block / blocksPerRow) * 4 + ((j >> 2) & 3));
}

// The job whose answer lies at texel t of the answers (their row 0 at rayAnswerRow()).
int rayJobAt(ivec2 t) {
    return ((t.y >> 2) * (uRayPyramidSize.x >> 2) + (t.x >> 2)) * 16 + (t.y & 3) * 4 + (t.x & 3);
}
