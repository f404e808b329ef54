#include "render/MomentPass.h"

#include <string>

#include "gl/Program.h"
#include "gnomon/Error.h"
#include "render/PassClock.h"

namespace gnomon::render {

namespace {
int filterIndex(ShadowFilter f) {
    return f == ShadowFilter::Evsm2 ? 0 : f == ShadowFilter::Evsm4 ? 1 : 2;
}

[[noreturn]] void refused(int size, int layers) {
    const std::size_t bytes = std::size_t(size) * std::size_t(size) * 16u * std::size_t(layers);
    throw Error(ErrorKind::Gl, "shadow moments: " + std::to_string(layers) + " layer(s) of " +
                                   std::to_string(size) + "² RGBA32F need " +
                                   std::to_string(bytes >> 20) +
                                   " MiB, which the OpenGL driver refused; lower --map-size");
}
}  // namespace

const gl::Program& MomentPass::program(ShadowFilter filter, bool rows, int radius) {
    gl::Program& p = mPrograms[(filterIndex(filter) * 2 + (rows ? 1 : 0)) * 64 + radius];
    if (p) return p;
    static const char* const kDefines[] = {"MOMENTS_EVSM2", "MOMENTS_EVSM4", "MOMENTS_MSM"};
    std::vector<std::string> defines = {kDefines[filterIndex(filter)],
                                        "MOMENT_RADIUS " + std::to_string(radius)};
    if (rows) defines.push_back("ROWS");
    p = gl::buildProgram(
        std::string("moments ") + toString(filter) + (rows ? " rows" : " columns") + " radius " +
            std::to_string(radius),
        {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "moments.frag.glsl"}},
        defines);
    return p;
}

void MomentPass::allocate(int size, int layers) {
    mLayerTargets.clear();
    mMoments = gl::Texture::array2D("shadow moments", GL_RGBA32F, size, size, layers);
    if (!mMoments.allocated()) refused(size, layers);
    for (int layer = 0; layer < layers; ++layer) {
        gl::Framebuffer fb("shadow moments layer " + std::to_string(layer));
        fb.attachLayer(GL_COLOR_ATTACHMENT0, mMoments, layer);
        fb.drawColour0();
        fb.checkComplete();
        mLayerTargets.push_back(std::move(fb));
    }
    mRows = gl::Texture();  // made for the first blur (allocateRows)
    mRowTarget = gl::Framebuffer();
}

void MomentPass::allocateRows(int size) {
    mRows = gl::Texture::plain2D("shadow moments (rows)", GL_RGBA32F, size, size);
    if (!mRows.allocated()) refused(size, 1);
    mRowTarget = gl::Framebuffer("shadow moments (rows)");
    mRowTarget.attach(GL_COLOR_ATTACHMENT0, mRows);
    mRowTarget.drawColour0();
    mRowTarget.checkComplete();
}

int MomentPass::blur(const ShadowPass& pass, const ShadowedLight& light, int radius) {
    const glm::ivec4 square(light.origin, light.mapSize, light.layer);
    glViewport(light.origin.x, light.origin.y, light.mapSize, light.mapSize);
    // Rows: stored depth to moments, averaged along x; without a blur, straight into the
    // moments array (one pass).
    const GLuint layerTarget = mLayerTargets[std::size_t(light.layer)].id();
    glBindFramebuffer(GL_FRAMEBUFFER, radius > 0 ? mRowTarget.id() : layerTarget);
    gl::use(program(mFilter, true, radius));
    gl::uniform(0, square);
    gl::uniform(
        2, glm::vec3(light.frame.near, light.frame.far, light.frame.orthographic ? 0.0f : 1.0f));
    gl::bindTexture(0, pass.maps());
    glBindSampler(0, mStored.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    if (radius == 0) return 1;
    // Columns: into the map's square of the moments array.
    glBindFramebuffer(GL_FRAMEBUFFER, layerTarget);
    gl::use(program(mFilter, false, radius));
    gl::uniform(0, square);
    gl::bindTexture(0, mRows);
    glBindSampler(0, mStored.id());  // NEAREST: the shader reads texel centres
    glDrawArrays(GL_TRIANGLES, 0, 3);
    return 2;
}

int MomentPass::update(const ShadowPass& pass, const std::vector<ShadowedLight>& lights,
                       const std::vector<int>& drawn, const ShadowOptions& options,
                       PassClock* clock, std::vector<PassTiming>* timings) {
    const int size = pass.mapArraySize();
    if (size == 0) return 0;
    const int layers = pass.maps().layers();
    bool all = options.filter != mFilter || options.momentBlur != mRadius;
    if (!mMoments || mMoments.width() != size || mMoments.layers() != layers) {
        allocate(size, layers);
        all = true;
    }
    if (options.momentBlur > 0 && (!mRows || mRows.width() != size)) allocateRows(size);
    mFilter = options.filter;
    mRadius = options.momentBlur;
    if (!mStored) mStored = gl::Sampler::storedDepth("shadow moments: stored depth");
    if (!mEmpty) mEmpty = gl::VertexArray("shadow moments (no attributes)");
    glBindVertexArray(mEmpty.id());
    glDisable(GL_DEPTH_TEST);
    int passes = 0;
    auto one = [&](const ShadowedLight& light) {
        if (light.frame.kind == shadow::FrameKind::Cube) return;
        if (clock) clock->start();
        passes += blur(pass, light, options.momentBlur);
        if (clock && timings) {
            timings->push_back(clock->stop(mapPassName("moments", light), light.light, 0));
        }
    };
    forMapsDrawn(lights, drawn, all, one);
    glEnable(GL_DEPTH_TEST);
    return passes;
}

void MomentPass::release() {
    mLayerTargets.clear();
    mRowTarget = gl::Framebuffer();
    mMoments = gl::Texture();
    mRows = gl::Texture();
    mRadius = -1;
}

std::size_t MomentPass::bytes() const {
    if (!mMoments) return 0;
    const std::size_t layer = std::size_t(mMoments.width()) * std::size_t(mMoments.height()) * 16u;
    return layer * (std::size_t(mMoments.layers()) + (mRows ? 1u : 0u));
}

}  // namespace gnomon::render
