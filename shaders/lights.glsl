// Lights as the main pass sees them: one record per light (up to MAX_LIGHTS, set
// from GL_MAX_UNIFORM_BLOCK_SIZE), positions and directions in world space, where the
// surface is shaded and its maps looked up, plus the light's shadow transform. A uniform
// block, not a storage buffer: indexed by the loop counter (dynamically uniform) its reads
// are scalar, where llvmpipe gathers storage-buffer reads per fragment.
#include "light_record.glsl"

layout(std140, binding = 1) uniform Lights {
    LightRecord lights[MAX_LIGHTS];
};
// Records are ordered by kind: [0, x) unshadowed, [x, y) one map each, [y, z) cubes,
// [z, w) cascaded (their cascade records follow at w and beyond). Lights that are off have
// no record.
layout(location = 6) uniform ivec4 uLightRanges;
// The loops visit records through this list (render/TiledLights.h), from uLightFirst to the
// ends in uLightRanges: every record in turn for an untiled draw, or the lights that reach
// one screen tile (ORDER_SLOTS: as many slots as the driver's uniform block holds, up to
// 4096). Read at the loop counter, a dynamically uniform index, it costs a scalar load per
// light.
layout(std140, binding = 2) uniform LightOrder {
    ivec4 uLightOrder[ORDER_SLOTS];  // four entries to a std140 slot
};
layout(location = 10) uniform int uLightFirst;
int lightRecord(int k) {
    return uLightOrder[k >> 2][k & 3];
}

#ifdef LIGHT_LISTS
// One draw for the whole view: each pixel reads its screen tile's ranges of the order from a
// texel of uLightLists (render/TiledLights.h, LightLists): first, then the ends of the
// unshadowed, map and cube lights; the cascaded lights, in every tile, follow the cubes.
// Tiles are whole blocks of the pixels llvmpipe shades together, so the loops run as often
// for every pixel of a block and a light no pixel there needs costs nothing.
layout(binding = 9) uniform highp isampler2D uLightLists;
layout(location = 0) uniform int uTileShift;  // log2 of a tile's side in pixels
#endif

// The direction from world position p to a light of type `type` (light_record.glsl): against
// its direction for directional and area lights, whose rays are parallel, toward its position
// for spot and point lights. The main pass's lighting and the shadow rays' pass take it alike.
vec3 toLightFrom(LightRecord light, int type, vec3 p) {
    if (type == kDirectional || type == kArea) return -normalize(light.direction);
    vec3 d = light.position - p;
    return d / length(d);
}

// This fragment's range of the light order: its unshadowed lights start at `first`, and its
// unshadowed, map, cube and cascaded lights end at `ends`.
struct LightRange {
    int first;
    ivec4 ends;
};
LightRange lightRange() {
#ifdef LIGHT_LISTS
    ivec4 t = texelFetch(uLightLists, ivec2(gl_FragCoord.xy) >> uTileShift, 0);
    return LightRange(t.x, ivec4(t.yzw, t.w + uLightRanges.w - uLightRanges.z));
#else
    return LightRange(uLightFirst, uLightRanges);
#endif
}
