#version 450 core
// Levels of the ray jobs' pyramid (ray_pyramid.glsl), into the pyramid, into the copy of it
// the rays' pass reads and into a copy the next pass reads (a texture cannot be read where it
// is drawn). LEVEL_ONE: the marks of 2x2 pixels of the first draw (alpha 0, within uMarks) as
// a mask. Otherwise up to four adjacent levels in one pass, each texel the sum of the texels
// it covers on the level the last pass drew (4, 16, 64 or 256 of them): on a CPU driver every
// pass waits for the one before, which cost more than these sums.
layout(location = 0) uniform ivec4 uLevel;  // first and last level drawn, the level below, P
layout(location = 1) uniform ivec4 uMarks;  // x0, y0, x1, y1 (past the end): pixels drawn this time
#ifdef LEVEL_ONE
layout(binding = 14) uniform sampler2D uColour;
#else
layout(binding = 14) uniform highp usampler2D uBelow;
#endif
layout(location = 0) out uint fLevel;
layout(location = 1) out uint fLevelRead;
layout(location = 2) out uint fCopy;

int levelColumn(int level) {
    return uLevel.w - (uLevel.w >> (level - 1));
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    uint v = 0u;
#ifdef LEVEL_ONE
    for (int i = 0; i < 4; ++i) {
        ivec2 q = 2 * p + ivec2(i & 1, i >> 1);
        bool inside = all(greaterThanEqual(q, uMarks.xy)) && all(lessThan(q, uMarks.zw));
        if (inside && texelFetch(uColour, q, 0).a == 0.0) v |= 1u << uint(i);
    }
#else
    int level = uLevel.x;
    while (level < uLevel.y && p.x >= levelColumn(level + 1)) ++level;
    ivec2 c = p - ivec2(levelColumn(level), 0);
    int n = 1 << (level - uLevel.z);  // texels of the level below a side
    ivec2 first = c * n + ivec2(levelColumn(uLevel.z), 0);
    if (c.y < (uLevel.w >> level)) {  // above a level's square: unused, left 0
        for (int y = 0; y < n; ++y) {
            for (int x = 0; x < n; ++x) {
                uint below = texelFetch(uBelow, first + ivec2(x, y), 0).r;
                if (uLevel.z == 1) below = (below & 1u) + ((below >> 1) & 1u) +
                                           ((below >> 2) & 1u) + ((below >> 3) & 1u);
                v += below;
            }
        }
    }
#endif
    fLevel = v;
    fLevelRead = v;
    fCopy = v;
}
