// The main pass's light record on the CPU: shaders/light_record.glsl itself, included with
// glm's types under GLSL's names, so the two cannot drift. Its std140 layout is checked here
// member by member; a field added to the .glsl must be added to the checks.
#pragma once

#include <cstddef>

#include <glm/glm.hpp>

namespace gnomon::gpu {

using vec2 = glm::vec2;
using vec3 = glm::vec3;
using mat4 = glm::mat4;
#include "light_record.glsl"  // NOLINT(bugprone-suspicious-include): shared with GLSL

// std140: a mat4 and each vec3 start on 16 bytes, a vec2 on 8, scalars on 4; the scalars
// after a vec3 share its slot.
static_assert(offsetof(LightRecord, textureFromWorld) == 0);
static_assert(offsetof(LightRecord, position) == 64 && offsetof(LightRecord, type) == 76);
static_assert(offsetof(LightRecord, direction) == 80 && offsetof(LightRecord, range) == 92);
static_assert(offsetof(LightRecord, colour) == 96 && offsetof(LightRecord, layer) == 108);
static_assert(offsetof(LightRecord, attenuation) == 112 && offsetof(LightRecord, cosOuter) == 124);
static_assert(offsetof(LightRecord, cosInner) == 128 && offsetof(LightRecord, uvScale) == 140);
static_assert(offsetof(LightRecord, biasConstant) == 144 && offsetof(LightRecord, mapFar) == 156);
static_assert(offsetof(LightRecord, mapCorner) == 160 && offsetof(LightRecord, farSplit) == 172);
static_assert(offsetof(LightRecord, firstSubRecord) == 176 &&
              offsetof(LightRecord, faceSlots) == 188);
static_assert(offsetof(LightRecord, emitterRadius) == 192 &&
              offsetof(LightRecord, sceneLight) == 204);
static_assert(sizeof(LightRecord) == 208, "a std140 array stride is a multiple of 16");
static_assert(sizeof(LightRecord) <= 256, "256 records must fit a 64 KiB uniform block");

// A record with nothing set: zeros, an identity transform, no map.
inline LightRecord emptyLightRecord() {
    LightRecord r{};
    r.textureFromWorld = glm::mat4(1.0f);
    r.layer = -1;
    return r;
}

}  // namespace gnomon::gpu

namespace gnomon {
using GpuLight = gpu::LightRecord;
}  // namespace gnomon
