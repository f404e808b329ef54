#include "render/MainPass.h"

#include <algorithm>
#include <cstring>

#include "gl/Caps.h"
#include "gl/Program.h"
#include "gl/State.h"
#include "render/EdgeMaps.h"
#include "render/MainPassVariants.h"
#include "render/RayScene.h"
#include "render/TiledLights.h"
#include "render/TransmittancePass.h"
#include "render/VisibilityTarget.h"
#include "shadow/DepthPacking.h"
#include "shadow/FrustumClip.h"

namespace gnomon::render {

namespace {
// View-space z from window depth d as (x·d + y) / (z·d + w): the inverse projection's z and
// w rows at ndc z = 2d − 1. They hold no x or y term for perspective and orthographic
// projections (whose z and w rows do not involve x and y), so the contact march needs no
// matrix product per step.
glm::vec4 viewZFromDepth(const glm::mat4& clipFromView) {
    const glm::mat4 m = glm::inverse(clipFromView);
    return {2.0f * m[2][2], m[3][2] - m[2][2], 2.0f * m[2][3], m[3][3] - m[2][3]};
}

// A draw's lights of each kind (unshadowed, single maps, cubes, cascaded) for its program, or
// all -1 when its loops stay loops. `ends` and `first`: the draw's range of the light order.
glm::ivec4 unrolledCounts(glm::ivec4 ends, int first, bool shadows) {
    const glm::ivec4 counts =
        shadows ? glm::ivec4(ends.x - first, ends.y - ends.x, ends.z - ends.y, ends.w - ends.z)
                : glm::ivec4(ends.w - first, 0, 0, 0);
    const int total = counts.x + counts.y + counts.z + counts.w;
    return total <= MainPass::kMaxUnrolledLights ? counts : glm::ivec4(-1);
}
// Under --shadow-rays uncertain, the rays run in RayMarks' pass between two draws, when the
// frame's target is known (gnomon bench's floor draws once).
bool raysApart(const MainPassInputs& in, const RenderOptions& options, bool floor) {
    return in.rays && options.shadow.shadowRays == ShadowRayMode::Uncertain && !floor &&
           in.targetColour && in.targetDepth;
}
}  // namespace

MainPass::MainPass() {
    const int blockBytes = gl::activeCaps().maxUniformBlockSize;
    mMaxLights = std::min(256, blockBytes / int(sizeof(GpuLight)));
    mLights = gl::Buffer("lights", std::size_t(mMaxLights) * sizeof(GpuLight), nullptr,
                         GL_DYNAMIC_STORAGE_BIT);
    mOrderCapacity = std::clamp(blockBytes / 16 * 4, kLeastLightOrderCapacity, kLightOrderCapacity);
    mOrder = gl::Buffer("light order", std::size_t(mOrderCapacity) * sizeof(std::int32_t), nullptr,
                        GL_DYNAMIC_STORAGE_BIT);
}

// Lights and their order: uploaded only when they differ from what the GPU holds.
void MainPass::uploadLights(const std::vector<GpuLight>& lights,
                            const std::vector<std::int32_t>& order) {
    const size_t bytes = lights.size() * sizeof(GpuLight);
    if (lights.size() != mUploaded.size() ||
        (bytes > 0 && std::memcmp(lights.data(), mUploaded.data(), bytes) != 0)) {
        mLights.update(0, bytes, lights.data());
        mUploaded = lights;
    }
    if (order != mUploadedOrder && !order.empty()) {
        mOrder.update(0, order.size() * sizeof(std::int32_t), order.data());
        mUploadedOrder = order;
    }
    glBindBufferBase(GL_UNIFORM_BUFFER, 1, mLights.id());
    glBindBufferBase(GL_UNIFORM_BUFFER, 2, mOrder.id());
}

int MainPass::bindLists(const LightLists& lists) {
    if (!mLists || mLists.width() != lists.columns || mLists.height() != lists.rows) {
        mLists =
            gl::Texture::integers2D("light lists", &lists.texels[0].x, lists.columns, lists.rows);
        mUploadedLists = lists.texels;
    } else if (lists.texels != mUploadedLists) {
        mLists.writeIntegers2D(&lists.texels[0].x);
        mUploadedLists = lists.texels;
    }
    gl::bindTexture(9, mLists);
    int shift = 0;
    while ((1 << shift) < lists.size)
        ++shift;
    return shift;
}

// The maps and their samplers on units 0 (2D) and 1 (cubes), and on 2 and 3 without
// comparison when the lookups read stored depth; true in that case.
bool MainPass::bindMaps(const MainPassInputs& in, const ShadowOptions& so) {
    // Hardware comparison with NEAREST is one texel; LINEAR gives the 2x2 bilinear PCF.
    const bool hand = handCompare(so);
    const GLint compareFilter = so.filter == ShadowFilter::None ? GL_NEAREST : GL_LINEAR;
    const GLint mapFilter = !hand                               ? compareFilter
                            : so.mapFilter == MapFilter::Linear ? GL_LINEAR
                                                                : GL_NEAREST;
    auto makeSampler = [](gl::Sampler& sampler, int& key, int want, const char* label, GLint filter,
                          bool compare) {
        if (sampler && key == want) return;
        sampler = gl::Sampler(label);
        sampler.set(GL_TEXTURE_MIN_FILTER, filter)
            .set(GL_TEXTURE_MAG_FILTER, filter)
            .set(GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE)
            .set(GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE)
            .set(GL_TEXTURE_COMPARE_MODE, compare ? GL_COMPARE_REF_TO_TEXTURE : GL_NONE)
            .set(GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
        key = want;
    };
    makeSampler(mMapSampler, mMapSamplerKey, mapFilter * 2 + (hand ? 1 : 0), "shadow map sampler",
                mapFilter, !hand);
    makeSampler(mCubeSampler, mCubeSamplerKey, compareFilter, "shadow cube sampler", compareFilter,
                true);
    if (!in.shadowMaps && !mDummyMaps) {
        mDummyMaps = gl::Texture::array2D("no shadow maps", GL_DEPTH_COMPONENT32F, 1, 1, 1);
    }
    if (!in.shadowCubes && !mDummyCubes) {
        mDummyCubes = gl::Texture::cubeArray("no shadow cubes", GL_DEPTH_COMPONENT32F, 1, 1);
    }
    gl::bindTexture(0, in.shadowMaps ? *in.shadowMaps : mDummyMaps);
    gl::bindTexture(1, in.shadowCubes ? *in.shadowCubes : mDummyCubes);
    glBindSampler(0, mMapSampler.id());
    glBindSampler(1, mCubeSampler.id());
    // Stored depths without comparison: PCSS's blocker search, and the receiver plane's
    // gathers (each texel compared against its own reference).
    const bool rawDepths = so.filter == ShadowFilter::Pcss || (so.receiverPlane && !hand);
    if (rawDepths) {
        if (!mRawSampler) mRawSampler = gl::Sampler::storedDepth("stored shadow depth sampler");
        gl::bindTexture(2, in.shadowMaps ? *in.shadowMaps : mDummyMaps);
        gl::bindTexture(3, in.shadowCubes ? *in.shadowCubes : mDummyCubes);
        glBindSampler(2, mRawSampler.id());
        glBindSampler(3, mRawSampler.id());
    }
    // The casters' outlines (EdgeMaps): unit 17, read with texelFetch and gathers.
    if (EdgeMaps::supported()) {
        if (!in.edgeMaps && !mNoEdges) {
            mNoEdges = gl::Texture::array2D("no caster outlines", GL_R32UI, 1, 1, 1);
            mNoEdges.setParameter(GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            mNoEdges.setParameter(GL_TEXTURE_MAG_FILTER, GL_NEAREST);
            mNoEdges.clearUnsignedZero(0, 0, 1, 1);
        }
        gl::bindTexture(17, in.edgeMaps ? *in.edgeMaps : mNoEdges);
        glBindSampler(17, 0);
    }
    // The moments of the moment filters: unit 6, filtered bilinearly.
    if (in.shadowMoments) {
        if (!mMomentSampler) {
            mMomentSampler = gl::Sampler::clamped("shadow moments sampler", GL_LINEAR);
        }
        gl::bindTexture(6, *in.shadowMoments);
        glBindSampler(6, mMomentSampler.id());
    }
    // Coloured shadows' transmittance: units 7 (2D maps, LINEAR) and 8 (cubes, NEAREST).
    if (in.transmittance) {
        if (!mTintSampler) mTintSampler = gl::Sampler::clamped("transmittance sampler", GL_LINEAR);
        if (!mRawSampler) mRawSampler = gl::Sampler::storedDepth("stored shadow depth sampler");
        gl::bindTexture(7, in.transmittance->maps());  // empty ones unbind the unit
        gl::bindTexture(8, in.transmittance->cubes());
        glBindSampler(7, mTintSampler.id());
        glBindSampler(8, mRawSampler.id());
    }
    // The casters' BVH for shadow rays: units 12 and 13, their cut-outs 10 and 11, the
    // triangles drawn 16 (OpenGL 4.5), read with texelFetch only.
    if (in.rays) {
        gl::bindTexture(12, in.rays->nodes());
        gl::bindTexture(13, in.rays->triangles());
        if (in.rays->starts()) gl::bindTexture(16, in.rays->starts());
        gl::bindTexture(10, in.rays->masks().uvs());
        gl::bindTexture(11, in.rays->masks().alphas());
    }
    // The view's depth for contact shadows: unit 5, read raw.
    if (in.viewDepth) {
        if (!mRawSampler) mRawSampler = gl::Sampler::storedDepth("stored shadow depth sampler");
        gl::bindTexture(5, *in.viewDepth);
        glBindSampler(5, mRawSampler.id());
    }
    return rawDepths;
}

void MainPass::useProgram(const gl::Program& p, const FrameUniforms& u) {
    gl::use(p);
    gl::uniform(1, u.in->viewFromWorld);
    gl::uniform(2, u.in->clipFromView);
    gl::uniform(3, u.in->ambient);
    gl::uniform(4, u.shadowFactor);
    gl::uniform(5, u.eye);
    gl::uniform(6, u.ranges);
    gl::uniform(10, u.first);
    if (u.tileShift >= 0) gl::uniform(0, u.tileShift);
    gl::uniform(7, u.depthAware);
    if (u.in->hasCascades) gl::uniform(11, u.in->cascadeDepth);
    if (u.in->viewDepth) {
        gl::uniform(8, u.viewZFromDepth);
        gl::uniform(9, u.contactLength);
        gl::uniform(13, u.clipFromWorld);
    }
    if (u.in->shadowMoments) gl::uniform(12, u.lightBleed);
    if (u.recordLight >= 0) gl::uniform(15, u.recordLight);
    if (u.in->rays) {
        gl::uniform(16, u.in->rays->scale());
        setPixelRayUniforms(u.in->pixelRays);
    }
    if (u.rayPyramid.x > 0) gl::uniform(17, u.rayPyramid);
}

// Opaque and masked items in their order (the fast program, then the material one where
// needed, each texture bound once), front faces only; then the back faces of the double-sided
// ones among them; blended ones last, farthest first, over them. Drawn after every front
// face, a double-sided solid's back faces (an open or inward-wound model from a format that
// does not give sides) mostly fail the depth test before they are shaded: drawn with culling
// off in one go, back faces drawn first were shaded and then covered (glmark2's horse: main
// pass 1.34 times as long). The picture is the same: each face is drawn once either way.
void MainPass::drawItems(const GpuScene& scene, const RenderOptions& options,
                         const FrameUniforms& u, bool visibilityPass, bool floor, Items which,
                         RayDraw rays) {
    const MainPassInputs& in = *u.in;
    // Light lists vary per tile: loops, never written out.
    const bool lists = u.tileShift >= 0;
    const glm::ivec4 counts =
        lists ? glm::ivec4(-1) : unrolledCounts(u.ranges, u.first, options.shadow.enabled);
    bool culling = true, material = false;
    // Receives shadows and casts none (a ground added by --ground, glmark2's); has no
    // highlight (gnomon's ground under a glTF model, whose materials all have one): each
    // drops what it does not need from its program.
    auto variantOf = [&](const DrawItem& item) {
        return ItemVariant{options.shadow.enabled && item.receives && !item.casts, !item.specular,
                           rays};
    };
    // Starts in the first opaque item's variant, so no program is built that nothing draws.
    ItemVariant variant;
    for (const DrawItem& item : scene.items()) {
        if (item.alphaMode != AlphaMode::Blend) {
            variant = variantOf(item);
            break;
        }
    }
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    useProgram(program(options, in, counts, visibilityPass, false, floor, variant, lists), u);
    GLuint texture = ~0u;
    // Sets the state `item` needs.
    auto setState = [&](const DrawItem& item) {
        if (item.materialPath != material || !(variantOf(item) == variant)) {
            material = item.materialPath;
            variant = variantOf(item);
            useProgram(program(options, in, counts, visibilityPass, material && !floor, floor,
                               variant, lists),
                       u);
        }
        if (material && scene.textureOf(item) != texture) {
            texture = scene.textureOf(item);
            gl::bindTexture2D(4, texture);
        }
    };
    auto setCulling = [&](bool on) {
        if (on != culling) on ? glEnable(GL_CULL_FACE) : glDisable(GL_CULL_FACE);
        culling = on;
    };
    // Runs of items needing the same state: one multi-draw each.
    mBlended.clear();
    mBackFaces.clear();
    const std::vector<DrawItem>& items = scene.items();
    std::uint32_t runStart = 0, runLength = 0;
    const bool opaque = which != Items::Blended, blended = which != Items::Opaque;
    for (std::uint32_t i = 0; i < items.size(); ++i) {
        if (items[i].alphaMode != AlphaMode::Blend) {
            if (!opaque) continue;
            const DrawItem& item = items[i];
            const bool differs = item.materialPath != material || !(variantOf(item) == variant) ||
                                 (material && scene.textureOf(item) != texture);
            if (differs) {  // the run so far is drawn in the state it was set up for
                scene.drawRange(runStart, runLength);
                runStart = i;
                runLength = 0;
                setState(item);
            }
            ++runLength;
            if (item.doubleSided) mBackFaces.push_back(i);
        } else if (blended && !visibilityPass) {  // scored: the surfaces behind (as the reference)
            const glm::vec3 c = items[i].bounds.centre();
            mBlended.emplace_back(-glm::length(glm::vec3(in.viewFromWorld * glm::vec4(c, 1.0f))),
                                  i);
        }
    }
    if (opaque) scene.drawRange(runStart, runLength);
    if (!mBackFaces.empty()) {
        glCullFace(GL_FRONT);
        // A solid's back faces are hidden behind its front ones wherever the view starts
        // outside it: only the rest of the item shows its back (a horse with a few faces
        // wound the wrong way shows those few). Not behind a masked front face: its clear
        // texels show the back faces.
        const glm::mat4 clipFromWorld = in.clipFromView * in.viewFromWorld;
        for (std::uint32_t i : mBackFaces) {
            setState(items[i]);
            const bool outside = items[i].alphaMode == AlphaMode::Opaque &&
                                 shadow::beyondNearPlane(items[i].bounds, clipFromWorld);
            scene.draw(i, 1, outside ? Part::Open : Part::All);
        }
        glCullFace(GL_BACK);
    }
    if (!mBlended.empty()) {
        std::sort(mBlended.begin(), mBlended.end());
        glEnable(GL_BLEND);
        glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
        glDepthMask(GL_FALSE);
        for (const auto& [distance, i] : mBlended) {
            setState(items[i]);
            setCulling(!items[i].doubleSided);
            scene.draw(i);
        }
        glDepthMask(in.depthReady ? GL_FALSE : GL_TRUE);
        glDisable(GL_BLEND);
    }
    glDisable(GL_CULL_FACE);
}

void MainPass::drawShaded(const GpuScene& scene, const RenderOptions& options,
                          const FrameUniforms& u, bool floor) {
    const MainPassInputs& in = *u.in;
    if (!raysApart(in, options, floor)) {
        drawItems(scene, options, u, false, floor);
        return;
    }
    // The opaque items with the maps' answers, marking where a ray must decide; those rays
    // (in a pass of their own when many: RayMarks::compacts); the marked pixels again with
    // their answers; the blended items over them (their rays in one draw).
    GLint frame = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &frame);
    const bool compact = mRayMarks.compacts();
    mRayPasses += compact ? 1 : 0;
    if (compact) mRayMarks.bindFirstDraw();
    drawItems(scene, options, u, false, floor, Items::Opaque, RayDraw::Mark);
    FrameUniforms second = u;
    second.rayPyramid = mRayMarks.trace(*in.targetColour, *in.targetDepth,
                                        {u.eye, in.rays->scale(), mMaxLights, mOrderCapacity / 4,
                                         in.pixelRays, in.rays->masks().any()},
                                        compact);
    scene.bind();
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    mRayMarks.beginCount();
    drawItems(scene, options, second, false, floor, Items::Opaque,
              compact ? RayDraw::Resolve : RayDraw::Inline);
    mRayMarks.endCount();
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(frame));
    glDepthFunc(in.depthReady ? GL_LEQUAL : GL_LESS);
    glDepthMask(in.depthReady ? GL_FALSE : GL_TRUE);
    drawItems(scene, options, u, false, floor, Items::Blended);
}

// ES (no image stores): the visibility pass once per light, into that light's layer.
void MainPass::recordVisibilityByLight(const GpuScene& scene, const RenderOptions& options,
                                       FrameUniforms u, const VisibilityTarget& visibility,
                                       bool floor) {
    GLint frame = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &frame);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_FALSE);
    for (int light = 0; light < visibility.layers(); ++light) {
        glBindFramebuffer(GL_FRAMEBUFFER, visibility.layerTarget(light).id());
        u.recordLight = light;
        drawItems(scene, options, u, true, floor);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(frame));
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
}

void MainPass::render(const GpuScene& scene, const MainPassInputs& in, const RenderOptions& options,
                      const VisibilityTarget* visibility, bool floor) {
    const TiledLights& tiled = *in.tiled;
    mRayPasses = 0;
    uploadLights(*in.lights, tiled.order());
    // Before the maps: on ES a texture is made and written through the active unit's binding.
    if (raysApart(in, options, floor)) mRayMarks.prepare(*in.targetColour, *in.targetDepth);
    const int tileShift = tiled.lists().size > 0 ? bindLists(tiled.lists()) : -1;
    const bool rawDepths = bindMaps(in, options.shadow);

    const DepthFormat cubeFormat = isColourFormat(options.shadow.depthFormat)
                                       ? DepthFormat::Depth32F
                                       : options.shadow.depthFormat;
    FrameUniforms u;
    u.in = &in;
    u.eye = glm::vec3(glm::inverse(in.viewFromWorld)[3]);
    u.viewZFromDepth = viewZFromDepth(in.clipFromView);
    u.shadowFactor = options.shading.shadowFactor;
    u.depthAware =
        glm::vec3(options.shadow.biasDepthAware, shadow::toleranceStep(options.shadow.depthFormat),
                  shadow::toleranceStep(cubeFormat));
    u.contactLength = options.shadow.contactLength;
    u.clipFromWorld = in.clipFromView * in.viewFromWorld;
    u.lightBleed = options.shadow.lightBleed;
    // The light order's range the draws use: every light, or one tile's.
    u.ranges = tiled.ranges();

    scene.bind();
    glEnable(GL_DEPTH_TEST);
    // With the view's depth in place, a fragment is shaded only where it is the surface kept
    // there (its depth equals the stored one, computed the same way: view_clip.glsl).
    glDepthFunc(in.depthReady ? GL_LEQUAL : GL_LESS);
    glDepthMask(in.depthReady ? GL_FALSE : GL_TRUE);
    glCullFace(GL_BACK);
    if (tiled.lists().size > 0) {
        // One draw; each pixel reads its tile's ranges of the order (main.frag.glsl).
        u.tileShift = tileShift;
        drawShaded(scene, options, u, floor);
        u.tileShift = -1;
    } else if (tiled.tiles().empty()) {
        drawShaded(scene, options, u, floor);
    } else {
        // Each pixel lies in one tile: drawn there once, blended surfaces in the same order.
        glEnable(GL_SCISSOR_TEST);
        for (const LightTile& tile : tiled.tiles()) {
            glScissor(tile.scissor.x, tile.scissor.y, tile.scissor.z, tile.scissor.w);
            u.ranges = tile.ends;
            u.first = tile.first;
            drawShaded(scene, options, u, floor);
        }
        glDisable(GL_SCISSOR_TEST);
        u.ranges = tiled.ranges();
        u.first = 0;
    }
    if (visibility && !gl::activeCaps().imageStore) {
        recordVisibilityByLight(scene, options, u, *visibility, floor);
    } else if (visibility) {
        // The surfaces that won the depth test, again: each light's visibility per pixel,
        // untiled (the score reads every light's visibility everywhere).
        gl::bindImage(0, visibility->visibility(), GL_RGBA32F);
        gl::bindImage(2, visibility->objects(), GL_R32F);
        const gl::Texture* tint = in.transmittance ? visibility->tint() : nullptr;
        if (tint) gl::bindImage(1, *tint, GL_RGBA32F);
        glDepthFunc(GL_LEQUAL);
        glDepthMask(GL_FALSE);
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        drawItems(scene, options, u, true, floor);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glDepthMask(GL_TRUE);
        glDepthFunc(GL_LESS);
        gl::imageStoresDone();
        gl::unbindImage(0, GL_RGBA32F);
        gl::unbindImage(2, GL_R32F);
        if (tint) gl::unbindImage(1, GL_RGBA32F);
    }
    // Between passes depth writes stay on: clears obey the mask (a pass that clears before
    // it sets its state would keep the last frame's depth).
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glBindSampler(0, 0);
    glBindSampler(1, 0);
    if (in.transmittance) {
        glBindSampler(7, 0);
        glBindSampler(8, 0);
    }
    if (rawDepths) {
        glBindSampler(2, 0);
        glBindSampler(3, 0);
    }
}

}  // namespace gnomon::render
