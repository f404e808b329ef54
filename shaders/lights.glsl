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
// one screen tile. Read at the loop counter, a dynamically uniform index, it costs a scalar
// load per light.
layout(std140, binding = 2) uniform LightOrder {
    ivec4 uLightOrder[1024];  // 4096 entries, four to a std140 slot
};
layout(location = 10) uniform int uLightFirst;
int lightRecord(int k) {
    return uLightOrder[k >> 2][k & 3];
}
