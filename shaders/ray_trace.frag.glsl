#version 450 core
// The shadow rays of the pixels the main pass's first draw marked (render/RayMarks.h), one
// fragment per marked pixel (ray_pyramid.glsl numbers them): the pixel's ray job (its point,
// its normal, the records of up to two lights a map was unsure of: shadow_rays.glsl's
// SHADOW_RAYS_MARK) traced as the main pass would (rayVisibility), each light's answer as the
// top bit of its record's half.
#include "lights.glsl"
#include "shadow_sample.glsl"
layout(location = 5) uniform vec3 uEye;
#include "ray_pyramid.glsl"
#include "shadow_rays.glsl"
layout(binding = 15) uniform highp usampler2DArray uRayJobs;
layout(location = 0) out uint fResult;

void main() {
    ivec2 t = ivec2(gl_FragCoord.xy) - ivec2(0, uRayPyramidSize.x / 2);  // under the pyramid
    int j = rayJobAt(t);
    fResult = 0u;
    if (j >= rayJobCount()) return;
    ivec2 p = rayJobPixel(j);
    uvec4 job = texelFetch(uRayJobs, ivec3(p, 0), 0);
    Receiver r;
    r.position = uintBitsToFloat(job.xyz);
    uvec4 normal = texelFetch(uRayJobs, ivec3(p, 1), 0);
    r.normal = uintBitsToFloat(normal.xyz);
    r.planeNormal = r.normal;
    r.viewDepth = 0.0;
    r.standInError = 0.0;
    r.pixel = vec2(p) + 0.5;
    r.object = float(normal.w);
    r.drawn = -1;  // uncertain's draws name no triangle (main.frag.glsl's RAYS_FROM_DRAWN)
    uint result = job.w;
    for (int slot = 0; slot < 2; ++slot) {
        int shift = 16 * slot;
        uint record = (job.w >> uint(shift)) & kRayRecordBits;
        if (record != kNoRayRecord) {
            LightRecord light = lights[record];
            vec3 toLight = toLightFrom(light, light.type, r.position);
            if (rayVisibility(light, r, toLight).visibility > 0.5)
                result |= kRayLitBit << uint(shift);
        }
    }
    fResult = result;
}
