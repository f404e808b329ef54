// Point lights' lookups: one cube-map array layer per light, the face of the direction
// from the light holding the depth along that face's axis. Included by shadow_lookup.glsl
// (its samplers, tolerances, filter sizes and receiver plane).

// Stored cube depth of the receiver's plane (through the light-relative point `p`, normal
// `planeNormal`) along the direction p + offset from the light: where that ray meets the
// plane, the perspective depth along p's major axis (offsets lie across it). A ray that
// misses the plane keeps p's own depth.
float cubePlaneDepth(vec3 planeNormal, vec3 p, vec3 offset, float near, float far) {
    vec3 d = p + offset;
    float t = dot(planeNormal, p) / dot(planeNormal, d);
    vec3 a = abs(p);
    float major = max(a.x, max(a.y, a.z)) * (t > 0.0 && t < 1e6 ? t : 1.0);
    float ndc = (far + near) / (far - near) - 2.0 * far * near / ((far - near) * major);
    return 0.5 * ndc + 0.5;
}

// Where a cube lookup lands: `toPoint`, the light-relative point whose direction is read, in
// layer `layer` of the cube-map array; `u` and `v` span the face of its major axis, `step` is
// one texel along them at the point; `reference` is compared with the stored depth.
struct CubeTap {
    vec3 toPoint;
    float layer;
    vec3 u;
    vec3 v;
    float step;
    float reference;
};

// The reference for a tap `o` (world units along u and v) away from the point: on the
// receiver's plane where one is followed.
float cubeReference(CubeTap c, TapPlane plane, vec2 o) {
#if defined(RECEIVER_PLANE)
    return c.reference + planeAlong(plane.g, plane.full, o, kCubeMaxApproach) - plane.spread;
#else
    return c.reference;
#endif
}
// At a silhouette, uphill taps compare against the full plane (where it is nearer than the
// capped one).
float uphillReference(CubeTap c, TapPlane plane, vec2 o) {
    return c.reference + min(dot(plane.g, o), dot(plane.full, o)) - plane.spread;
}

#if defined(RECEIVER_PLANE)
// The silhouette rule (receiver_plane.glsl) for lookups without the 3 x 3 kernel's two halves
// (--filter none or hw2x2, --pcf-size 1, poisson): one tap more, a texel diagonally downhill,
// whose footprint lies wholly beyond the point, tells a silhouette from a fold. Without it a
// post's side almost in the plane of a point light is striped with false shadow (the
// Lantern's post; tests/gl/test_score.cpp's post).
bool cubeSilhouette(CubeTap c, TapPlane plane) {
    vec2 downhill = c.step * sign(plane.full);
    vec3 tap = c.toPoint + downhill.x * c.u + downhill.y * c.v;
    float beyond = CUBE_COMPARE(uShadowCubes, tap, c.layer, cubeReference(c, plane, downhill));
    return atSilhouette(plane, kSingleTapSilhouetteCosine, 1.0 - beyond);
}
// One comparison: at a silhouette the point's own footprint, whose uphill half holds the face
// across the edge, is compared against the full plane.
float cubeSingleTap(CubeTap c, TapPlane plane) {
    float fullSpread = 0.5 * c.step * (abs(plane.full.x) + abs(plane.full.y));
    bool silhouette = cubeSilhouette(c, plane);
    float reference = silhouette ? c.reference - fullSpread : c.reference - plane.spread;
    return CUBE_COMPARE(uShadowCubes, c.toPoint, c.layer, reference);
}
#endif

#if defined(FILTER_PCF) || defined(FILTER_MOMENTS)
#if defined(FILTER_MOMENTS)
// Cubes have no moments: the default 3 x 3 PCF, which leaks less light than one comparison
// would.
const int kCubeKernel = 3;
#else
const int kCubeKernel = PCF_SIZE;
#endif
// A K x K kernel of taps in the face's plane.
float cubeKernel(CubeTap c, TapPlane plane) {
#if defined(RECEIVER_PLANE)
    if (kCubeKernel == 1) {  // a constant: the compiler keeps one branch
        return cubeSingleTap(c, plane);
    }
#endif
    const int r = kCubeKernel / 2;
    vec2 full = plane.full;
    // The kernel's taps in two halves, for the silhouette rule (receiver_plane.glsl): each tap of
    // one half-plane of offsets, turned to the downhill side of the point, then its mirror
    // image uphill, compared against the full plane when every downhill tap whose bilinear
    // footprint lies wholly beyond the point (the others may read the point's own texel) was
    // lit. Each tap is read once. Without a receiver plane there is no downhill (the flat
    // plane) and no silhouette: the plain K x K kernel.
    float sum = CUBE_COMPARE(uShadowCubes, c.toPoint, c.layer, cubeReference(c, plane, vec2(0.0)));
    float downhillShadow = 0.0;
    float beyond = 0.999 * c.step * (abs(full.x) + abs(full.y));
    for (int y = 0; y <= r; ++y) {
        for (int x = -r; x <= r; ++x) {
            if (y == 0 && x <= 0) continue;
            vec2 o = vec2(x, y) * c.step;
            vec2 downhill = dot(full, o) < 0.0 ? -o : o;
            vec3 tap = c.toPoint + downhill.x * c.u + downhill.y * c.v;
            float t = CUBE_COMPARE(uShadowCubes, tap, c.layer, cubeReference(c, plane, downhill));
            sum += t;
            downhillShadow += dot(full, downhill) >= beyond ? 1.0 - t : 0.0;
        }
    }
    bool silhouette = atSilhouette(plane, kCubeSilhouetteCosine, downhillShadow);
    for (int y = 0; y <= r; ++y) {
        for (int x = -r; x <= r; ++x) {
            if (y == 0 && x <= 0) continue;
            vec2 o = vec2(x, y) * c.step;
            vec2 uphill = dot(full, o) < 0.0 ? o : -o;
            float compareTo = silhouette ? uphillReference(c, plane, uphill)
                                         : cubeReference(c, plane, uphill);
            vec3 tap = c.toPoint + uphill.x * c.u + uphill.y * c.v;
            sum += CUBE_COMPARE(uShadowCubes, tap, c.layer, compareTo);
        }
    }
    return sum / float(kCubeKernel * kCubeKernel);
}
#endif

#if defined(FILTER_PCSS)
// PCSS on the face (pcss_lookup.glsl): `major` is the point's distance along the face's axis,
// `slope` the surface's (surfaceSlope).
float cubePcss(LightRecord light, CubeTap c, TapPlane plane, float major, float slope) {
    float near = light.mapNear;
    float texelAtReceiver = light.texelWorldSize * major;  // one texel at the receiver, world
    float perTexel = texelAtReceiver * slope * storedPerWorld(light, major, false);
    float search = clamp(pcssSearchWorld(light, major) / (light.texelWorldSize * near), 1.0,
                         kPcssMaxTexels);
    mat2 turn = poissonRotation();
    float blockers = 0.0, count = 0.0;
    for (int i = 0; i < 16; ++i) {
        vec2 o = turn * kPoissonDisc[i] * search;
        vec3 tap = c.toPoint + (o.x * c.u + o.y * c.v) * texelAtReceiver;
        float z = CUBE_READ(uShadowCubeDepths, tap, c.layer).r;
#if defined(RECEIVER_PLANE)
        if (z < cubeReference(c, plane, o * texelAtReceiver)) {
#else
        if (z < c.reference - length(o) * perTexel) {
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
        vec3 tap = c.toPoint + (o.x * c.u + o.y * c.v) * texelAtReceiver;
#if defined(RECEIVER_PLANE)
        float reference = cubeReference(c, plane, o * texelAtReceiver);
        sum += CUBE_COMPARE(uShadowCubes, tap, c.layer, reference);
#else
        sum += CUBE_COMPARE(uShadowCubes, tap, c.layer, c.reference - length(o) * perTexel);
#endif
    }
    return sum / 16.0;
}
#endif

#if defined(FILTER_POISSON)
float cubePoisson(CubeTap c, TapPlane plane) {
    float radius = c.step * 0.5 * float(PCF_SIZE);
    mat2 turn = poissonRotation();
#if defined(RECEIVER_PLANE)
    // At a silhouette the uphill taps are compared against the full plane, as the kernel's are.
    bool silhouette = cubeSilhouette(c, plane);
#else
    const bool silhouette = false;
#endif
    float sum = 0.0;
    for (int i = 0; i < 16; ++i) {
        vec2 o = turn * kPoissonDisc[i] * radius;
        vec3 tap = c.toPoint + o.x * c.u + o.y * c.v;
        float reference = silhouette && dot(plane.full, o) < 0.0 ? uphillReference(c, plane, o)
                                                                 : cubeReference(c, plane, o);
        sum += CUBE_COMPARE(uShadowCubes, tap, c.layer, reference);
    }
    return sum / 16.0;
}
#endif

// The receiver's plane on the face, per world unit of tap offset along u and v (flat without
// RECEIVER_PLANE). `stored` is the point's own stored depth.
TapPlane cubePlane(Receiver r, vec3 wsToLight, CubeTap c, float stored, float near, float far) {
    TapPlane plane = kFlatPlane;
#if defined(RECEIVER_PLANE)
    plane.cosine = abs(dot(r.planeNormal, wsToLight));
    // Affine on the face: a face is a perspective projection. The spread is half a texel's
    // change, for the bilinear comparisons.
    vec3 n = r.planeNormal;
    vec2 g = vec2(cubePlaneDepth(n, c.toPoint, c.u * c.step, near, far) - stored,
                  cubePlaneDepth(n, c.toPoint, c.v * c.step, near, far) - stored) / c.step;
    // Capped as for single maps: no steeper than a surface tilted kPlaneMaxSlope, whose depth
    // changes that many steps per step across the light; further on the approach side.
    float along = max(1.0 - kPlaneMaxSlope * c.step / length(c.toPoint), 1e-3);
    float maxPerWorld =
        abs(stored - cubePlaneDepth(n, c.toPoint * along, vec3(0.0), near, far)) / c.step;
    plane.full = g;
    float steep = length(g);
    if (steep > maxPerWorld) g *= maxPerWorld / steep;
    plane.g = g;
    plane.spread = 0.5 * c.step * (abs(g.x) + abs(g.y));
#endif
    return plane;
}

// Point lights: the cube face of the direction light -> point holds the depth
// along that face's axis; compare against the same depth of this point. PCF taps lie in the
// face's plane (a 2-D kernel on the face, not the online WebGL tutorial's 3-D grid of
// directions: the same footprint for k^2 instead of k^3 lookups).
ShadowSample cubeVisibility(LightRecord light, Receiver r, vec3 wsToLight) {
    ShadowSample result = kLitSample;
    // From where the cube was drawn (a map kept while its light moves was drawn elsewhere).
    vec3 toPoint = (light.textureFromWorld * vec4(r.position, 1.0)).xyz;
    vec3 cubeOrigin = -light.textureFromWorld[3].xyz;
    float near = light.mapNear, far = light.mapFar;
    vec3 a = abs(toPoint);
    float major = max(a.x, max(a.y, a.z));
    result.texelWorld = light.texelWorldSize * major;
    toPoint += lookupOffset(light, r, wsToLight, light.texelWorldSize * major, kCubeReach,
                            kCubeGrazingShift);
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
    // under a point light just above it flips into shadow at once). Both sides round, as
    // mapRounding counts them: 2^-23, not 2^-24.
    float wsScale = length(r.position) + length(cubeOrigin);
    float rounding = exp2(-23.0) * (farTerm + nearTerm * (2.0 + wsScale / major));
    CubeTap c;
    c.toPoint = toPoint;
    c.reference = stored - depthTolerance(light, max(uDepthAware.z, rounding));
    c.layer = float(light.layer);
#if defined(COLOURED_SHADOWS)
    result.tint = cubeTint(c.toPoint, c.layer, c.reference);
#endif
#ifdef RAYS_ONLY
    return result;  // the tint alone: a ray gives the visibility (shadow_lookup.glsl)
#endif
    // Two axes spanning the face of the major axis; one texel is 2 / size at unit distance.
    c.u = a.x >= a.y && a.x >= a.z ? vec3(0, 1, 0) : vec3(1, 0, 0);
    c.v = a.z >= a.x && a.z >= a.y ? vec3(0, 1, 0) : vec3(0, 0, 1);
    c.step = light.texelUv * 2.0 * major;
    TapPlane plane = cubePlane(r, wsToLight, c, stored, near, far);
#if defined(FILTER_PCF) || defined(FILTER_MOMENTS)
    result.visibility = cubeKernel(c, plane);
#elif defined(FILTER_PCSS)
    result.visibility = cubePcss(light, c, plane, major, surfaceSlope(r.normal, wsToLight));
#elif defined(FILTER_POISSON)
    result.visibility = cubePoisson(c, plane);
#elif defined(RECEIVER_PLANE)
    result.visibility = cubeSingleTap(c, plane);
#else
    result.visibility = CUBE_COMPARE(uShadowCubes, c.toPoint, c.layer, c.reference);
#endif
    return result;
}
