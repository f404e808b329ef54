// Per-object data shared by every pass: one record per scene object, uploaded when the scene
// or its animation time changes, indexed by OBJECT_INDEX.
struct ObjectData {
    mat4 worldFromModel;
    mat4 worldFromModelNormal;  // inverse transpose, upper 3x3 used
    vec4 baseColour;            // rgb, a = 1
    vec4 material;              // x specular, y shininess, z unlit (0/1), w double-sided (0/1)
    vec4 flags;   // x receives shadows (0/1), y alpha mode (0 opaque, 1 mask, 2 blend), z cutoff,
                  // w how far the shadow passes' stand-in strays from the mesh (model units)
    vec4 uvRow0;  // texture coordinates used: (dot(uvRow0.xyz, (u, v, 1)),
    vec4 uvRow1;  //                            dot(uvRow1.xyz, (u, v, 1))) (KHR_texture_transform)
};

// The records as RGBA32F texels, kObjectTexels to each (render::GpuScene::kObjectTextureUnit):
// on llvmpipe a texel fetch gathers, where a storage buffer is read one lane at a time.
// Fields no stage uses are never fetched: the compiler drops the unused fetches.
// GLSL ES 3.00 (WebGL2) has no buffer textures: there the records are rows of an RGBA32F 2D
// texture, GNOMON_OBJECTS_PER_ROW records to a row, record i from texel (i % that) x
// kObjectTexels of row i / that (gl/ShaderSource.h: kObjectsPerRow).
const int kObjectTexels = 13;
#ifdef GNOMON_GLES
layout(binding = 15) uniform sampler2D uObjects;
#define OBJECT_ADDRESS ivec2
#define OBJECT_START(index) objectStart(index)
#define OBJECT_TEXEL(t, c) texelFetch(uObjects, t + ivec2(c, 0), 0)
ivec2 objectStart(uint index) {
    uint perRow = uint(GNOMON_OBJECTS_PER_ROW);
    return ivec2(int(index % perRow) * kObjectTexels, int(index / perRow));
}
#else
layout(binding = 15) uniform samplerBuffer uObjects;
#define OBJECT_ADDRESS int
#define OBJECT_START(index) int(index) * kObjectTexels
#define OBJECT_TEXEL(t, c) texelFetch(uObjects, t + c)
#endif
ObjectData objectAt(uint index) {
    OBJECT_ADDRESS t = OBJECT_START(index);
    ObjectData o;
    for (int c = 0; c < 4; ++c) {
        o.worldFromModel[c] = OBJECT_TEXEL(t, c);
        o.worldFromModelNormal[c] = OBJECT_TEXEL(t, 4 + c);
    }
    o.baseColour = OBJECT_TEXEL(t, 8);
    o.material = OBJECT_TEXEL(t, 9);
    o.flags = OBJECT_TEXEL(t, 10);
    o.uvRow0 = OBJECT_TEXEL(t, 11);
    o.uvRow1 = OBJECT_TEXEL(t, 12);
    return o;
}

// The object drawn, OBJECT_INDEX. OpenGL 4.5: an instanced attribute, its entry chosen by the
// draw's base instance (one multi-draw covers many objects). WebGL2 has no base instance:
// there the record is uDrawBase, the draw's first (gl/ShaderSource.h: kDrawBaseLocation),
// plus the draw's number within a multi-draw (GNOMON_DRAW_ID: gl_DrawID, or 0 without
// multi-draws), so a multi-draw's records follow one another in the order of its draws.
#ifdef GNOMON_GLES
layout(location = 14) uniform int uDrawBase;
#define OBJECT_INDEX uint(uDrawBase + GNOMON_DRAW_ID)
#else
layout(location = 4) in uint aObject;
#define OBJECT_INDEX aObject
// The draw's first triangle's number (render/DrawnTriangles.h).
layout(location = 5) in uint aFirstTriangle;
#endif

vec2 materialUv(ObjectData o, vec2 uv) {
    vec3 h = vec3(uv, 1.0);
    return vec2(dot(o.uvRow0.xyz, h), dot(o.uvRow1.xyz, h));
}
