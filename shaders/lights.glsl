// Lights as the main pass sees them: one std430 record per light (any number; SPEC S3),
// positions and directions already in view space, plus the light's shadow transform.
const int kDirectional = 0;
const int kSpot = 1;
const int kPoint = 2;

struct LightData {
    mat4 textureFromWorld;  // world -> light clip -> [0,1] map coordinates and depth
    vec4 vsPosition;        // xyz, w = type
    vec4 vsDirection;       // xyz towards where the light goes, w = on (0/1)
    vec4 colour;            // rgb = colour x intensity, w = shadow layer (-1: no shadow)
    vec4 attenuation;       // c0, c1, c2, cos(outer cone)
    vec4 shadow;            // x cos(inner cone), y texel world size, z orthographic, w uv scale
    vec4 shadowBias;        // x constant (stored depth), y normal offset (texels), z texel uv
};

layout(std430, binding = 1) readonly buffer Lights {
    LightData lights[];
};
