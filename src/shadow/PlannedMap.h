// One shadow map of a frame as the plan leaves it for the passes: the light camera, where the
// map lies in its array, which casters reach it, and whether it must be drawn again. Pure
// data and geometry, no GL (shadow::FramePlan makes these; render::ShadowPass draws them).
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <string>

#include <glm/glm.hpp>

#include "core/Aabb.h"
#include "gnomon/Options.h"
#include "shadow/FrustumClip.h"
#include "shadow/ShadowMath.h"

namespace gnomon::shadow {

// What the plan needs of one drawable item (render::GpuScene keeps one per draw item, in the
// same order): enough to fit light cameras and to cull casters per map.
struct SceneItem {
    Aabb bounds;                 // world space, at the synced time
    std::uint64_t dataHash = 0;  // of the object's GPU record: changes when it moves
    std::uint32_t object = 0;    // the scene object it draws
    AlphaMode alphaMode = AlphaMode::Opaque;
    bool drawable = false;  // has triangles
    bool casts = true, receives = true;
    bool closed = false;  // has faces on solids wound outwards (culled in shadow passes)
};

// Does an item with these flags draw into shadow maps' depth? Blended casters may not; with
// --blend-shadows coloured only their fully opaque texels do (the rest tints the light
// through the transmittance maps).
inline bool castsDepth(bool casts, bool drawable, AlphaMode alpha, const ShadowOptions& options) {
    return casts && drawable &&
           !(alpha == AlphaMode::Blend && options.blendShadows == BlendShadows::None);
}
// Does it tint the light through it (drawn into the transmittance maps)?
inline bool castsTint(bool casts, bool drawable, AlphaMode alpha, const ShadowOptions& options) {
    return casts && drawable && alpha == AlphaMode::Blend &&
           options.blendShadows == BlendShadows::Coloured;
}

// What a map holds once drawn: the camera(s), its place, the casters and the depth state.
// A map held under one key serves a frame that wants the same key (MapKey::serves).
struct MapKey {
    std::array<glm::mat4, 6> clipFromWorld{};  // one (2D map) or six (cube) used
    int mapSize = 0;
    glm::ivec3 place{-1};               // 2D maps: origin and layer; cubes: the cube
    std::uint64_t castersHash = ~0ull;  // geometry + the casters in the volume
    CullMode cull = CullMode::Back;
    float slope = -1.0f, units = -1.0f;
    bool depthClamp = false;
    DepthFormat format = DepthFormat::Depth32F;
    BlendShadows blend = BlendShadows::Dithered;
    bool edges = false;                  // with the casters' edges beside it (render/EdgeMaps.h)
    std::uint8_t faces = kAllCubeFaces;  // cubes: the faces drawn
    // What a lookup needs of the camera besides clipFromWorld (all follow from it): where it
    // stood (a cube's origin), its depth range and texel size (LightCameraFrame's).
    glm::vec3 eye{0.0f};
    float near = 0.0f, far = 0.0f, texelWorldSize = 0.0f;
    bool operator==(const MapKey&) const = default;
    // A map drawn as `this` may stand in for one wanted as `want` (a light that moved, kept
    // by the redraw budget): the same place and depth state, only the camera or casters
    // differ.
    bool samePlace(const MapKey& want) const {
        return castersHash != ~0ull && mapSize == want.mapSize && place == want.place &&
               cull == want.cull && slope == want.slope && units == want.units &&
               depthClamp == want.depthClamp && format == want.format && blend == want.blend &&
               edges == want.edges;
    }
    // A map drawn as `this` serves `want`: the same, its faces a superset of want's.
    bool serves(const MapKey& want) const {
        MapKey same = want;
        same.faces = faces;
        return *this == same && (want.faces & ~faces) == 0;
    }
};

struct ShadowedLight {
    int light = 0;  // index into Scene::lights
    int mapSize = 1024;
    LightCameraFrame frame;
    bool depthClamp = false;  // fitted cameras: casters in front of near still cast
    int layer = 0;            // 2D array layer, or cube index in the cube-map array
    int record = 0;           // the main pass light record this map belongs to
    int cascade = -1;         // cascade index of a directional light, -1 if not cascaded
    // The view depths whose pixels read this map (a cascade's slice and the previous
    // cascade's blend band; every depth for the others).
    float depthFrom = 0.0f, depthTo = std::numeric_limits<float>::max();
    glm::ivec2 origin{0};  // 2D maps: the map's lower-left texel in its layer
    int face = -1;         // a point light's face drawn as a map of its own (0..5), else -1
    // Its depth casters: FramePlan::casters()[firstCaster, firstCaster + casterCount).
    std::uint32_t firstCaster = 0, casterCount = 0;
    MapKey key{};         // what the map holds once drawn
    bool redraw = false;  // this frame draws it (else the map held serves)
    // Kept by the redraw budget: the map held was drawn under another key, which its
    // record's lookups now use (FramePlan::chooseRedraws).
    bool waiting = false;
};

// What a light's map sees, for culling what it need not draw: its clip volume (casters in
// front of the near plane count when the depth is clamped), or its cube's: within the far
// sphere and, when only some faces are drawn, inside one of theirs; and within the light's
// range (LightCameraFrame::reach).
class LightVolume {
public:
    explicit LightVolume(const ShadowedLight& light)
        : mLight(light),
          mCube(light.frame.kind == FrameKind::Cube),
          mClipFromWorld(mCube ? glm::mat4(1.0f) : light.frame.clipFromWorld()),
          mEye(glm::inverse(light.frame.lightFromWorld)[3]) {
        for (int face = 0; mCube && light.frame.faces != kAllCubeFaces && face < 6; ++face) {
            if (light.frame.drawsFace(face))
                mFaces[std::size_t(mFaceCount++)] = light.frame.faceClipFromWorld(face);
        }
    }
    bool outside(const Aabb& box) const {
        const float reach = mLight.frame.reach;
        if (reach > 0.0f && box.distanceTo(mEye) > reach) return true;
        if (!mCube) return outsideClipVolume(box, mClipFromWorld, mLight.depthClamp);
        if (outsideCube(box, mLight.frame)) return true;
        for (int i = 0; i < mFaceCount; ++i) {
            if (!outsideClipVolume(box, mFaces[std::size_t(i)], true)) return false;
        }
        return mFaceCount > 0;
    }
    // Might `box` hold the light (a spot's or point light's position)? Then a closed caster
    // in it is seen from inside, every face turned away, and culling would drop it all (a
    // point light inside a closed body would light everything around it).
    bool holdsLight(const Aabb& box) const {
        return !mLight.frame.orthographic && glm::all(glm::lessThanEqual(box.min, mEye)) &&
               glm::all(glm::lessThanEqual(mEye, box.max));
    }

private:
    const ShadowedLight& mLight;
    bool mCube;
    glm::mat4 mClipFromWorld;
    glm::vec3 mEye;                     // the light's position (perspective and cube frames)
    std::array<glm::mat4, 6> mFaces{};  // the drawn faces' clip volumes, when not all six
    int mFaceCount = 0;
};

// A pass's name for one map in FrameStats::passes: "<what> light N[, cascade K | face F]".
inline std::string mapPassName(const char* what, const ShadowedLight& light) {
    return std::string(what) + " light " + std::to_string(light.light) +
           (light.cascade >= 0 ? ", cascade " + std::to_string(light.cascade) : "") +
           (light.face >= 0 ? ", face " + std::to_string(light.face) : "");
}

}  // namespace gnomon::shadow
