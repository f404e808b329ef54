// The GPU copy of a Scene: all meshes in one vertex and one index buffer (uploaded once per
// distinct geometry), the textures (uploaded once per distinct set), and one record per
// object (re-uploaded only when transforms or materials change, e.g. animation; read by the
// vertex stages as texels of a buffer texture). Items
// are ordered opaque, then masked, then blended, and by texture and sidedness within each,
// so passes bind each texture once and draw each run of like items with one
// one call from a static command list (gl::DrawCommands: one command per item; the object
// index reaches the shaders as an instanced attribute, through baseInstance).
#pragma once

#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "core/Aabb.h"
#include "gl/Draw.h"
#include "gl/Objects.h"
#include "gnomon/Scene.h"
#include "render/DrawnTriangles.h"
#include "scene/MeshTopology.h"
#include "shadow/FramePlan.h"
#include "shadow/MeshPieces.h"
#include "shadow/StandIn.h"

namespace gnomon::render {

struct GpaObject {
    glm::mat4 worldFromModel;
    glm::mat4 worldFromModelNormal;
    glm::vec4 baseColour;
    glm::vec4 material;  // specular, shininess, unlit, double-sided
    glm::vec4 flags;     // receives shadows, alpha mode (0 opaque, 1 mask, 2 blend), cutoff,
                         // stand-in caster's error (model units)
    glm::vec4 uvRow0;    // texture coordinates used: (dot(uvRow0.xyz, (u, v, 1)),
    glm::vec4 uvRow1;    //                            dot(uvRow1.xyz, (u, v, 1)))
};
// scene_data.glsl reads a record as kObjectTexels RGBA32F texels.
constexpr std::size_t kObjectTexels = 13;
static_assert(sizeof(GpaObject) == kObjectTexels * sizeof(glm::vec4),
              "scene_data.glsl's kObjectTexels");
// Why `objects` records do not fit a buffer texture of `maxTexels` texels, in one sentence
// naming both and what to do; empty when they fit.
std::string objectRecordsOverflow(std::size_t objects, std::size_t maxTexels);

struct DrawItem {
    std::uint32_t object = 0;
    GLsizei indexCount = 0;
    std::size_t firstIndexByte = 0;  // indices are global (no base vertex)
    bool doubleSided = false;
    // The first closedIndexCount indices lie on solids wound outwards in the world
    // (splitForCulling): a shadow pass that culls their back faces keeps their shadow. The
    // same for the stand-in caster's indices (a simplified mesh: all of them or none).
    GLsizei closedIndexCount = 0;
    bool casts = true;
    bool receives = true;
    Aabb bounds;                 // world space, at the synced time
    std::uint64_t dataHash = 0;  // of the object's GPU record: changes when it moves
    AlphaMode alphaMode = AlphaMode::Opaque;
    GLuint texture = 0;         // base colour texture, 0 = none
    bool materialPath = false;  // textured or not opaque: needs the material shader variants
    // Its material has a specular highlight (and is lit): without one, the main pass draws it
    // with a program that drops the specular term (MainPass, NO_SPECULAR).
    bool specular = true;
    // The stand-in caster shadow passes draw (--caster-detail; the full mesh at 1).
    GLsizei standInIndexCount = 0;
    std::size_t standInFirstIndexByte = 0;
    GLsizei standInClosedIndexCount = 0;
    // Its first triangle's number among all objects' drawn triangles (DrawnTriangles).
    std::uint32_t firstTriangle = 0;
};

// Which of an item's triangles a draw takes: all, those on solids (DrawItem's
// closedIndexCount), or the rest.
enum class Part { All, Closed, Open };

// Does `item` draw into shadow maps' depth with these options? Blended casters may not; with
// --blend-shadows coloured only their fully opaque texels do (the rest tints the light
// through the transmittance maps).
inline bool castsShadow(const DrawItem& item, const ShadowOptions& options) {
    return shadow::castsDepth(item.casts, item.indexCount > 0, item.alphaMode, options);
}
// Does it tint the light through it (drawn into the transmittance maps)?
inline bool castsTint(const DrawItem& item, const ShadowOptions& options) {
    return shadow::castsTint(item.casts, item.indexCount > 0, item.alphaMode, options);
}
// Does it need the alpha-tested depth programs (masked, or blended and dithered or coloured)?
inline bool alphaTestedCaster(const DrawItem& item, const ShadowOptions& options) {
    return item.alphaMode == AlphaMode::Mask ||
           (item.alphaMode == AlphaMode::Blend && (options.blendShadows == BlendShadows::Dithered ||
                                                   options.blendShadows == BlendShadows::Coloured));
}

class GpuScene {
public:
    // Makes the GPU copy match `scene` at `seconds`, with stand-in casters keeping
    // `casterDetail` of each mesh's triangles; returns true when anything changed. Reads the
    // scene's meshes, materials, textures and objects only when its revision or `seconds`
    // differ from the last call's; simplifies the meshes only when the geometry or
    // `casterDetail` changed.
    bool sync(const Scene& scene, double seconds, float casterDetail = 1.0f);
    // Binds the vertex array, the object records (texture unit kObjectTextureUnit, the
    // uObjects buffer texture of scene_data.glsl) and the draw commands.
    void bind() const;
    static constexpr GLuint kObjectTextureUnit = 15;
    // Issues one draw of item `item` (`instances` copies: 1, or one per cube face a point
    // light draws).
    void draw(std::uint32_t item, GLsizei instances = 1, Part part = Part::All) const;
    // Draws `part` of items [first, first + count) in one call (each 1 to kMaxInstances
    // times), of their stand-in casters when `standIns` (shadow passes).
    static constexpr std::size_t kMaxInstances = 6;
    static constexpr std::size_t kCommandSets = 6;  // {full, stand-in} x {all, closed, open}
    void drawRange(std::uint32_t first, std::uint32_t count, GLsizei instances = 1,
                   bool standIns = false, Part part = Part::All) const;
    const std::vector<DrawItem>& items() const { return mItems; }
    // Which triangle a draw's fragment lies on (DrawnTriangles).
    const DrawnTriangles& drawnTriangles() const { return mDrawn; }
    // The items as the frame plan sees them (same order), with the bounds and counters that
    // tell it what changed.
    shadow::PlanScene planScene() const {
        return {&mPlanItems, mBounds, mRevision, geometryHash()};
    }
    // The item's base colour texture, or a 1x1 white one (alpha 1) when it has none.
    GLuint textureOf(const DrawItem& item) const {
        return item.texture ? item.texture : mWhite.id();
    }
    // World bounds of all objects (or casters only) at the synced time.
    const Aabb& bounds() const { return mBounds; }
    const Aabb& casterBounds() const { return mCasterBounds; }
    // Does any object have an unlit material (shadows darken it whatever the light's falloff)?
    bool hasUnlit() const { return mHasUnlit; }
    // Does any item blend (drawn over the view's depth, so not within it)?
    bool hasBlended() const { return mHasBlended; }
    // Does any blended item tint the light through it with these options (coloured shadows)?
    bool hasTintingCasters(const ShadowOptions& options) const {
        return mHasBlendedCasters && options.blendShadows == BlendShadows::Coloured;
    }
    // Changes whenever geometry or object data changed.
    std::uint64_t revision() const { return mRevision; }
    // How many times vertices and indices went to the GPU (a new geometry, a new stand-in
    // detail): what tests check the caching by.
    std::uint64_t geometryUploads() const { return mGeometryUploads; }
    // Content hash of all vertex and index data, stand-in casters included.
    std::uint64_t geometryHash() const {
        std::uint32_t detail = 0;
        std::memcpy(&detail, &mCasterDetail, sizeof detail);
        return mGeometryHash ^ (std::uint64_t(detail) * 0x9e3779b97f4a7c15ull);
    }

private:
    void uploadGeometry(const Scene& scene);
    // Makes the stand-ins for `casterDetail` unless kept already; true when it made them.
    bool makeStandIns(const Scene& scene, float casterDetail);
    void uploadTextures(const Scene& scene);
    bool uploadDrawCommands();
    void uploadObjectRecords(std::size_t n);
    void orderItems();
    void addItems(const DrawItem& whole, const std::vector<shadow::MeshPiece>& pieces,
                  const glm::mat4& worldFromModel);
    // Where the command drawing `part` of item `item`, `instances` times, lies in mCommands.
    std::size_t commandIndex(std::size_t item, GLsizei instances, bool standIns, Part part) const {
        const std::size_t set = (standIns ? 3 : 0) + std::size_t(part);
        return (set * kMaxInstances + std::size_t(instances - 1)) * mItems.size() + item;
    }
    static void checkObjectTexels(std::size_t objects);

    std::uint64_t mGeometryHash = 0, mTextureHash = 0;
    bool mHaveTextures = false;
    std::vector<gl::Texture> mTextures;  // Scene::textures order
    gl::Texture mWhite;
    bool mHaveGeometry = false;
    void setInstanceDivisor(GLsizei instances) const;

    gl::Buffer mVertices, mIndices, mObjects;
    gl::Texture mObjectTexels;     // mObjects as RGBA32F texels, 13 per record
    std::size_t mObjectCount = 0;  // records in mObjectTexels
    // Per item and part (all, closed, open), the draw's record: its object (attribute 4) and
    // its first triangle's number (attribute 5, DrawnTriangles); a command's base instance
    // picks it (OpenGL 4.5 only).
    gl::Buffer mDrawRecords;
    std::vector<GLuint> mRecordScratch, mRecords;
    DrawnTriangles mDrawn;
    // One command per item and part (all, closed, open), for 1 to 6 instances, then the same
    // for the stand-ins: commandIndex.
    gl::DrawCommands mCommands;
    std::vector<gl::DrawCommand> mCommandScratch;
    mutable GLsizei mDivisor = 1;
    mutable gl::VertexArray mVao;  // its instance divisor changes per draw (setInstanceDivisor)
    std::vector<GpaObject> mObjectData;  // reused every frame, no allocation once sized
    // Each object's castsShadows as last synced: not in its record, yet a change must redraw
    // the maps and refit the lights (a new revision).
    std::vector<std::uint8_t> mCasts;
    std::vector<DrawItem> mItems;
    std::vector<shadow::SceneItem> mPlanItems;  // mItems' plan data, same order
    std::vector<std::pair<std::size_t, std::uint32_t>>
        mMeshRanges;  // first index byte, first vertex
    // Stand-in casters by detail: the ones made for the current geometry (empty indices: the
    // mesh's own), at most kKeptStandIns of them, and where each mesh's lies in the index
    // buffer per detail (1: the full meshes), first index byte and count.
    static constexpr std::size_t kKeptStandIns = 4;
    std::map<float, std::vector<shadow::StandIn>> mStandIns;
    std::map<float, std::vector<std::pair<std::size_t, GLsizei>>> mStandInRanges;
    float mCasterDetail = 1.0f;  // the detail drawn
    std::uint64_t mGeometryUploads = 0;
    std::vector<Aabb> mMeshBounds;
    // Per mesh, for the current geometry: its indices in the order uploaded, the closed
    // ones first (splitForCulling).
    std::vector<CullingSplit> mSplits;
    // Per mesh: its pieces (one when it is small or an object blends with it).
    std::vector<std::vector<shadow::MeshPiece>> mPieces;
    Aabb mBounds, mCasterBounds;
    bool mHasUnlit = false, mHasBlended = false, mHasBlendedCasters = false;
    std::uint64_t mRevision = 0;
    std::uint64_t mSyncedRevision = 0;  // the Scene::revision and time last synced
    double mSyncedSeconds = 0.0;
};

}  // namespace gnomon::render
