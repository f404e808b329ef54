// Per-object data shared by every pass: one std430 record per scene object, uploaded when
// the scene or its animation time changes, indexed by aObject.
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

layout(std430, binding = 0) readonly buffer Objects {
    ObjectData objects[];
};

// The object drawn: an instanced attribute, its entry chosen by the draw's base instance
// (one multi-draw covers many objects).
layout(location = 4) in uint aObject;

vec2 materialUv(ObjectData o, vec2 uv) {
    vec3 h = vec3(uv, 1.0);
    return vec2(dot(o.uvRow0.xyz, h), dot(o.uvRow1.xyz, h));
}
