#version 450 core
// Coloured shadows (render/TransmittancePass.h): a blended caster's transmittance, which
// the blend state multiplies into the map's colour, and its depth, which a MIN blend keeps
// in alpha. A surface of colour c and opacity a passes the share 1 - a of the light,
// filtered by its colour as strongly as it is opaque: white passes 1 - a (what dithered
// shadows cover on average), a = 0 passes everything, a = 1 nothing. truth/AlphaRays.cpp
// traces the same rule.
layout(binding = 4) uniform sampler2D uBaseColourTexture;  // 1x1 white when untextured

in AlphaOut {
    vec2 uv;
    flat float alpha;   // base colour alpha factor
    flat float cutoff;  // unused: every caster drawn here is blended
} vAlpha;
in vec3 vColour;

layout(location = 0) out vec4 transmittance;

void main() {
    vec4 texel = textureLod(uBaseColourTexture, vAlpha.uv, 0.0);
    float a = clamp(vAlpha.alpha * texel.a, 0.0, 1.0);
    // Fully opaque texels are in the depth map already (BLEND_OPAQUE_PARTS): they shadow, with
    // the depth map's filtering, and must not darken the tint of the texels around them.
    if (a >= 254.5 / 255.0) discard;
    vec3 c = clamp(vColour * texel.rgb, 0.0, 1.0);
    transmittance = vec4((1.0 - a) * mix(vec3(1.0), c, a), gl_FragCoord.z);
}
