// Per-object data shared by every pass: one record per scene object, uploaded when the scene
// or its animation time changes, indexed by aObject.
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
layout(binding = 15) uniform samplerBuffer uObjects;
const int kObjectTexels = 13;
ObjectData objectAt(uint index) {
    int t = int(index) * kObjectTexels;
    ObjectData o;
    for (int c = 0; c < 4; ++c) {
        o.worldFromModel[c] = texelFetch(uObjects, t + c);
        o.worldFromModelNormal[c] = texelFetch(uObjects, t + 4 + c);
    }
    o.baseColour = texelFetch(uObjects, t + 8);
    o.material = texelFetch(uObjects, t + 9);
    o.flags = texelFetch(uObjects, t + 10);
    o.uvRow0 = texelFetch(uObjects, t + 11);
    o.uvRow1 = texelFetch(uObjects, t + 12);
    return o;
}

// The object drawn: an instanced attribute, its entry chosen by the draw's base instance
// (one multi-draw covers many objects).
layout(location = 4) in uint aObject;

vec2 materialUv(ObjectData o, vec2 uv) {
    vec3 h = vec3(uv, 1.0);
    return vec2(dot(o.uvRow0.xyz, h), dot(o.uvRow1.xyz, h));
}
