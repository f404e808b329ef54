#version 450 core
// A level of the ray jobs' pyramid (ray_pyramid.glsl), into the pyramid, into the copy of it
// the rays' pass reads and into a copy the next level reads (a texture cannot be read where it
// is drawn). LEVEL_ONE: the marks of 2x2 pixels of the first draw (alpha 0, within uMarks) as
// a mask; otherwise the sum of the 2x2 texels below (their masks' bits on level 1).
layout(location = 0) uniform ivec2 uLevel;  // the level drawn, P
layout(location = 1) uniform ivec4 uMarks;  // x0, y0, x1, y1 (past the end): pixels drawn this time
#ifdef LEVEL_ONE
layout(binding = 14) uniform sampler2D uColour;
#else
layout(binding = 14) uniform highp usampler2D uBelow;
#endif
layout(location = 0) out uint fLevel;
layout(location = 1) out uint fLevelRead;
layout(location = 2) out uint fCopy;

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
    int side = uLevel.y;
    // Level l's columns start at P - (P >> (l - 1)); the level below's, P >> (l - 2) before.
    ivec2 c = p - ivec2(side - (side >> (level - 1)), 0);
    ivec2 first = 2 * c + ivec2(side - (side >> (level - 2)), 0);
    for (int i = 0; i < 4; ++i) {
        uint below = texelFetch(uBelow, first + ivec2(i & 1, i >> 1), 0).r;
        if (level == 2)  // (no bitCount in WebGL2's GLSL ES 3.00)
            below = (below & 1u) + ((below >> 1) & 1u) + ((below >> 2) & 1u) + ((below >> 3) & 1u);
        v += below;
    }
#endif
    fLevel = v;
    fLevelRead = v;
    fCopy = v;
}
