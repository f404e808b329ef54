#include "render/ViewDepthPass.h"

#include "gl/Program.h"
#include "gl/State.h"
#include "render/DepthRuns.h"
#include "shadow/FrustumClip.h"
#include "shadow/ShadowMath.h"

namespace gnomon::render {

const gl::Program& ViewDepthPass::program(bool alphaTested) {
    gl::Program& p = mPrograms[alphaTested ? 1 : 0];
    if (!p) {
        // The shadow pass's depth programs, positioned as the main pass positions them.
        std::vector<std::string> defines{"VIEW_CAMERA"};
        if (alphaTested) defines.push_back("ALPHA_TEST");
        p = gl::buildProgram(
            alphaTested ? "view depth (alpha-tested)" : "view depth",
            {{GL_VERTEX_SHADER, "depth.vert.glsl"}, {GL_FRAGMENT_SHADER, "depth.frag.glsl"}},
            defines);
    }
    return p;
}

void ViewDepthPass::draw(const GpuScene& scene) {
    glBindFramebuffer(GL_FRAMEBUFFER, mTarget.id());
    const float one = 1.0f;
    glDepthMask(GL_TRUE);  // the clear obeys it
    mTarget.clearDepth(one);
    glViewport(0, 0, mGrid.size.x, mGrid.size.y);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_POLYGON_OFFSET_FILL);
    gl::setDepthClamp(false);
    glCullFace(GL_BACK);
    scene.bind();
    // What the main pass draws opaque: masked items cut where it cuts, blended ones skipped.
    mItems.clear();
    const std::vector<DrawItem>& items = scene.items();
    for (std::uint32_t i = 0; i < items.size(); ++i) {
        if (items[i].indexCount > 0 && items[i].alphaMode != AlphaMode::Blend) {
            mItems.push_back(i);
            mTrianglesDrawn += std::uint64_t(items[i].indexCount / 3);  // submitted, culled too
        }
    }
    const glm::mat4 clipFromWorld = mClipFromView * mViewFromWorld;
    drawDepthRuns(
        scene, mItems, 1, /*standIns=*/false,
        [](const DrawItem& item) { return item.alphaMode == AlphaMode::Mask; },
        // Double-sided solids beyond the near plane show no back faces (MainPass likewise),
        // unless a mask's clear texels show them.
        [&](const DrawItem& item) {
            if (!item.doubleSided) return Cull::All;
            if (item.alphaMode != AlphaMode::Opaque) return Cull::None;
            return shadow::beyondNearPlane(item.bounds, clipFromWorld) ? Cull::Solids : Cull::None;
        },
        [&](bool alpha) {
            gl::use(program(alpha));
            gl::uniform(1, mViewFromWorld);
            gl::uniform(2, mClipFromView);
        });
}

void ViewDepthPass::allocate(const shadow::SampleGrid& grid) {
    mDepth = gl::Texture::plain2D("view depth", GL_DEPTH_COMPONENT32F, grid.size.x, grid.size.y);
    // Read with texelFetch and no sampler (reduce()): ES counts a depth texture filtered
    // LINEAR without comparison, or with mipmaps it lacks, as incomplete, reading 0.
    mDepth.setParameter(GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    mDepth.setParameter(GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    mTarget = gl::Framebuffer("view depth");
    mTarget.depthOnly();
    mTarget.attach(GL_DEPTH_ATTACHMENT, mDepth);
    mTarget.checkComplete();
    mRanges = gl::Texture::plain2D("view depth ranges", GL_RG32F, grid.cells.x, grid.cells.y);
    mRangeTarget = gl::Framebuffer("view depth ranges");
    mRangeTarget.attach(GL_COLOR_ATTACHMENT0, mRanges);
    mRangeTarget.drawColour0();
    mRangeTarget.checkComplete();
}

void ViewDepthPass::reduce() {
    if (!mReduce) {
        mReduce = gl::buildProgram("view depth reduction",
                                   {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                    {GL_FRAGMENT_SHADER, "depth_reduce.frag.glsl"}});
        mEmpty = gl::VertexArray("view depth reduction (no attributes)");
    }
    glBindFramebuffer(GL_FRAMEBUFFER, mRangeTarget.id());
    glViewport(0, 0, mGrid.cells.x, mGrid.cells.y);
    glDisable(GL_DEPTH_TEST);
    gl::use(mReduce);
    gl::uniform(0, glm::ivec2(mGrid.block, mGrid.block));
    gl::uniform(1, glm::ivec2(mGrid.size.x, mGrid.size.y));
    gl::bindTexture(0, mDepth);
    glBindSampler(0, 0);  // the main pass's comparing sampler would compare the gathers
    glBindVertexArray(mEmpty.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glEnable(GL_DEPTH_TEST);
}

const shadow::ViewSamples& ViewDepthPass::sample(const GpuScene& scene, const Camera& camera,
                                                 int width, int height) {
    const float aspect = float(width) / float(height);
    const shadow::SampleGrid grid = shadow::sampleGrid(width, height, kGridLimit);
    mTrianglesDrawn = 0;
    // The grid follows from the size alone, which holds() compares.
    if (holds(scene, camera, width, height)) return mSamples;
    if (grid.size != mGrid.size || !mTarget) allocate(grid);
    mGrid = grid;
    // The main pass's own matrices (Renderer), so its depths and these are the same.
    mViewFromWorld = gnomon::viewFromWorld(camera);
    mClipFromView = gnomon::clipFromView(camera, aspect);
    draw(scene);
    reduce();
    mRead.resize(std::size_t(grid.cells.x) * std::size_t(grid.cells.y));
    mRanges.read(0, 0, 0, grid.cells.x, grid.cells.y, GL_RG, GL_FLOAT,
                 mRead.size() * sizeof(glm::vec2), mRead.data());
    shadow::viewSamples(mRead, grid, camera, aspect, mSamples);
    mValid = true;
    mRevision = scene.revision();
    return mSamples;
}

bool ViewDepthPass::holds(const GpuScene& scene, const Camera& camera, int width,
                          int height) const {
    return mValid && mRevision == scene.revision() && mGrid.size == glm::ivec2(width, height) &&
           mViewFromWorld == gnomon::viewFromWorld(camera) &&
           mClipFromView == gnomon::clipFromView(camera, float(width) / float(height));
}

}  // namespace gnomon::render
