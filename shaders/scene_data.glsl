// Per-object data shared by every pass: one std430 record per scene object, uploaded when
// the scene or its animation time changes, indexed by the per-draw uniform uObject.
struct ObjectData {
    mat4 worldFromModel;
    mat4 worldFromModelNormal;  // inverse transpose, upper 3x3 used
    vec4 baseColour;            // rgb, a = 1
    vec4 material;              // x specular, y shininess, z unlit (0/1), w double-sided (0/1)
    vec4 flags;                 // x receives shadows (0/1)
};

layout(std430, binding = 0) readonly buffer Objects {
    ObjectData objects[];
};

layout(location = 0) uniform uint uObject;
