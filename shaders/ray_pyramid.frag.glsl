#version 450 core
// One level of the ray jobs' pyramid (ray_pyramid.glsl), into the pyramid, into the copy of it
// the rays' pass reads and into a copy the next level reads (a texture cannot be read where
// it is drawn). LEVEL_ONE: the marks of 2x2
// pixels of the first draw (alpha 0, within uMarks) as a mask; otherwise the counts of 2x2
// texels of the level below.
layout(location = 0) uniform ivec4 uLevel;  // its column, the column of the level below, that level
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
    ivec2 c = ivec2(gl_FragCoord.xy) - ivec2(uLevel.x, 0);
    uint v = 0u;
    for (int i = 0; i < 4; ++i) {
        ivec2 q = 2 * c + ivec2(i & 1, i >> 1);
#ifdef LEVEL_ONE
        bool inside = all(greaterThanEqual(q, uMarks.xy)) && all(lessThan(q, uMarks.zw));
        if (inside && texelFetch(uColour, q, 0).a == 0.0) v |= 1u << uint(i);
#else
        uint below = texelFetch(uBelow, q + ivec2(uLevel.y, 0), 0).r;
        if (uLevel.z == 1) below = (below & 1u) + ((below >> 1) & 1u) + ((below >> 2) & 1u) +
                                   ((below >> 3) & 1u);
        v += below;
#endif
    }
    fLevel = v;
    fLevelRead = v;
    fCopy = v;
}
