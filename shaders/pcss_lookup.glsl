// Percentage-closer soft shadows' search and filter for single maps (FILTER_PCSS), included
// by shadow_lookup.glsl after the pieces it uses: compareDepth, rawDepth, the Poisson disc and
// its per-pixel rotation. The cube lookup's PCSS (cube_lookup.glsl) uses the helpers too.
#if defined(FILTER_PCSS)
// Percentage-closer soft shadows (Fernando 2005). The light is a disc of radius R at
// distance u from the receiver (directional lights: a cone of half-angle a). A blocker
// search over the cone's footprint on the map's near plane averages the depths of what lies
// in front of the receiver; the penumbra there is R (u_r - u_b) / u_b wide (directional:
// (t_r - t_b) tan a), and a Poisson filter of that radius gives the visibility. Taps away
// from the centre compare against the receiver's plane, not its centre depth: tolerance
// grows with the tap's distance times the tangent of the light's angle to the surface.
// Searches and penumbrae are capped at this radius in texels of the map: wider ones would
// spread 16 taps too thin (raise the map's texel size, i.e. a smaller map, for softer).
const float kPcssMaxTexels = 48.0;

// Linear distance from the map's eye for a stored depth (orthographic or perspective).
float linearDepth(LightRecord light, float stored, bool ortho) {
    float n = light.mapNear, f = light.mapFar;
    return ortho ? n + stored * (f - n) : n * f / (f - stored * (f - n));
}

// Stored-depth change per world unit of depth at distance t.
float storedPerWorld(LightRecord light, float t, bool ortho) {
    float n = light.mapNear, f = light.mapFar;
    return ortho ? 1.0 / (f - n) : f * n / ((f - n) * t * t);
}

// World radius of the blocker search (at the near plane) and of the penumbra (at the
// receiver), for a receiver at distance tr and an average blocker at tb.
float pcssSearchWorld(LightRecord light, float tr) {
    float n = light.mapNear;
    return light.emitterAngular != 0 ? light.emitterRadius * (tr - n)
                              : light.emitterRadius * (tr - n) / max(tr + light.emitterDistance, 1e-6);
}
float pcssPenumbraWorld(LightRecord light, float tr, float tb) {
    return light.emitterAngular != 0 ? light.emitterRadius * (tr - tb)
                              : light.emitterRadius * (tr - tb) / max(tb + light.emitterDistance, 1e-6);
}

// tan of the angle between the surface and the light direction, capped: the receiver-plane
// slope the taps allow for.
float surfaceSlope(vec3 wsNormal, vec3 wsToLight) {
    float nDotL = clamp(dot(wsNormal, wsToLight), 0.05, 1.0);
    return min(sqrt(1.0 - nDotL * nDotL) / nDotL, 8.0);
}

// `plane`: the receiver plane's stored-depth gradient per layer uv and its half-texel spread
// (z < 0: none; taps then allow the surface's slope times their distance instead).
float pcssTapReference(float reference, vec2 o, vec3 plane, float perTexel, vec2 offsetUv) {
    return plane.z >= 0.0 ? reference + dot(plane.xy, offsetUv) - plane.z
                          : reference - length(o) * perTexel;
}

float pcssMap(LightRecord light, vec2 uv, float layer, float receiverStored, float reference,
              vec2 lo, vec2 hi, float texelUv, bool ortho, float slope, vec3 plane) {
    float n = light.mapNear;
    float tr = linearDepth(light, receiverStored, ortho);
    float texelAtNear = light.texelWorldSize * (ortho ? 1.0 : n);
    float texelAtReceiver = light.texelWorldSize * (ortho ? 1.0 : tr);
    float perTexel = texelAtReceiver * slope * storedPerWorld(light, tr, ortho);
    float search = clamp(pcssSearchWorld(light, tr) / texelAtNear, 1.0, kPcssMaxTexels);
    mat2 turn = poissonRotation();
    float blockers = 0.0, count = 0.0;
    for (int i = 0; i < 16; ++i) {
        vec2 o = turn * kPoissonDisc[i] * search;
        vec2 tap = clamp(uv + o * texelUv, lo, hi);
        float z = rawDepth(tap, layer);
        if (z < pcssTapReference(reference, o, plane, perTexel, tap - uv)) {
            blockers += z;
            count += 1.0;
        }
    }
    if (count == 0.0) return 1.0;
    float tb = linearDepth(light, blockers / count, ortho);
    float radius =
        clamp(pcssPenumbraWorld(light, tr, tb) / texelAtReceiver, 1.0, kPcssMaxTexels);
    float sum = 0.0;
    for (int i = 0; i < 16; ++i) {
        vec2 o = turn * kPoissonDisc[i] * radius;
        vec2 tap = clamp(uv + o * texelUv, lo, hi);
        sum += compareDepth(tap, layer, pcssTapReference(reference, o, plane, perTexel, tap - uv));
    }
    return sum / 16.0;
}
#endif
