// Coloured shadows (COLOURED_SHADOWS): the light a shadow lookup's receiver gets through
// blended casters, from the transmittance maps (render/TransmittancePass.h), laid out as the
// depth maps are. A texel tints only a receiver behind the nearest blended caster it holds
// (its alpha: that caster's stored depth), so what lies between the glass and the light
// stays untinted.
layout(binding = 7) uniform sampler2DArray uTransmittance;         // read by texelFetch
layout(binding = 8) uniform samplerCubeArray uTransmittanceCubes;  // NEAREST

// The last lookup's transmittance (white: nothing tinted the light).
vec3 gTint = vec3(1.0);

vec3 tintOf(vec4 stored, float reference) {
    return reference > stored.a ? stored.rgb : vec3(1.0);
}

// 2D maps: bilinear by hand over the 2x2 texels around `uv` (layer coordinates), kept
// inside the map's square [originUv, originUv + uvScale]; each texel tested on its own.
vec3 mapTint(vec2 uv, float layer, float reference, vec2 originUv, float uvScale,
             float texelUv) {
    vec2 s = uv / texelUv - 0.5;  // in texels of the layer: texel i's centre is at i
    vec2 base = floor(s);
    vec2 f = s - base;
    vec2 first = floor(originUv / texelUv + 0.5);
    vec2 last = first + floor(uvScale / texelUv + 0.5) - 1.0;
    ivec2 a = ivec2(clamp(base, first, last)), b = ivec2(clamp(base + 1.0, first, last));
    int l = int(layer);
    vec3 t00 = tintOf(texelFetch(uTransmittance, ivec3(a.x, a.y, l), 0), reference);
    vec3 t10 = tintOf(texelFetch(uTransmittance, ivec3(b.x, a.y, l), 0), reference);
    vec3 t01 = tintOf(texelFetch(uTransmittance, ivec3(a.x, b.y, l), 0), reference);
    vec3 t11 = tintOf(texelFetch(uTransmittance, ivec3(b.x, b.y, l), 0), reference);
    return mix(mix(t00, t10, f.x), mix(t01, t11, f.x), f.y);
}

// Cubes: the nearest texel of the face the direction meets.
vec3 cubeTint(vec3 toPoint, float layer, float reference) {
    return tintOf(texture(uTransmittanceCubes, vec4(toPoint, layer)), reference);
}
