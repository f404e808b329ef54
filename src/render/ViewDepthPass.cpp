#include "render/ViewDepthPass.h"

#include "gl/Program.h"
#include "shadow/ShadowMath.h"

namespace gnomon::render {

const gl::Program& ViewDepthPass::program(bool alphaTested) {
    gl::Program& p = mPrograms[alphaTested ? 1 : 0];
    if (!p) {
        // The shadow pass's depth programs: only the matrix differs.
        p = gl::buildProgram(
            alphaTested ? "view depth (alpha-tested)" : "view depth",
            {{GL_VERTEX_SHADER, "depth.vert.glsl"}, {GL_FRAGMENT_SHADER, "depth.frag.glsl"}},
            alphaTested ? std::vector<std::string>{"ALPHA_TEST"} : std::vector<std::string>{});
    }
    return p;
}

void ViewDepthPass::draw(const GpuScene& scene, const glm::mat4& clipFromWorld) {
    glBindFramebuffer(GL_FRAMEBUFFER, mTarget.id());
    const float one = 1.0f;
    glClearNamedFramebufferfv(mTarget.id(), GL_DEPTH, 0, &one);
    glViewport(0, 0, mGrid.x, mGrid.y);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_DEPTH_CLAMP);
    glCullFace(GL_BACK);
    scene.bind();
    bool alpha = false, culling = false;
    GLuint texture = ~0u;
    glDisable(GL_CULL_FACE);
    glUseProgram(program(false).id());
    glUniformMatrix4fv(1, 1, GL_FALSE, &clipFromWorld[0][0]);
    // Runs of consecutive items in the same state: one multi-draw each.
    const std::vector<DrawItem>& items = scene.items();
    std::uint32_t runStart = 0, runLength = 0;
    for (std::uint32_t i = 0; i < items.size(); ++i) {
        const DrawItem& item = items[i];
        if (item.indexCount == 0 || item.alphaMode == AlphaMode::Blend) continue;
        const bool wantAlpha = item.alphaMode == AlphaMode::Mask;
        const bool wantCull = !item.doubleSided;
        const bool differs = wantAlpha != alpha || (alpha && scene.textureOf(item) != texture) ||
                             wantCull != culling;
        if (differs || i != runStart + runLength) {
            scene.drawRange(runStart, runLength);
            runStart = i;
            runLength = 0;
        }
        if (wantAlpha != alpha) {
            alpha = wantAlpha;
            glUseProgram(program(alpha).id());
            glUniformMatrix4fv(1, 1, GL_FALSE, &clipFromWorld[0][0]);
        }
        if (alpha && scene.textureOf(item) != texture) {
            texture = scene.textureOf(item);
            glBindTextureUnit(4, texture);
        }
        if (wantCull != culling) {
            wantCull ? glEnable(GL_CULL_FACE) : glDisable(GL_CULL_FACE);
            culling = wantCull;
        }
        ++runLength;
    }
    scene.drawRange(runStart, runLength);
    glDisable(GL_CULL_FACE);
}

const shadow::ViewSamples& ViewDepthPass::sample(const GpuScene& scene, const Camera& camera,
                                                 int width, int height) {
    const float aspect = float(width) / float(height);
    const glm::ivec2 grid = shadow::sampleGridSize(width, height, kGridLimit);
    const glm::mat4 clipFromWorld = shadow::sampleGridScale(grid) *
                                    shadow::clipFromView(camera, aspect) *
                                    shadow::viewFromWorld(camera);
    if (mValid && mRevision == scene.revision() && mClipFromWorld == clipFromWorld &&
        mGrid == grid) {
        return mSamples;
    }
    if (mGrid != grid || !mTarget) {
        mDepth = gl::Texture::plain2D("view depth samples", GL_DEPTH_COMPONENT32F, grid.x, grid.y);
        mTarget = gl::Framebuffer("view depth samples");
        glNamedFramebufferDrawBuffer(mTarget.id(), GL_NONE);
        glNamedFramebufferReadBuffer(mTarget.id(), GL_NONE);
        glNamedFramebufferTexture(mTarget.id(), GL_DEPTH_ATTACHMENT, mDepth.id(), 0);
        mTarget.checkComplete();
    }
    mGrid = grid;
    draw(scene, clipFromWorld);
    mRead.resize(std::size_t(grid.x) * std::size_t(grid.y));
    glGetTextureImage(mDepth.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                      GLsizei(mRead.size() * sizeof(float)), mRead.data());
    shadow::viewSamples(mRead, grid, camera, aspect, mSamples);
    mValid = true;
    mRevision = scene.revision();
    mClipFromWorld = clipFromWorld;
    return mSamples;
}

}  // namespace gnomon::render
