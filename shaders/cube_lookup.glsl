// Point lights' lookups: one cube-map array layer per light, the face of the direction
// from the light holding the depth along that face's axis. Included by shadow_lookup.glsl
// (its samplers, tolerances, filter sizes and receiver plane).

// Stored cube depth of the receiver's plane (through the light-relative point `p`, normal
// gPlaneNormal) along the direction p + offset from the light: where that ray meets the
// plane, the perspective depth along p's major axis (offsets lie across it). A ray that
// misses the plane keeps p's own depth.
float cubePlaneDepth(vec3 p, vec3 offset, float near, float far) {
    vec3 d = p + offset;
    float t = dot(gPlaneNormal, p) / dot(gPlaneNormal, d);
    vec3 a = abs(p);
    float major = max(a.x, max(a.y, a.z)) * (t > 0.0 && t < 1e6 ? t : 1.0);
    float ndc = (far + near) / (far - near) - 2.0 * far * near / ((far - near) * major);
    return 0.5 * ndc + 0.5;
}

#if defined(RECEIVER_PLANE)
// The silhouette rule (receiver_plane.glsl) for lookups without the 3 x 3 kernel's two halves
// (--filter none or hw2x2, --pcf-size 1, poisson): one tap more, a texel diagonally downhill,
// whose footprint lies wholly beyond the point, tells a silhouette from a fold. Without it the
// Lantern's post under a point light almost in the plane of its side (lantern-post-point in
// scripts/quality-real.py) is striped as the 3 x 3 kernel was before the rule: 1.79 % of the
// view falsely shadowed away from edges with --filter none; a post's side 0.05 outside the
// light's plane, 6 away, 27 % with poisson (tests/gl/test_score.cpp's post, --fit-to boxes).
bool cubeSilhouette(vec3 toPoint, float layer, vec3 u, vec3 v, float step, float reference,
                    vec2 g, vec2 full, float spread) {
    vec2 downhill = step * sign(full);
    float beyond = texture(uShadowCubes, vec4(toPoint + downhill.x * u + downhill.y * v, layer),
                           reference + planeAlong(g, full, downhill, kCubeMaxApproach) - spread);
    return atSilhouette(kSingleTapSilhouetteCosine, 1.0 - beyond);
}
// One comparison: at a silhouette the point's own footprint, whose uphill half holds the face
// across the edge, is compared against the full plane.
float cubeSingleTap(vec3 toPoint, float layer, vec3 u, vec3 v, float step, float reference,
                    vec2 g, vec2 full, float spread) {
    float fullSpread = 0.5 * step * (abs(full.x) + abs(full.y));
    bool silhouette = cubeSilhouette(toPoint, layer, u, v, step, reference, g, full, spread);
    return texture(uShadowCubes, vec4(toPoint, layer),
                   silhouette ? reference - fullSpread : reference - spread);
}
#endif

// Point lights: the cube face of the direction light -> point holds the depth
// along that face's axis; compare against the same depth of this point. PCF taps lie in the
// face's plane (a 2-D kernel on the face, not the online WebGL tutorial's 3-D grid of
// directions: the same footprint for k^2 instead of k^3 lookups).
float cubeVisibility(LightRecord light, vec3 wsPosition, vec3 wsNormal, vec3 wsToLight) {
    vec3 toPoint = wsPosition - light.position;
    float near = light.mapNear, far = light.mapFar;
    vec3 a = abs(toPoint);
    float major = max(a.x, max(a.y, a.z));
    gTexelWorld = light.texelWorldSize * major;
    vec3 offset = normalOffset(light, wsNormal, wsToLight, light.texelWorldSize * major, kCubeReach);
#if defined(RECEIVER_PLANE)
    offset += grazingPlaneOffset(wsToLight, light.texelWorldSize * major, kCubeReach,
                                 kCubeGrazingShift);
#endif
#ifdef STAND_IN_LIFT
    offset += wsToLight * standInLift(light.texelWorldSize * major);
#endif
    toPoint += offset;
    a = abs(toPoint);
    major = max(a.x, max(a.y, a.z));
    float farTerm = (far + near) / (far - near);
    float nearTerm = 2.0 * far * near / ((far - near) * major);
    float stored = 0.5 * (farTerm - nearTerm) + 0.5;
    // Float rounding the stored depth's step does not cover: stored depth is a difference of
    // two terms, each rounded to 2^-24 of itself by the rasteriser and by this code in their
    // own orders, and the point itself is rounded to 2^-24 of its world coordinates, a share
    // of its distance from the light that grows as the light nears it. Either passes one
    // step of a float map on receivers near the nearest caster's distance (a box's top face
    // under a point light 0.1 to 0.5 units above it: up to 6 % of the view falsely shadowed
    // with one step, the whole face inside the cube's downward face flipping at once). Both
    // sides round, as mapRounding counts them: 2^-24 alone left a line of false shadow along
    // AlphaBlendModeTest's wall top, its cube's near plane just above (0.09 % of a view).
    float wsScale = length(wsPosition) + length(light.position);
    float rounding = exp2(-23.0) * (farTerm + nearTerm * (2.0 + wsScale / major));
    float reference = stored - depthTolerance(light, max(uDepthAware.z, rounding));
    float layer = float(light.layer);
#if defined(COLOURED_SHADOWS)
    gTint = cubeTint(toPoint, layer, reference);
#endif
    // Two axes spanning the face of the major axis; one texel is 2 / size at unit distance.
    vec3 u = a.x >= a.y && a.x >= a.z ? vec3(0, 1, 0) : vec3(1, 0, 0);
    vec3 v = a.z >= a.x && a.z >= a.y ? vec3(0, 1, 0) : vec3(0, 0, 1);
    float step = light.texelUv * 2.0 * major;
#if defined(RECEIVER_PLANE)
    // Stored depth per world unit of tap offset along u and v (affine on the face: a face is
    // a perspective projection), and its half-texel spread for the bilinear comparisons.
    vec2 g = vec2(cubePlaneDepth(toPoint, u * step, near, far) - stored,
                  cubePlaneDepth(toPoint, v * step, near, far) - stored) / step;
    // Capped as for single maps: no steeper than a surface tilted kPlaneMaxSlope, whose depth
    // changes that many steps per step across the light; further on the approach side.
    float along = max(1.0 - kPlaneMaxSlope * step / length(toPoint), 1e-3);
    float maxPerWorld = abs(stored - cubePlaneDepth(toPoint * along, vec3(0.0), near, far)) / step;
    vec2 full = g;
    float steep = length(g);
    if (steep > maxPerWorld) g *= maxPerWorld / steep;
    float spread = 0.5 * step * (abs(g.x) + abs(g.y));
#define CUBE_REFERENCE(o) (reference + planeAlong(g, full, (o), kCubeMaxApproach) - spread)
#else
    vec2 g = vec2(0.0), full = vec2(0.0);  // no plane: every tap at the point's own depth
    float spread = 0.0;
#define CUBE_REFERENCE(o) (reference)
#endif
#if defined(FILTER_PCF) || defined(FILTER_MOMENTS)
#if defined(FILTER_MOMENTS)
    // Cubes have no moments: the default 3 x 3 PCF. One comparison (what they had before)
    // leaked 1.8x PCF's light on ToyCar under a point light.
    const int kCubeKernel = 3;
#else
    const int kCubeKernel = PCF_SIZE;
#endif
#if defined(RECEIVER_PLANE)
    if (kCubeKernel == 1) {  // a constant: the compiler keeps one branch
        return cubeSingleTap(toPoint, layer, u, v, step, reference, g, full, spread);
    }
#endif
    const int r = kCubeKernel / 2;
    // The kernel's taps in two halves, for the silhouette rule (receiver_plane.glsl): each tap of
    // one half-plane of offsets, turned to the downhill side of the point, then its mirror
    // image uphill, compared against the full plane when every downhill tap whose bilinear
    // footprint lies wholly beyond the point (the others may read the point's own texel) was
    // lit. Each tap is read once. Without a receiver plane there is no downhill (g and full
    // are 0) and no silhouette: the plain K x K kernel.
    float sum = texture(uShadowCubes, vec4(toPoint, layer), CUBE_REFERENCE(vec2(0.0)));
    float downhillShadow = 0.0;
    float beyond = 0.999 * step * (abs(full.x) + abs(full.y));
    for (int y = 0; y <= r; ++y) {
        for (int x = -r; x <= r; ++x) {
            if (y == 0 && x <= 0) continue;
            vec2 o = vec2(x, y) * step;
            vec2 downhill = dot(full, o) < 0.0 ? -o : o;
            float t = texture(uShadowCubes, vec4(toPoint + downhill.x * u + downhill.y * v, layer),
                              CUBE_REFERENCE(downhill));
            sum += t;
            downhillShadow += dot(full, downhill) >= beyond ? 1.0 - t : 0.0;
        }
    }
    bool silhouette = atSilhouette(kCubeSilhouetteCosine, downhillShadow);
    for (int y = 0; y <= r; ++y) {
        for (int x = -r; x <= r; ++x) {
            if (y == 0 && x <= 0) continue;
            vec2 o = vec2(x, y) * step;
            vec2 uphill = dot(full, o) < 0.0 ? o : -o;
            float compareTo = silhouette
                                  ? reference + min(dot(g, uphill), dot(full, uphill)) - spread
                                  : CUBE_REFERENCE(uphill);
            sum += texture(uShadowCubes, vec4(toPoint + uphill.x * u + uphill.y * v, layer),
                           compareTo);
        }
    }
    return sum / float(kCubeKernel * kCubeKernel);
#elif defined(FILTER_PCSS)
    float texelAtReceiver = light.texelWorldSize * major;  // one texel at the receiver, world
    float perTexel = texelAtReceiver * surfaceSlope(wsNormal, wsToLight) *
                     storedPerWorld(light, major, false);
    float search = clamp(pcssSearchWorld(light, major) / (light.texelWorldSize * near), 1.0,
                         kPcssMaxTexels);
    mat2 turn = poissonRotation();
    float blockers = 0.0, count = 0.0;
    for (int i = 0; i < 16; ++i) {
        vec2 o = turn * kPoissonDisc[i] * search;
        vec3 tap = toPoint + (o.x * u + o.y * v) * texelAtReceiver;
        float z = texture(uShadowCubeDepths, vec4(tap, layer)).r;
#if defined(RECEIVER_PLANE)
        if (z < CUBE_REFERENCE(o * texelAtReceiver)) {
#else
        if (z < reference - length(o) * perTexel) {
#endif
            blockers += z;
            count += 1.0;
        }
    }
    if (count == 0.0) return 1.0;
    float tb = linearDepth(light, blockers / count, false);
    float radius =
        clamp(pcssPenumbraWorld(light, major, tb) / texelAtReceiver, 1.0, kPcssMaxTexels);
    float sum = 0.0;
    for (int i = 0; i < 16; ++i) {
        vec2 o = turn * kPoissonDisc[i] * radius;
        vec3 tap = toPoint + (o.x * u + o.y * v) * texelAtReceiver;
#if defined(RECEIVER_PLANE)
        sum += texture(uShadowCubes, vec4(tap, layer), CUBE_REFERENCE(o * texelAtReceiver));
#else
        sum += texture(uShadowCubes, vec4(tap, layer), reference - length(o) * perTexel);
#endif
    }
    return sum / 16.0;
#elif defined(FILTER_POISSON)
    float radius = step * 0.5 * float(PCF_SIZE);
    mat2 turn = poissonRotation();
#if defined(RECEIVER_PLANE)
    // At a silhouette the uphill taps are compared against the full plane, as the kernel's are.
    bool silhouette = cubeSilhouette(toPoint, layer, u, v, step, reference, g, full, spread);
#define POISSON_REFERENCE(o)                                                      \
    (silhouette && dot(full, (o)) < 0.0                                           \
         ? reference + min(dot(g, (o)), dot(full, (o))) - spread                  \
         : CUBE_REFERENCE(o))
#else
#define POISSON_REFERENCE(o) CUBE_REFERENCE(o)
#endif
    float sum = 0.0;
    for (int i = 0; i < 16; ++i) {
        vec2 o = turn * kPoissonDisc[i] * radius;
        vec4 tap = vec4(toPoint + o.x * u + o.y * v, layer);
        sum += texture(uShadowCubes, tap, POISSON_REFERENCE(o));
    }
#undef POISSON_REFERENCE
    return sum / 16.0;
#elif defined(RECEIVER_PLANE)
    return cubeSingleTap(toPoint, layer, u, v, step, reference, g, full, spread);
#else
    return texture(uShadowCubes, vec4(toPoint, layer), CUBE_REFERENCE(vec2(0.0)));
#endif
#undef CUBE_REFERENCE
}
