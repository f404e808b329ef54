#include "shadow/FramePlan.h"
#include "shadow/MapSizing.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "scene/SceneUtil.h"

namespace gnomon::shadow {

namespace {
// LightRecord::type (shaders/light_record.glsl).
int lightTypeCode(LightType type) {
    switch (type) {
        case LightType::Directional:
            return gpu::kDirectional;
        case LightType::Spot:
            return gpu::kSpot;
        case LightType::Point:
            return gpu::kPoint;
        case LightType::Area:
            return gpu::kArea;
    }
    return gpu::kDirectional;
}

bool casts(const Scene& s, const RenderOptions& options, std::size_t i) {
    return options.shadow.enabled && s.lights[i].castsShadows && lightIsOn(s, options, i);
}

// The map-related fields of a light record for a single-frustum or cube frame.
void fillShadowRecord(GpuLight& g, const LightCameraFrame& frame, const Light& light,
                      const ShadowOptions& options) {
    g.texelWorldSize = frame.texelWorldSize;
    g.mapNear = frame.near;
    g.mapFar = frame.far;
    // PCSS's emitter: a disc of lightRadius at the light (area lights: on their plane,
    // which may lie off the map's depth origin), or the directional light's angle.
    if (light.type == LightType::Directional) {
        g.emitterRadius = std::tan(glm::radians(options.lightAngle));
        g.emitterAngular = 1;
        g.emitterDistance = 0.0f;
    } else {
        const glm::vec3 eye = glm::vec3(glm::inverse(frame.lightFromWorld)[3]);
        const float offset = light.type == LightType::Area && glm::length(light.direction) > 0.0f
                                 ? glm::dot(eye - light.position, glm::normalize(light.direction))
                                 : 0.0f;
        g.emitterRadius = options.lightRadius;
        g.emitterAngular = 0;
        g.emitterDistance = offset;
    }
    g.frame = frame.kind == FrameKind::Cube           ? gpu::kFrameCube
              : frame.kind == FrameKind::Orthographic ? gpu::kFrameOrthographic
                                                      : gpu::kFramePerspective;
    g.textureFromWorld = frame.kind == FrameKind::Cube
                             ? frame.lightFromWorld  // a translation to the light
                             : textureFromClip() * frame.clipFromWorld();
}
}  // namespace

bool FramePlan::wantsViewSamples(const Scene& s, const RenderOptions& options) {
    if (options.shadow.fitTo != FitTo::ViewDepth) return false;
    for (std::size_t i = 0; i < s.lights.size(); ++i) {
        const Light& l = s.lights[i];
        if (l.shadowCamera.policy == ShadowCameraPolicy::Fit && casts(s, options, i)) {
            return true;
        }
    }
    return false;
}

FramePlan::Held* FramePlan::held(std::size_t i) {
    if (!mFollowing) return nullptr;
    if (mHeld.size() <= i) mHeld.resize(i + 1);
    return &mHeld[i];
}

bool FramePlan::unchanged(const Scene& s, const RenderOptions& options, const PlanScene& scene,
                          const ViewSamples* samples, const Camera* fitCamera) const {
    const Made& m = mMade;
    // Samples filled some other way than viewSamples() carry no generation: always replan.
    const std::uint64_t generation = samples ? samples->generation : 0;
    return m.valid && (!samples || generation != 0) && m.geometry == scene.revision &&
           m.samples == generation && m.following == mFollowing &&
           m.hasFitCamera == (fitCamera != nullptr) && (!fitCamera || m.fitCamera == *fitCamera) &&
           m.camera == s.camera && m.options == options && m.lights == s.lights;
}

void FramePlan::plan(const Scene& s, const RenderOptions& options, const PlanScene& scene,
                     const ViewSamples* samples, const Camera* fitCamera, const HeldMaps& held) {
    if (!unchanged(s, options, scene, samples, fitCamera)) {
        mMade.valid = false;  // until this plan is whole
        mHeldLayout = held.layout;
        mFitCamera = fitCamera ? *fitCamera : s.camera;
        // Faces of their own only with the view's samples to fit them to (a face fitted to
        // boxes is no finer than the cube's), and while their records fit the main pass. Not
        // under PCSS: its blocker search widens each face (cubeLookupReachTexels) until a face
        // map is coarser than the cube's.
        const bool faces = samples && !samples->empty() &&
                           options.shadow.pointMaps == PointMaps::Faces &&
                           options.shadow.filter != ShadowFilter::Pcss;
        mSizeCap = 0;
        planWithin(s, options, scene, samples, faces);
        fitBudget(s, options, scene, samples, faces);
        mPacker.keep();  // the places the next plan keeps
        fillMapRecords();
        collectCasters(scene, options.shadow);
        mMade.geometry = scene.revision;
        mMade.samples = samples ? samples->generation : 0;
        mMade.lights = s.lights;
        mMade.camera = s.camera;
        mMade.hasFitCamera = fitCamera != nullptr;
        if (fitCamera) mMade.fitCamera = *fitCamera;
        mMade.following = mFollowing;
        mMade.options = options;
        mMade.valid = true;
    }
    chooseRedraws(held, options.shadow.mapRedraws);
}

// The lights planned, in records the main pass holds, their maps laid out.
void FramePlan::planWithin(const Scene& s, const RenderOptions& options, const PlanScene& scene,
                           const ViewSamples* samples, bool faces) {
    planLights(s, options, scene, samples, faces);
    if (mHasFaces && int(mLights.size() + mCascadeRecords.size()) > mRecordLimit)
        planLights(s, options, scene, samples, false);
    orderLights(s.lights.size());
    layOutMaps(options.shadow);
}

// Maps of lights naming no size halved together until their arrays fit the budget; a
// sentence (budgetNote) when even kMinNeededMapSize does not.
void FramePlan::fitBudget(const Scene& s, const RenderOptions& options, const PlanScene& scene,
                          const ViewSamples* samples, bool faces) {
    mBudgetNote.clear();
    auto over = [&] {
        return largestArrayBytes(mLayout) > mBudgetBytes || mLayout.layers2D > mMaxLayers ||
               6 * mLayout.cubes > mMaxLayers;
    };
    if (!over()) return;
    int largest = 0;
    for (const ShadowedLight& sl : mShadowed) {
        const Light& l = s.lights[std::size_t(sl.light)];
        if (l.shadowMapSize == 0 && options.shadow.mapSize == 0)
            largest = std::max(largest, sl.mapSize);
    }
    for (mSizeCap = largest / 2; mSizeCap >= kMinNeededMapSize && over(); mSizeCap /= 2)
        planWithin(s, options, scene, samples, faces);
    if (over()) {
        mBudgetNote = std::to_string(mShadowed.size()) + " shadow maps need more than the " +
                      std::to_string(mBudgetBytes >> 20) + " MiB (and " +
                      std::to_string(mMaxLayers) + " layers) an array holds even at " +
                      std::to_string(kMinNeededMapSize) +
                      "² for the lights naming no size; shadow fewer lights or lower their "
                      "shadow-map-size";
    }
}

// The size light `light` asks for when it names none: by need, within the budget's cap.
int FramePlan::wantedSize(const Light& light, const RenderOptions& options) const {
    const int need = neededMapSize(light, mFitCamera, options.width, options.height,
                                   shadowMapSizeOf(light, options.shadow));
    if (mSizeCap <= 0) return need;
    return std::min(need > 0 ? need : shadowMapSizeOf(light, options.shadow), mSizeCap);
}

int FramePlan::windowSize(std::size_t index, const Light& light, const RenderOptions& options,
                          int wanted) {
    if (wanted <= 0 || (light.type != LightType::Spot && light.type != LightType::Point))
        return wanted;
    // A probe without the held extent (a fit at another size would replace it); a cube's
    // faces are sized one by one (planFaces).
    int size = 0;
    const LightCameraFrame probe =
        sizedLightCameraFrame(light, options.shadow, mFitCamera, mFit, size, nullptr, wanted);
    if (!probe.valid || probe.kind != FrameKind::Perspective) return wanted;
    const float whole =
        light.type == LightType::Point
            ? 2.0f / float(size)
            : 2.0f * std::tan(glm::radians(std::clamp(light.outerConeDegrees, 1.0f, 89.0f))) /
                  float(size);
    const Held* h = held(index);
    const int kept = h && h->maps[0].valid ? h->maps[0].mapSize : 0;
    return windowMapSize(probe.texelWorldSize, whole, size, kept);
}

bool FramePlan::withinRange(const Light& light, const ViewSamples* samples) {
    mFit.samples = samples;
    const float reach = lightReach(light);
    if (!(reach > 0.0f) || !samples || samples->empty()) return true;
    samplesWithin(*samples, light.position, reach, mWithin);
    mFit.samples = &mWithin;
    return !mWithin.empty();
}

void FramePlan::planLights(const Scene& s, const RenderOptions& options, const PlanScene& scene,
                           const ViewSamples* samples, bool faces) {
    mShadowed.clear();
    mLights.clear();
    mCascadeRecords.clear();
    mHasCascades = mHasFaces = false;
    const float aspect = float(options.width) / float(options.height);
    // What fitted light cameras look at: the items' boxes, the view and what it sees.
    mFit.casters.clear();
    mFit.receivers.clear();
    for (const SceneItem& item : *scene.items) {
        if (!item.drawable) continue;
        if (castsDepth(item.casts, item.drawable, item.alphaMode, options.shadow))
            mFit.casters.push_back(item.bounds);
        if (item.receives) mFit.receivers.push_back(item.bounds);
    }
    mFit.viewKnown = true;
    mFit.viewClipFromWorld =
        gnomon::clipFromView(mFitCamera, aspect) * gnomon::viewFromWorld(mFitCamera);
    mFit.samples = samples;
    mFit.stabilise = options.shadow.stabilise;
    mFit.visibleFilled = false;
    clipReceivers(mFit, mFit.visibleReceivers);
    mFit.visibleFilled = true;
    for (std::size_t i = 0; i < s.lights.size(); ++i) {
        const Light& light = s.lights[i];
        GpuLight g = gpu::emptyLightRecord();
        const glm::vec3 direction = glm::length(light.direction) > 0.0f
                                        ? glm::normalize(light.direction)
                                        : glm::vec3(0, -1, 0);
        g.position = light.position;
        g.type = lightTypeCode(light.type);
        // 0 off; on: the range (point, spot), or -1 for none.
        const bool ranged =
            light.range > 0.0f && (light.type == LightType::Point || light.type == LightType::Spot);
        g.direction = direction;
        g.range = !lightIsOn(s, options, i) ? 0.0f : ranged ? light.range : -1.0f;
        g.colour = light.colour * light.intensity;
        g.attenuation = {light.attenuation.constant, light.attenuation.linear,
                         light.attenuation.quadratic};
        g.cosOuter = std::cos(glm::radians(light.outerConeDegrees));
        g.cosInner = std::cos(glm::radians(light.innerConeDegrees));
        g.sceneLight = int(i);  // for the visibility pass
        const bool named = light.shadowMapSize > 0 || options.shadow.mapSize > 0;
        const int wanted = named ? 0 : wantedSize(light, options);
        const int mapSize = wanted > 0 ? wanted : shadowMapSizeOf(light, options.shadow);
        const bool shadowing = casts(s, options, i);
        g.biasConstant = options.shadow.biasConstant;
        g.normalOffset = options.shadow.normalOffset;
        const bool cascadable = shadowing && light.type == LightType::Directional &&
                                light.shadowCamera.policy == ShadowCameraPolicy::Fit &&
                                !scene.bounds.empty();
        int cascades = options.shadow.cascades;
        if (cascades == 0) {
            cascades = samples && !samples->empty()
                           ? autoCascadeCount(samples->nearest, samples->farthest)
                           : 1;
        }
        if (cascadable && cascades > 1 && !(samples && samples->empty())) {
            planCascades(s, options, i, direction, mapSize, cascades, aspect, scene.bounds, g);
        } else if (shadowing && !withinRange(light, samples)) {
            // Its range holds nothing the view sees: no map.
        } else if (shadowing) {
            Held* h = held(i);
            int size = 0;
            const LightCameraFrame frame = sizedLightCameraFrame(
                light, options.shadow, mFitCamera, mFit, size, h ? &h->maps[0] : nullptr,
                windowSize(i, light, options, wanted));
            if (frame.valid && frame.kind == FrameKind::Cube && faces) {
                planFaces(s, options, i, frame.faces, size, g);
            } else if (frame.valid) {
                fillShadowRecord(g, frame, light, options.shadow);
                g.sceneLight = int(i);
                mShadowed.push_back(
                    {.light = int(i),
                     .mapSize = size,
                     .frame = frame,
                     .depthClamp = light.shadowCamera.policy == ShadowCameraPolicy::Fit,
                     .record = int(i)});
            }
        }
        mFit.samples = samples;  // withinRange may have pointed it at mWithin
        mLights.push_back(g);
    }
}

// Orders the records by kind for the main pass's loops (shaders/lights.glsl): lights that
// are off are dropped; unshadowed, single-map, cube and cascaded lights follow each other,
// then the cascade records. Indices into the records (shadowed lights, cascaded lights'
// first cascade) are rewritten to match.
void FramePlan::orderLights(std::size_t sceneLights) {
    mOrdered.clear();
    mRemap.assign(sceneLights, -1);
    mHasMap.assign(sceneLights, 0);
    for (const ShadowedLight& sl : mShadowed)
        mHasMap[std::size_t(sl.light)] = 1;
    // The record classes in uLightRanges' order: unshadowed, one map, cube, cascaded.
    auto kindOf = [&](std::size_t i) {
        const GpuLight& g = mLights[i];
        if (g.range == 0.0f) return -1;
        if (!mHasMap[i]) return 0;
        if (g.frame == gpu::kFrameCube || g.frame == gpu::kFrameFaces) return 2;
        return g.frame == gpu::kFrameCascaded ? 3 : 1;
    };
    for (int kind = 0; kind < 4; ++kind) {
        for (std::size_t i = 0; i < sceneLights; ++i) {
            if (kindOf(i) != kind) continue;
            mRemap[i] = int(mOrdered.size());
            mOrdered.push_back(mLights[i]);
        }
        mRanges[kind] = int(mOrdered.size());
    }
    const int base = int(mOrdered.size());
    for (GpuLight& g : mOrdered) {
        if (g.frame == gpu::kFrameCascaded || g.frame == gpu::kFrameFaces)
            g.firstSubRecord += base - int(sceneLights);
    }
    mOrdered.insert(mOrdered.end(), mCascadeRecords.begin(), mCascadeRecords.end());
    for (ShadowedLight& sl : mShadowed) {
        sl.record = sl.cascade >= 0 || sl.face >= 0 ? sl.record - int(sceneLights) + base
                                                    : mRemap[std::size_t(sl.record)];
    }
    mLights.swap(mOrdered);
}

int FramePlan::singleMapKind() const {
    int kind = -1;
    for (int i = mRanges.x; i < mRanges.y; ++i) {
        const int type = mLights[std::size_t(i)].type;
        if (kind >= 0 && type != kind) return -1;
        kind = type;
    }
    return kind;
}

bool FramePlan::constantFalloff() const {
    for (int i = 0; i < mRanges.w; ++i) {
        const GpuLight& g = mLights[std::size_t(i)];
        const int type = g.type;
        if (type == gpu::kDirectional) continue;
        if (g.attenuation.y != 0.0f || g.attenuation.z != 0.0f) return false;
        if (type != gpu::kArea && g.range > 0.0f) return false;  // a range's window
    }
    return true;
}

// `count` maps along the view (Zhang et al. 2006, Parallel-Split Shadow Maps). With view
// samples: split over the depth range they span, each cascade fitted to the samples that
// may read it (its own slice and the previous cascade's blend band). Without: from the
// camera's near plane to where the scene ends, each a stabilised sphere around its slice.
void FramePlan::planCascades(const Scene& s, const RenderOptions& options, std::size_t lightIndex,
                             const glm::vec3& direction, int mapSize, int count, float aspect,
                             const Aabb& sceneBounds, GpuLight& g) {
    const Camera& cam = mFitCamera;
    const ViewSamples* samples = mFit.samples;
    float near = cam.near, far = cam.far;
    if (samples) {
        // The samples' pad: the surface between them may come a little nearer or go farther.
        near = std::max(cam.near, samples->nearest - samples->pad(samples->nearest));
        far = samples->farthest + samples->pad(samples->farthest);
    } else {
        const glm::vec3 forward = glm::normalize(cam.centre - cam.eye);
        float farthest = cam.near * 2.0f;
        for (const glm::vec3& c : sceneBounds.corners())
            farthest = std::max(farthest, glm::dot(c - cam.eye, forward));
        far = std::min(cam.far, farthest);
    }
    if (options.shadow.stabilise) {
        float n = near, f = far;
        stabiliseDepthRange(n, f);
        n = std::max(n, cam.near);
        f = std::min(f, cam.far);
        // A held range serves while it holds [near, far] and is not much looser than n..f.
        Held* h = held(lightIndex);
        if (h && h->cascades == count && h->splitRange.x <= near && h->splitRange.y >= far &&
            h->splitRange.y / h->splitRange.x <= kHoldSlack * (f / n)) {
            n = h->splitRange.x;
            f = h->splitRange.y;
        } else if (h) {
            h->splitRange = {n, f};
            h->cascades = count;
        }
        near = n;
        far = f;
    }
    const float blend = options.shadow.cascadeBlend;
    const std::vector<float> splits = cascadeSplits(near, far, count, options.shadow.cascadeLambda);
    const int first = int(s.lights.size() + mCascadeRecords.size());
    mHasCascades = true;
    g.frame = gpu::kFrameCascaded;
    g.layer = 0;  // has shadows; the maps are the cascade records'
    g.firstSubRecord = first;
    g.cascadeCount = count;
    g.cascadeBlend = blend;
    for (int k = 0; k < count; ++k) {
        const float from = splits[std::size_t(k)], to = splits[std::size_t(k) + 1];
        LightCameraFrame frame;
        frame.valid = false;
        // Where the previous cascade starts blending into this one (shadow_lookup.glsl's
        // cascadeVisibility: the first cascade's band is measured from depth 0).
        const float previous = k >= 2 ? splits[std::size_t(k) - 1] : 0.0f;
        const float reach = k == 0 ? 0.0f : from - blend * (from - previous);
        if (samples) {
            Held* h = held(lightIndex);
            frame = sampledCascadeFrame(direction, mFit, reach,
                                        k + 1 == count ? std::numeric_limits<float>::max() : to,
                                        mapSize, h && k < kMaxCascades ? &h->maps[k] : nullptr);
        }
        // No sample or no caster in this slice: a sphere around it still shadows correctly.
        if (!frame.valid) {
            frame = cascadeFrame(direction, cam, aspect, from, to, sceneBounds, mapSize,
                                 options.shadow.stabilise);
        }
        GpuLight c = g;
        fillShadowRecord(c, frame, s.lights[lightIndex], options.shadow);
        c.sceneLight = int(lightIndex);
        c.farSplit = to;
        c.mapCorner = glm::vec2(0.0f);
        c.mapNear = frame.near;
        c.firstSubRecord = c.cascadeCount = 0;  // a map of its own, not the light's list
        c.cascadeBlend = 0.0f;
        mCascadeRecords.push_back(c);
        mShadowed.push_back({.light = int(lightIndex),
                             .mapSize = mapSize,
                             .frame = frame,
                             .depthClamp = true,
                             .record = first + k,
                             .cascade = k,
                             .depthFrom = reach,
                             .depthTo = k + 1 == count ? std::numeric_limits<float>::max() : to});
    }
}

// Each face the view looks up (`faces`, bit f for face f) a perspective map fitted to the
// samples in it, its record after the scene's lights like a cascade's. The light's own record
// says where they are (light_record.glsl, kFrameFaces): firstSubRecord the first, faceSlots a
// table of six 3-bit slots, face f's record at first + slot, 7 for a face with no map (no
// pixel the view drew looks it up).
void FramePlan::planFaces(const Scene& s, const RenderOptions& options, std::size_t lightIndex,
                          std::uint8_t faces, int mapSize, GpuLight& g) {
    const Light& light = s.lights[lightIndex];
    const int first = int(s.lights.size() + mCascadeRecords.size());
    int table = 0, count = 0;
    for (int face = 0; face < 6; ++face) {
        int slot = 7;
        if ((faces >> face) & 1u) {
            Held* h = held(lightIndex);
            HeldExtent* kept = h ? &h->maps[1 + face] : nullptr;
            int size = mapSize;
            if (light.shadowMapSize <= 0 && options.shadow.mapSize <= 0) {
                // Probed without the held extent, which a fit at another size would replace.
                const LightCameraFrame probe =
                    pointFaceFrame(light, face, options.shadow, mFit, mapSize, nullptr);
                size =
                    windowMapSize(probe.valid ? probe.texelWorldSize : 0.0f, 2.0f / float(mapSize),
                                  mapSize, kept && kept->valid ? kept->mapSize : 0);
            }
            const LightCameraFrame frame =
                pointFaceFrame(light, face, options.shadow, mFit, size, kept);
            if (frame.valid) {
                GpuLight c = g;
                fillShadowRecord(c, frame, light, options.shadow);
                c.mapCorner = glm::vec2(0.0f);
                c.mapNear = frame.near;
                mCascadeRecords.push_back(c);
                mShadowed.push_back({.light = int(lightIndex),
                                     .mapSize = size,
                                     .frame = frame,
                                     .depthClamp = true,
                                     .record = first + count,
                                     .face = face});
                slot = count++;
            }
        }
        table |= slot << (3 * face);
    }
    if (count == 0) return;  // no face holds a caster over what the view sees: no shadow
    mHasFaces = true;
    g.frame = gpu::kFrameFaces;
    g.layer = 0;  // has shadows; the maps are the face records'
    g.firstSubRecord = first;
    g.faceSlots = table;
}

}  // namespace gnomon::shadow
