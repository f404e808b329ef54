// What a shadow lookup is asked about (Receiver) and what it answers (ShadowSample): shared by
// the maps' lookups (shadow_lookup.glsl) and the shadow rays' own pass (ray_trace.frag.glsl).
// The fragment the lookups are for, the same for every light (main.frag.glsl fills it in; the
// rays' pass from the pixel's ray job).
struct Receiver {
    vec3 position;       // world space
    vec3 normal;         // the shading normal, world space
    vec3 planeNormal;    // RECEIVER_PLANE: the triangle's own plane (receiver_plane.glsl)
    float viewDepth;     // the depth along the view that picks a cascade
    float standInError;  // STAND_IN_LIFT: how far the object's stand-in strays (world units)
    vec2 pixel;          // the pixel's centre (window coordinates)
    float object;        // the scene object drawn there
    int drawn;           // the triangle drawn there (render/DrawnTriangles.h), -1: not known
};

// What one light's lookup found.
struct ShadowSample {
    float visibility;  // 0 in shadow, 1 lit
    float texelWorld;  // world size of the map texel read (gnomon score's aliasing band); 0: none
    vec3 tint;         // COLOURED_SHADOWS: the share of the light blended casters let through
    int cascade;       // the cascade read (--debug-view cascades); -1: none
    bool traced;       // SHADOW_RAYS: a ray decided the visibility, not the map
};
const ShadowSample kLitSample = ShadowSample(1.0, 0.0, vec3(1.0), -1, false);
