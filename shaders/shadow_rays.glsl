// Shadow rays (--shadow-rays all): a shadowed light's visibility from one ray through a BVH
// of the scene's casters (bvh_trace.glsl, built by render::RayScene) instead of its map. The
// hard answer of the light's centre, as the reference traces it (truth::ShadowRays): soft
// filters get it too, and masked or blended casters block the ray whole. Included by
// main.frag.glsl after uEye.
#include "bvh_trace.glsl"

// Below this cosine between the surface's plane and the way to the light, the surface faces
// away from the light: in its own shadow (the reference's edge-on bound).
const float kRayEdgeOn = 1e-3;

// How far a ray starts off its surface along the geometric normal: a share of the casters'
// extent (the root's box) for the rounding of the interpolated position on its plane, plus a
// share of the position's own size for the rounding of its coordinates.
float rayLift(vec3 p) {
    vec3 lo = bvhTexel(uBvhNodes, 0).xyz, hi = bvhTexel(uBvhNodes, 1).xyz;
    return 2e-5 * length(hi - lo) + 4e-6 * length(p);
}

// The light's visibility at `r` along `wsToLight` (lightAt's direction): 0 when a caster lies
// between. Directional lights reach from infinitely far; area lights, parallel as they light,
// from their plane; spot and point lights from their position.
ShadowSample rayVisibility(LightRecord light, Receiver r, vec3 wsToLight) {
    ShadowSample result = kLitSample;
    vec3 n = r.planeNormal;
    if (dot(n, uEye - r.position) < 0.0) n = -n;  // the side the camera sees
    if (dot(n, wsToLight) <= kRayEdgeOn) {
        result.visibility = 0.0;
        return result;
    }
    vec3 origin = r.position + n * rayLift(r.position);
    vec3 dir = wsToLight;
    float reach = 1e30;
    if (light.type == kArea) {
        reach = dot(origin - light.position, normalize(light.direction));
    } else if (light.type != kDirectional) {
        vec3 d = light.position - origin;
        reach = length(d);
        dir = d / reach;
    }
    if (!(reach > 0.0)) return result;  // behind an area light's plane: nothing to cross
    result.visibility = bvhTrace(origin, dir, 0.0, reach, true) >= 0.0 ? 0.0 : 1.0;
    return result;
}
