// Lights as the main pass sees them: one record per light (up to MAX_LIGHTS, set
// from GL_MAX_UNIFORM_BLOCK_SIZE), positions and directions in world space, where the
// surface is shaded and its maps looked up, plus the light's shadow transform. A uniform
// block, not a storage buffer: indexed by the loop counter (dynamically uniform) its reads
// are scalar, where llvmpipe gathers storage-buffer reads per fragment.
const int kDirectional = 0;
const int kSpot = 1;
const int kPoint = 2;
const int kArea = 3;

// LightData.shadow.z: how the light's map was made.
const float kFramePerspective = 0.0;
const float kFrameOrthographic = 1.0;
const float kFrameCube = 2.0;
const float kFrameCascaded = 3.0;  // placement: x first cascade record, y count, z blend
// A point light's faces as maps of their own: placement x the first face record, y six 3-bit
// slots (face f's record at x + slot, 7: no map; faceVisibility in shadow_lookup.glsl).
const float kFrameFaces = 4.0;

struct LightData {
    mat4 textureFromWorld;  // world -> light clip -> [0,1] map coordinates and depth
    vec4 position;          // xyz, w = type
    vec4 direction;         // xyz towards where the light goes, w = range (point, spot; -1:
                            // none; 0 never reaches the shader: lights that are off)
    vec4 colour;            // rgb = colour x intensity, w = shadow layer (-1: no shadow)
    vec4 attenuation;       // c0, c1, c2, cos(outer cone); cascade records: x = far split
    vec4 shadow;            // x cos(inner cone), y texel world size, z frame kind, w uv scale
    vec4 shadowBias;        // x constant (stored depth), y normal offset (texels), z texel uv,
                            // w the map's far plane
    vec4 placement;         // 2D maps: xy the map's lower-left corner in its layer (uv);
                            // cascaded lights: see kFrameCascaded; w the map's near plane
    vec4 soft;              // PCSS: x emitter radius (world; directional: tan of its angular
                            // radius), y 1 = angular, z emitter distance at map depth 0;
                            // w the light's index in the scene
};

layout(std140, binding = 1) uniform Lights {
    LightData lights[MAX_LIGHTS];
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
