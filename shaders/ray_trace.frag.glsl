#version 450 core
// The shadow rays of the pixels the main pass's first draw marked (render/RayMarks.h), one
// fragment per marked pixel (ray_pyramid.glsl numbers them): the pixel's ray job (its point,
// its normal, the triangle drawn or the object, the records of up to two lights a map was
// unsure of: shadow_rays.glsl's SHADOW_RAYS_MARK) traced as the main pass would
// (rayVisibility), each light's answer as the top bit of its record's half, where the second
// draw reads it: on OpenGL 4.5 stored at the pixel (the pass draws into no texture); on ES 3.0,
// which has no image stores, in the fragment's texel under the pyramid, where the second draw
// finds the pixel's number.
#include "lights.glsl"
#include "shadow_sample.glsl"
layout(location = 5) uniform vec3 uEye;
#include "ray_pyramid.glsl"
#include "shadow_rays.glsl"
layout(binding = 15) uniform highp usampler2D uRayJobs;
layout(location = 0) out uint fResult;
#ifndef GNOMON_GLES
layout(r32ui, binding = 1) uniform writeonly uimage2D uRayAnswersImage;
#endif

// Past slot `slot` (-1: before the first), the job's next light: its slot (2: none left),
// light and direction, and the first steps of its rays (rayTripStep).
int nextLight(uint records, int slot, Receiver r, out RayTrip q, out LightRecord light,
              out vec3 toLight) {
    q = rayTrip();
    q.step = kRayDone;
    light = lights[0];
    toLight = vec3(0.0, 0.0, 1.0);
    ++slot;
    if (slot == 0 && (records & kRayRecordBits) == kNoRayRecord) ++slot;
    if (slot == 1 && ((records >> 16) & kRayRecordBits) == kNoRayRecord) ++slot;
    if (slot < 2) {
        light = lights[(records >> uint(16 * slot)) & kRayRecordBits];
        toLight = toLightFrom(light, light.type, r.position);
        q.step = kRayBegin;
        rayTripStep(q, r, light, toLight, -1.0, -1);
    }
    return slot;
}

void main() {
    ivec2 t = ivec2(gl_FragCoord.xy) - ivec2(0, rayAnswerRow());
    int j = rayJobAt(t);
    fResult = 0u;
    if (j >= rayJobCount()) return;
    ivec2 p = rayJobPixel(j);
    uvec4 job = texelFetch(uRayJobs, p, 0);  // shadow_rays.glsl's WRITE_RAY_JOB
    Receiver r;
    r.pixel = vec2(p) + 0.5;
    r.position = rayJobPoint(r.pixel, uintBitsToFloat(job.x));
    r.normal = rayFromOctahedral(unpackSnorm2x16(job.z));
    r.planeNormal = r.normal;
    r.viewDepth = 0.0;
    r.standInError = 0.0;
    bool drawn = (job.w & 0x80000000u) == 0u;
    r.object = drawn ? -1.0 : float(job.w & 0x7fffffffu);
    r.drawn = drawn ? int(job.w) : -1;
    uint records = job.y, result = records;
    // Both lights' rays in one loop of one trace (shadow_rays.glsl's RayTrip): each lane goes
    // on to its second light as soon as its first is answered.
    RayTrip q;
    LightRecord light;
    vec3 toLight;
    int slot = nextLight(records, -1, r, q, light, toLight);
    while (slot < 2) {
        if (q.step != kRayDone) {
            int hit;
            float d = bvhTrace(q.from, q.dir, q.t0, q.t1, q.anyCaster, q.skip, hit);
            rayTripStep(q, r, light, toLight, d, hit);
        }
        if (q.step == kRayDone) {
            if (q.t < 0.0) result |= kRayLitBit << uint(16 * slot);
            slot = nextLight(records, slot, r, q, light, toLight);
        }
    }
    fResult = result;
#ifndef GNOMON_GLES
    imageStore(uRayAnswersImage, p, uvec4(result));
#endif
}
