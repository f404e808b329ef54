// One light record of the main pass's Lights block (shaders/lights.glsl), declared once for
// GLSL and C++: the shader assembler includes it into programs; src/shadow/LightRecord.h
// includes it into C++ after naming glm's types as GLSL's, and checks its std140 offsets at
// compile time. Each vec3 is followed by a scalar in its 16-byte slot and the vec2 by two,
// where std140 and a packed C++ struct agree; the record stays within 256 bytes so 256
// lights fit a 64 KiB uniform block. Every field means one thing whatever the light's kind.

// A light's kind (LightRecord::type).
const int kDirectional = 0;
const int kSpot = 1;
const int kPoint = 2;
const int kArea = 3;

// How a record's map was made (LightRecord::frame).
const int kFramePerspective = 0;
const int kFrameOrthographic = 1;
const int kFrameCube = 2;      // a cube map: six 90-degree frusta around a point light
const int kFrameCascaded = 3;  // the maps are the cascade records that follow the lights
const int kFrameFaces = 4;     // a point light's faces as maps of their own, in face records

struct LightRecord {
    mat4 textureFromWorld;  // world -> light clip -> [0, 1] map coordinates and stored depth;
                            // cubes: world -> offset from where the cube was drawn
    vec3 position;          // world space
    int type;               // kDirectional...
    vec3 direction;         // world space, normalised: where the light goes
    float range;            // point, spot: unlit beyond it; -1: no range; 0: the light is off
    vec3 colour;            // linear RGB: colour x intensity
    int layer;              // the map's layer (2D array or cube array); -1: no map of its own
    vec3 attenuation;       // 1 / (x + y d + z d^2)
    float cosOuter;         // spot: cosine of the outer cone
    float cosInner;         // spot: cosine of the inner cone
    float texelWorldSize;   // one map texel in world units (perspective: at distance 1)
    int frame;              // kFramePerspective...
    float uvScale;          // the map's size / the array's size
    float biasConstant;     // added to the receiver's depth, in stored depth
    float normalOffset;     // along the normal, in map texels
    float texelUv;          // one texel of the array, in uv
    float mapFar;           // the map's far plane
    vec2 mapCorner;         // 2D maps: the map's lower-left corner in its layer (uv)
    float mapNear;          // the map's near plane
    float farSplit;         // cascade records: the view depth where the cascade ends
    int firstSubRecord;     // cascaded and face lights: their first cascade or face record
    int cascadeCount;       // cascaded lights: how many cascade records
    float cascadeBlend;     // cascaded lights: the share of a cascade blended with the next
    int faceSlots;          // face lights: six 3-bit slots, face f's record at first + slot
                            // (7: the face has no map)
    float emitterRadius;    // PCSS: world radius of the emitter (directional: tan of its
                            // angular radius)
    int emitterAngular;     // PCSS: 1 for a directional light's angular emitter
    float emitterDistance;  // PCSS: the emitter's distance from the map's depth origin
    int sceneLight;         // the light's index in the scene (the visibility records)
};
