// The view camera's clip position of a model-space point, as the main pass (main.vert.glsl)
// and the view depth pass (depth.vert.glsl with VIEW_CAMERA) both compute it. The main pass
// starts from the view depth pass's depth and keeps only the fragments that equal it, so
// the two must give the very same depths: one expression chain, in this order, with
// gl_Position invariant in both (GLSL 4.50, section 4.8.1: invariance across programs).
layout(location = 1) uniform mat4 uViewFromWorld;
layout(location = 2) uniform mat4 uClipFromView;

invariant gl_Position;

// `ws`, `vs`: the point in world and view space on the way.
vec4 viewClip(ObjectData o, vec3 msPosition, out vec4 ws, out vec4 vs) {
    ws = o.worldFromModel * vec4(msPosition, 1.0);
    vs = uViewFromWorld * ws;
    return uClipFromView * vs;
}
