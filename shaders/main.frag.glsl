#version 450 core
// Main pass shading (SPEC S4): ambient + Blinn-Phong diffuse and specular per light in view
// space, attenuation 1/(c0 + c1 d + c2 d^2) (area lights: d from the light's plane), spot
// cones, and per-light shadow visibility.
// A shadowed fragment keeps ambient only (SHADOWED_FACTOR undefined) or has its colour
// multiplied by uShadowFactor per shadowing light (SHADOWED_FACTOR, the WebGL book's 0.7).
// SHADOWS_OFF skips every lookup and leaves lighting unchanged.
// VISIBILITY_PASS (gnomon score): after the main pass, the visible surfaces are drawn again
// (depth test LEQUAL, no writes) and each light's visibility and the world size of the map
// texel it came from are stored per pixel, one image layer per light.
#include "lights.glsl"
#include "shadow_lookup.glsl"

in VertexOut {
    vec3 wsPosition;
    vec3 wsNormal;
    vec3 vsPosition;
    vec3 vsNormal;
    vec3 colour;
    flat vec4 material;
    flat float receives;
} vIn;

layout(location = 3) uniform vec3 uAmbient;
layout(location = 4) uniform float uShadowFactor;
layout(location = 5) uniform mat4 uWorldFromView;

layout(location = 0) out vec4 fragColour;

#ifdef VISIBILITY_PASS
layout(early_fragment_tests) in;
layout(rg32f, binding = 0) uniform writeonly image2DArray uVisibility;
#endif

void main() {
    bool unlit = vIn.material.z > 0.5;
    bool receives = vIn.receives > 0.5;
    vec3 vsN = normalize(vIn.vsNormal);
    vec3 wsN = normalize(vIn.wsNormal);
    if (vIn.material.w > 0.5 && !gl_FrontFacing) {  // double-sided: light the side we see
        vsN = -vsN;
        wsN = -wsN;
    }
    vec3 base = vIn.colour;
    vec3 vsToEye = normalize(-vIn.vsPosition);

    vec3 lit = unlit ? base : uAmbient * base;
    float factor = 1.0;
    for (int i = 0; i < uLightCount; ++i) {
        LightData light = lights[i];
        if (light.vsDirection.w < 0.5) continue;
        int type = int(light.vsPosition.w);
        vec3 vsToLight;
        float falloff = 1.0;
        if (type == kDirectional) {
            vsToLight = -normalize(light.vsDirection.xyz);
        } else if (type == kArea) {
            // Parallel rays; falloff with the distance from the light's plane (Hessian
            // normal form: n.p + d, with d = -n.p0 for the plane through the light).
            vec3 n = normalize(light.vsDirection.xyz);
            vsToLight = -n;
            float dist = abs(dot(n, vIn.vsPosition - light.vsPosition.xyz));
            vec3 c = light.attenuation.xyz;
            falloff = 1.0 / max(c.x + c.y * dist + c.z * dist * dist, 1e-6);
        } else {
            vec3 d = light.vsPosition.xyz - vIn.vsPosition;
            float dist = length(d);
            vsToLight = d / dist;
            vec3 c = light.attenuation.xyz;
            falloff = 1.0 / max(c.x + c.y * dist + c.z * dist * dist, 1e-6);
            if (type == kSpot) {
                float cosAngle = dot(-vsToLight, normalize(light.vsDirection.xyz));
                falloff *= smoothstep(light.attenuation.w, light.shadow.x, cosAngle);
            }
        }
        float visibility = 1.0;
#ifndef SHADOWS_OFF
        if (receives && light.colour.w >= 0.0) {
            vec3 wsToLight = mat3(uWorldFromView) * vsToLight;
            gTexelWorld = 0.0;
            visibility = shadowVisibility(light, vIn.wsPosition, wsN, wsToLight, -vIn.vsPosition.z);
#ifdef VISIBILITY_PASS
            imageStore(uVisibility, ivec3(ivec2(gl_FragCoord.xy), i),
                       vec4(visibility, gTexelWorld, 0.0, 0.0));
#endif
        }
#endif
        if (unlit) {
            factor *= mix(uShadowFactor, 1.0, visibility);
            continue;
        }
        float nDotL = max(dot(vsN, vsToLight), 0.0);
        vec3 h = normalize(vsToLight + vsToEye);
        float spec = nDotL > 0.0 ? vIn.material.x * pow(max(dot(vsN, h), 0.0), vIn.material.y) : 0.0;
        vec3 contribution = light.colour.rgb * falloff * (nDotL * base + spec);
#ifdef SHADOWED_FACTOR
        lit += contribution;
        factor *= mix(uShadowFactor, 1.0, visibility);
#else
        lit += visibility * contribution;
#endif
    }
    vec3 colour = lit * factor;
#ifdef DEBUG_CASCADES
    const vec3 kTints[4] = vec3[](vec3(1, 0.3, 0.3), vec3(0.3, 1, 0.3), vec3(0.3, 0.5, 1),
                                  vec3(1, 1, 0.3));
    if (gCascade >= 0) colour = mix(colour, kTints[gCascade], 0.35);
#endif
    fragColour = vec4(colour, 1.0);
}
