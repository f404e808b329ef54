#include "render/GpuScene.h"

#include <algorithm>
#include <cstring>
#include <string>
#include <string_view>
#include <tuple>

#include "gl/Caps.h"
#include "gl/ShaderSource.h"
#include "gnomon/Error.h"
#include "scene/MeshTopology.h"
#include "scene/SceneUtil.h"
#include "shadow/MeshPieces.h"
#include "shadow/StandIn.h"

namespace gnomon::render {
namespace {

struct GpuVertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec3 colour;
    glm::vec2 uv;
};

template <typename T>
void hashBytes(std::uint64_t& h, const std::vector<T>& v) {
    const std::string_view bytes(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
    h = h * 0x100000001b3ull ^ std::hash<std::string_view>{}(bytes) ^ v.size();
}

std::uint64_t hashGeometry(const Scene& scene) {
    std::uint64_t h = 0xcbf29ce484222325ull ^ scene.meshes.size();
    for (const Mesh& m : scene.meshes) {
        hashBytes(h, m.positions);
        hashBytes(h, m.normals);
        hashBytes(h, m.colours);
        hashBytes(h, m.uvs);
        hashBytes(h, m.indices);
        for (const MeshLod& l : m.lods) {
            hashBytes(h, l.positions);
            hashBytes(h, l.indices);
        }
    }
    return h;
}

std::uint64_t hashTextures(const Scene& scene) {
    std::uint64_t h = 0x84222325cbf29ce4ull ^ scene.textures.size();
    for (const Texture& t : scene.textures) {
        hashBytes(h, t.rgba);
        h = h * 0x100000001b3ull ^ (std::uint64_t(t.width) << 32 | std::uint64_t(t.height));
        h = h * 0x100000001b3ull ^ (int(t.wrapS) * 9 + int(t.wrapT) * 3 + int(t.nearest));
    }
    return h;
}

GLint glWrap(TextureWrap w) {
    return w == TextureWrap::ClampToEdge      ? GL_CLAMP_TO_EDGE
           : w == TextureWrap::MirroredRepeat ? GL_MIRRORED_REPEAT
                                              : GL_REPEAT;
}

// Mesh-local indices made global: OpenGL ES 3.0 (WebGL2) draws have no base vertex.
void appendRebased(std::vector<std::uint32_t>& indices, const std::vector<std::uint32_t>& own,
                   std::uint32_t base) {
    for (std::uint32_t i : own)
        indices.push_back(i + base);
}

}  // namespace

void GpuScene::uploadGeometry(const Scene& scene) {
    // Each mesh's triangles, those on solids first (culled in shadow passes), worked out once
    // per geometry: a new stand-in detail uploads again but keeps them.
    if (mSplits.size() != scene.meshes.size()) {
        mSplits.clear();
        mPieces.clear();
        // Meshes an object blends with keep their triangles' order: it is the order they
        // blend in.
        std::vector<bool> blended(scene.meshes.size(), false);
        for (const Object& o : scene.objects) {
            if (o.mesh < blended.size() &&
                scene.materials[o.material].alphaMode == AlphaMode::Blend) {
                blended[o.mesh] = true;
            }
        }
        for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
            mSplits.push_back(splitForCulling(scene.meshes[m]));
            CullingSplit& split = mSplits.back();
            if (blended[m]) {
                mPieces.push_back({{0, std::uint32_t(split.indices.size()), false, {}}});
            } else {
                mPieces.push_back(shadow::cutIntoPieces(scene.meshes[m].positions, split.indices,
                                                        split.closedIndices));
            }
        }
        mDrawn.setMeshes(scene, mSplits);
    }
    std::vector<GpuVertex> vertices;
    std::vector<std::uint32_t> indices;
    mMeshRanges.clear();
    std::vector<std::pair<std::size_t, GLsizei>> full;
    for (const Mesh& m : scene.meshes) {
        mMeshRanges.emplace_back(indices.size() * sizeof(std::uint32_t),
                                 std::uint32_t(vertices.size()));
        full.emplace_back(mMeshRanges.back().first, GLsizei(m.indices.size()));
        for (size_t i = 0; i < m.positions.size(); ++i) {
            vertices.push_back({m.positions[i], m.normals[i],
                                m.colours.empty() ? glm::vec3(1.0f) : m.colours[i],
                                m.uvs.empty() ? glm::vec2(0.0f) : m.uvs[i]});
        }
        // The file's coarser versions follow the mesh's own vertices, in order, where its
        // stand-ins index them (shadow/StandIn.h); only their positions are read.
        for (const MeshLod& lod : m.lods) {
            for (const glm::vec3& p : lod.positions)
                vertices.push_back(
                    {p, glm::vec3(0.0f, 0.0f, 1.0f), glm::vec3(1.0f), glm::vec2(0.0f)});
        }
        appendRebased(indices, mSplits[full.size() - 1].indices, mMeshRanges.back().second);
    }
    // Every stand-in made so far after all full meshes, sharing their vertices (same base
    // vertex); meshes too small to simplify keep drawing their own range.
    mStandInRanges.clear();
    mStandInRanges[1.0f] = full;
    for (const auto& [detail, meshes] : mStandIns) {
        std::vector<std::pair<std::size_t, GLsizei>>& ranges = mStandInRanges[detail];
        ranges = full;
        for (std::size_t m = 0; m < meshes.size(); ++m) {
            const std::vector<std::uint32_t>& own = meshes[m].indices;
            if (own.empty()) continue;
            ranges[m] = {indices.size() * sizeof(std::uint32_t), GLsizei(own.size())};
            appendRebased(indices, own, mMeshRanges[m].second);
        }
    }
    mVertices =
        gl::Buffer("scene vertices", vertices.size() * sizeof(GpuVertex), vertices.data(), 0);
    mIndices = gl::Buffer("scene indices", indices.size() * sizeof(std::uint32_t), indices.data(),
                          0, gl::Buffer::Use::Indices);
    mVao = gl::VertexArray("scene");
    mVao.vertexBuffer(0, mVertices, 0, sizeof(GpuVertex));
    mVao.elements(mIndices);
    const std::size_t offsets[4] = {offsetof(GpuVertex, position), offsetof(GpuVertex, normal),
                                    offsetof(GpuVertex, colour), offsetof(GpuVertex, uv)};
    for (int a = 0; a < 4; ++a)
        mVao.attribute(a, 0, a == 3 ? 2 : 3, GL_FLOAT, offsets[a]);
    mMeshBounds = meshBounds(scene);
    mObjectData.clear();          // forces the object upload below
    mDrawRecords = gl::Buffer();  // and the draw records' binding to the new vertex array
    mHaveGeometry = true;
    ++mGeometryUploads;
}

// A detail not made yet for this geometry is made once and kept beside the others, so going
// back to one (tune's trials alternate with the starting settings, the viewer's slider)
// switches index ranges without simplifying or uploading again.
bool GpuScene::makeStandIns(const Scene& scene, float casterDetail) {
    if (!(casterDetail < 1.0f) || mStandIns.contains(casterDetail)) return false;
    if (mStandIns.size() >= kKeptStandIns) mStandIns.clear();
    std::vector<shadow::StandIn>& made = mStandIns[casterDetail];
    for (const Mesh& m : scene.meshes) {
        made.push_back(shadow::makeStandIn(m, casterDetail));
        if (made.back().indices.size() == m.indices.size()) made.back() = {};  // its own range
    }
    return true;
}

void GpuScene::uploadTextures(const Scene& scene) {
    mTextures.clear();
    if (!mWhite) {
        const std::uint8_t white[4] = {255, 255, 255, 255};
        mWhite = gl::Texture::image2D("white", 1, 1, white, GL_REPEAT, GL_REPEAT, true);
    }
    for (const Texture& t : scene.textures) {
        mTextures.push_back(gl::Texture::image2D("texture '" + t.name + "'", t.width, t.height,
                                                 t.rgba.data(), glWrap(t.wrapS), glWrap(t.wrapT),
                                                 t.nearest));
    }
    mHaveTextures = true;
}

bool GpuScene::sync(const Scene& scene, double seconds, float casterDetail) {
    // The scene's revision names the state of its meshes, materials, textures and objects:
    // the same one at the same time leaves nothing here to change, and nothing is read (the
    // hashes below read every byte). A new revision is hashed: a copy of the scene, or an
    // edit that changed nothing the GPU holds, uploads nothing.
    const bool sameContent =
        mHaveGeometry && mHaveTextures && scene.revision.value() == mSyncedRevision;
    const bool sameDetail = casterDetail == mCasterDetail;
    if (sameContent && sameDetail && seconds == mSyncedSeconds) return false;
    bool changed = !sameDetail;
    mCasterDetail = casterDetail;
    if (!sameContent) {
        const std::uint64_t hash = hashGeometry(scene);
        if (!mHaveGeometry || hash != mGeometryHash) {
            mStandIns.clear();  // made for other meshes
            mStandInRanges.clear();
            mSplits.clear();
            mGeometryHash = hash;
        }
        const std::uint64_t textureHash = hashTextures(scene);
        if (!mHaveTextures || textureHash != mTextureHash) {
            uploadTextures(scene);
            mTextureHash = textureHash;
            mObjectData.clear();  // items hold texture names: rebuild them
            changed = true;
        }
    }
    if (makeStandIns(scene, casterDetail) || mStandInRanges.empty()) {
        uploadGeometry(scene);
        changed = true;
    }
    const std::vector<std::pair<std::size_t, GLsizei>>& standIns =
        mStandInRanges.at(casterDetail < 1.0f ? casterDetail : 1.0f);
    const std::vector<shadow::StandIn>* standInMeshes =
        casterDetail < 1.0f ? &mStandIns.at(casterDetail) : nullptr;

    // Object records: rebuilt on the CPU (cheap), uploaded only when they differ.
    const size_t n = scene.objects.size();
    const bool resized = mObjectData.size() != n;
    mObjectData.resize(n);
    mCasts.resize(n);
    mItems.clear();
    bool dataChanged = resized;
    mBounds = Aabb();
    mCasterBounds = Aabb();
    mHasUnlit = false;
    mHasBlended = false;
    mHasBlendedCasters = false;
    mDrawn.setObjects(scene);
    for (size_t i = 0; i < n; ++i) {
        const Object& o = scene.objects[i];
        const Material& mat = scene.materials[o.material];
        mHasUnlit = mHasUnlit || mat.unlit;
        mHasBlended = mHasBlended || mat.alphaMode == AlphaMode::Blend;
        mHasBlendedCasters =
            mHasBlendedCasters || (mat.alphaMode == AlphaMode::Blend && o.castsShadows);
        GpaObject g;
        g.worldFromModel = o.worldFromModelAt(seconds);
        g.worldFromModelNormal =
            glm::mat4(glm::transpose(glm::inverse(glm::mat3(g.worldFromModel))));
        g.baseColour = glm::vec4(mat.baseColour, mat.alpha);
        g.material = {mat.specular, mat.shininess, mat.unlit ? 1.0f : 0.0f,
                      mat.doubleSided ? 1.0f : 0.0f};
        g.flags = {o.receivesShadows ? 1.0f : 0.0f, float(int(mat.alphaMode)), mat.alphaCutoff,
                   // Only a caster's own stand-in stands in front of it.
                   standInMeshes && o.castsShadows ? (*standInMeshes)[o.mesh].error : 0.0f};
        const glm::mat3& uv = mat.uvTransform;
        g.uvRow0 = {uv[0][0], uv[1][0], uv[2][0], 0.0f};
        g.uvRow1 = {uv[0][1], uv[1][1], uv[2][1], 0.0f};
        if (resized || std::memcmp(&g, &mObjectData[i], sizeof g) != 0) {
            mObjectData[i] = g;
            dataChanged = true;
        }
        if (mCasts[i] != std::uint8_t(o.castsShadows)) {
            mCasts[i] = std::uint8_t(o.castsShadows);
            changed = true;
        }
        const Aabb box = mMeshBounds[o.mesh].transformed(g.worldFromModel);
        mBounds.extend(box);
        if (o.castsShadows) mCasterBounds.extend(box);
        const Mesh& mesh = scene.meshes[o.mesh];
        const CullingSplit& split = mSplits[o.mesh];
        const std::string_view record(reinterpret_cast<const char*>(&mObjectData[i]),
                                      sizeof(GpaObject));
        DrawItem item{
            std::uint32_t(i), GLsizei(mesh.indices.size()), mMeshRanges[o.mesh].first,
            mat.doubleSided,
            // On solids wound outwards in the world, as culling in a shadow pass needs.
            split.winding * glm::determinant(glm::mat3(g.worldFromModel)) > 0.0f
                ? GLsizei(split.closedIndices)
                : 0,
            o.castsShadows, o.receivesShadows, box, std::hash<std::string_view>{}(record),
            mat.alphaMode,
            mat.baseColourTexture >= 0 ? mTextures[std::size_t(mat.baseColourTexture)].id() : 0u,
            mat.baseColourTexture >= 0 || mat.alphaMode != AlphaMode::Opaque};
        item.specular = mat.specular > 0.0f && !mat.unlit;
        item.firstTriangle = mDrawn.objectFirst(i);
        item.standInFirstIndexByte = standIns[o.mesh].first;
        item.standInIndexCount = standIns[o.mesh].second;
        // A simplified stand-in is not split: culled only when its whole mesh is a solid.
        const bool ownRange = item.standInFirstIndexByte == item.firstIndexByte;
        item.standInClosedIndexCount = ownRange ? item.closedIndexCount
                                       : item.closedIndexCount == item.indexCount
                                           ? item.standInIndexCount
                                           : 0;
        addItems(item, mPieces[o.mesh], g.worldFromModel);
    }
    orderItems();
    if (uploadDrawCommands()) changed = true;
    if (dataChanged) {
        uploadObjectRecords(n);
        changed = true;
    }
    if (changed) ++mRevision;
    mSyncedRevision = scene.revision.value();
    mSyncedSeconds = seconds;
    return changed;
}

// `whole` as one item, or, when its mesh was cut into pieces (shadow/MeshPieces.h) and it
// does not blend (blending follows the mesh's order, which pieces sorted by depth would not),
// one item per piece: each its own index range and world box, so a map culls the pieces
// beyond its volume. A simplified stand-in is not cut: the first piece draws all of it and
// is bounded by the whole object.
void GpuScene::addItems(const DrawItem& whole, const std::vector<shadow::MeshPiece>& pieces,
                        const glm::mat4& worldFromModel) {
    if (pieces.size() <= 1 || whole.alphaMode == AlphaMode::Blend) {
        mItems.push_back(whole);
        return;
    }
    const bool ownStandIn = whole.standInFirstIndexByte == whole.firstIndexByte;
    const bool solid = whole.closedIndexCount > 0;  // the object's solids face outwards
    for (std::size_t p = 0; p < pieces.size(); ++p) {
        const shadow::MeshPiece& piece = pieces[p];
        DrawItem item = whole;
        item.indexCount = GLsizei(piece.indexCount);
        item.firstIndexByte = whole.firstIndexByte + piece.firstIndex * sizeof(std::uint32_t);
        item.firstTriangle = whole.firstTriangle + piece.firstIndex / 3;
        item.closedIndexCount = solid && piece.closed ? item.indexCount : 0;
        item.bounds = piece.bounds.transformed(worldFromModel);
        if (ownStandIn) {
            item.standInFirstIndexByte = item.firstIndexByte;
            item.standInIndexCount = item.indexCount;
            item.standInClosedIndexCount = item.closedIndexCount;
        } else if (p == 0) {
            item.bounds = whole.bounds;
        } else {
            item.standInIndexCount = 0;
            item.standInClosedIndexCount = 0;
        }
        mItems.push_back(item);
    }
}

// Opaque first, then masked, then blended; by texture within each (binds once each). And
// the plan's copy of them.
void GpuScene::orderItems() {
    std::stable_sort(mItems.begin(), mItems.end(), [](const DrawItem& a, const DrawItem& b) {
        return std::make_tuple(int(a.alphaMode), a.texture, a.doubleSided) <
               std::make_tuple(int(b.alphaMode), b.texture, b.doubleSided);
    });
    mPlanItems.resize(mItems.size());
    for (std::size_t i = 0; i < mItems.size(); ++i) {
        const DrawItem& d = mItems[i];
        mPlanItems[i] = {d.bounds,         d.dataHash, d.object,   d.alphaMode,
                         d.indexCount > 0, d.casts,    d.receives, d.closedIndexCount > 0};
    }
}

// The object records, to a buffer texture (ES: rows of a 2D texture), remade when their count
// changed.
void GpuScene::uploadObjectRecords(std::size_t n) {
    const float* records = n ? &mObjectData[0].worldFromModel[0][0] : nullptr;
    if (!gl::activeCaps().textureBuffers) {
        // ES: rows of kObjectsPerRow records in a 2D texture (scene_data.glsl).
        const int rowTexels = int(gl::kObjectsPerRow * kObjectTexels);
        if (mObjectCount != n || !mObjectTexels) {
            checkObjectTexels(n);
            mObjectTexels =
                gl::Texture::texelRows("scene objects", records, n * kObjectTexels, rowTexels);
        } else if (n > 0) {
            mObjectTexels.writeTexelRows(records, n * kObjectTexels);
        }
    } else if (mObjects.size() != n * sizeof(GpaObject) || !mObjects) {
        checkObjectTexels(n);
        mObjects = gl::Buffer("scene objects", n * sizeof(GpaObject), mObjectData.data(),
                              GL_DYNAMIC_STORAGE_BIT);
        mObjectTexels = gl::Texture::bufferView("scene objects", mObjects, GL_RGBA32F);
    } else {
        mObjects.update(0, n * sizeof(GpaObject), mObjectData.data());
    }
    mObjectCount = n;
}

std::string objectRecordsOverflow(std::size_t objects, std::size_t maxTexels) {
    const std::size_t texels = objects * kObjectTexels;
    if (texels <= maxTexels) return {};
    return "the scene has " + std::to_string(objects) + " objects: their records need " +
           std::to_string(texels) + " texels of a data texture, more than this driver's " +
           std::to_string(maxTexels) + "; merge objects that share a material";
}

// A buffer texture holds at most GL_MAX_TEXTURE_BUFFER_SIZE texels (65 536 at least); ES's
// rows of records, kObjectsPerRow records a row and at most MAX_TEXTURE_SIZE rows.
void GpuScene::checkObjectTexels(std::size_t objects) {
    const gl::Caps& caps = gl::activeCaps();
    const std::size_t most =
        caps.textureBuffers
            ? std::size_t(std::max(caps.maxTextureBufferSize, 0))
            : gl::kObjectsPerRow * kObjectTexels * std::size_t(std::max(caps.maxTextureSize, 0));
    const std::string overflow = objectRecordsOverflow(objects, most);
    if (!overflow.empty()) throw Error(ErrorKind::Gl, overflow);
}

// The object-index attribute (sized to the objects) and the draw commands in item order,
// for 1 to 6 instances; true when the commands changed (and were uploaded).
bool GpuScene::uploadDrawCommands() {
    const std::size_t n = mItems.size();
    // OpenGL 4.5: a command's base instance picks its record (object, first triangle), read as
    // instanced attributes: instance i of a draw with base instance b reads record
    // b + i / divisor. ES has no base instance: the base instance is the object index, which
    // the shaders take from a uniform instead, and no record is read.
    const bool records = gl::activeCaps().drawIndirect;
    if (records) {
        mRecordScratch.assign(2 * std::max<std::size_t>(3 * n, 1), 0u);
        for (std::size_t i = 0; i < n; ++i) {
            const DrawItem& item = mItems[i];
            for (Part part : {Part::All, Part::Closed, Part::Open}) {
                GLuint* r = &mRecordScratch[2 * (std::size_t(part) * n + i)];
                r[0] = item.object;
                r[1] = item.firstTriangle +
                       (part == Part::Open ? GLuint(item.closedIndexCount) / 3 : 0u);
            }
        }
        if (!mDrawRecords || mRecordScratch.size() != mRecords.size()) {
            mDrawRecords = gl::Buffer("draw records", mRecordScratch.size() * sizeof(GLuint),
                                      mRecordScratch.data(), GL_DYNAMIC_STORAGE_BIT);
            mVao.vertexBuffer(1, mDrawRecords, 0, 2 * sizeof(GLuint));
            mVao.integerAttribute(4, 1, 1, GL_UNSIGNED_INT, 0);
            mVao.integerAttribute(5, 1, 1, GL_UNSIGNED_INT, sizeof(GLuint));
            mVao.divisor(1, 1);
            mDivisor = 1;
        } else if (mRecordScratch != mRecords) {
            mDrawRecords.update(0, mRecordScratch.size() * sizeof(GLuint), mRecordScratch.data());
        }
        std::swap(mRecords, mRecordScratch);
    }
    // Draw commands in item order, for 1 to 6 instances (a cube draws the faces the view
    // looks up), then the same for the stand-in casters; uploaded when they differ.
    mCommandScratch.resize(kCommandSets * kMaxInstances * n);
    for (std::size_t i = 0; i < n; ++i) {
        const DrawItem& item = mItems[i];
        for (bool standIn : {false, true}) {
            const GLuint first = GLuint(
                (standIn ? item.standInFirstIndexByte : item.firstIndexByte) / sizeof(GLuint));
            const GLuint count = GLuint(standIn ? item.standInIndexCount : item.indexCount);
            const GLuint closed =
                GLuint(standIn ? item.standInClosedIndexCount : item.closedIndexCount);
            for (Part part : {Part::All, Part::Closed, Part::Open}) {
                const GLuint base = records ? GLuint(std::size_t(part) * n + i) : item.object;
                gl::DrawCommand c{count, 1, first, 0, base};
                if (part == Part::Closed) c.count = closed;
                if (part == Part::Open) c = {count - closed, 1, first + closed, 0, base};
                for (GLsizei k = 1; k <= GLsizei(kMaxInstances); ++k) {
                    c.instanceCount = GLuint(k);
                    mCommandScratch[commandIndex(i, k, standIn, part)] = c;
                }
            }
        }
    }
    return mCommands.assign(mCommandScratch);
}

// The vertex stages read the object records as texels of a buffer texture, not from a storage
// buffer: llvmpipe (Mesa 22.3) reads a storage buffer one lane at a time behind a branch per
// lane, where a texel fetch gathers, and the main pass's vertex stage reads a record per vertex
// (docs/results/performance.md, "Scene size and per-frame overhead").
void GpuScene::bind() const {
    glBindVertexArray(mVao.id());
    gl::bindTexture(kObjectTextureUnit, mObjectTexels);
    mCommands.bind();
}

void GpuScene::setInstanceDivisor(GLsizei instances) const {
    if (instances == mDivisor || !mDrawRecords) return;
    mVao.divisor(1, int(instances));  // every copy: one object
    mDivisor = instances;
}

void GpuScene::draw(std::uint32_t item, GLsizei instances, Part part) const {
    setInstanceDivisor(instances);
    mCommands.drawOne(commandIndex(item, instances, false, part));
}

void GpuScene::drawRange(std::uint32_t first, std::uint32_t count, GLsizei instances, bool standIns,
                         Part part) const {
    if (count == 0) return;
    setInstanceDivisor(instances);
    mCommands.draw(commandIndex(first, instances, standIns, part), count);
}

}  // namespace gnomon::render
