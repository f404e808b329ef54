// Coloured shadows (COLOURED_SHADOWS): the light a shadow lookup's receiver gets through
// blended casters, from the transmittance maps (render/TransmittancePass.h), laid out as the
// depth maps are. A texel tints only a receiver behind the nearest blended caster it holds
// (its alpha: that caster's stored depth), so what lies between the glass and the light
// stays untinted.
#include "cube_access.glsl"
#include "texel_gather.glsl"
layout(binding = 7) uniform sampler2DArray uTransmittance;  // LINEAR
layout(binding = 8) uniform CUBE_MAPS uTransmittanceCubes;  // NEAREST

vec3 tintOf(vec4 stored, float reference) {
    return reference > stored.a ? stored.rgb : vec3(1.0);
}

// 2D maps: the bilinear transmittance around `uv` (layer coordinates, kept inside the map's
// square [lo, hi]) counted for the share of its 2x2 footprint whose nearest blended caster
// lies in front of the receiver; clear texels (depth 1, transmittance 1) count as in front,
// which changes nothing they add. Exact wherever the tinting texels agree; two reads (one
// gather of the depths, one bilinear read of the colour) where reading the four texels one by
// one would take four.
vec3 mapTint(vec2 uv, float layer, float reference, vec2 lo, vec2 hi, float texelUv) {
    uv = clamp(uv, lo, hi);
    vec4 depths = GATHER_LAYER_AT(uTransmittance, uv, layer, 3);
    vec2 f = fract(uv / texelUv - 0.5);
    // Gathered as (i, j+1), (i+1, j+1), (i+1, j), (i, j): their bilinear weights.
    vec4 w = vec4((1.0 - f.x) * f.y, f.x * f.y, f.x * (1.0 - f.y), (1.0 - f.x) * (1.0 - f.y));
    vec4 through =
        max(vec4(lessThan(depths, vec4(reference))), vec4(greaterThanEqual(depths, vec4(1.0))));
    vec3 rgb = texture(uTransmittance, vec3(uv, layer)).rgb;
    return mix(vec3(1.0), rgb, dot(w, through));
}

// Cubes: the nearest texel of the face the direction meets.
vec3 cubeTint(vec3 toPoint, float layer, float reference) {
    return tintOf(CUBE_READ(uTransmittanceCubes, toPoint, layer), reference);
}
