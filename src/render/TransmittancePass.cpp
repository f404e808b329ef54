#include "render/TransmittancePass.h"

#include <string>

#include "gl/Caps.h"
#include "gl/Program.h"
#include "gl/State.h"
#include "gnomon/Error.h"
#include "render/DepthRuns.h"
#include "render/PassClock.h"

namespace gnomon::render {

namespace {
// RGBA16: colour and the nearest blended depth, 8 bytes a texel. ES 3.0 (WebGL2) cannot
// render to it; half floats hold the colour as well, the depth less finely.
GLenum tintFormat() {
    return gl::activeCaps().norm16 ? GL_RGBA16 : GL_RGBA16F;
}

[[noreturn]] void refused(const std::string& what, std::size_t bytes) {
    const char* format = gl::activeCaps().norm16 ? "RGBA16" : "RGBA16F";
    throw Error(ErrorKind::Gl, "coloured shadows: " + what + " of " + format + " need " +
                                   std::to_string(bytes >> 20) +
                                   " MiB, which the OpenGL driver refused; lower --map-size "
                                   "or use --blend-shadows dithered (no transmittance maps)");
}

gl::Framebuffer target(const std::string& label, const gl::Texture& colour,
                       const gl::Texture& depth, int layer) {
    gl::Framebuffer fb(label);
    fb.attachLayer(GL_COLOR_ATTACHMENT0, colour, layer);
    fb.attachLayer(GL_DEPTH_ATTACHMENT, depth, layer);
    fb.drawColour0();
    fb.checkComplete();
    return fb;
}
}  // namespace

const gl::Program& TransmittancePass::program() {
    if (!mProgram) {
        mProgram = gl::buildProgram("transmittance",
                                    {{GL_VERTEX_SHADER, "depth.vert.glsl"},
                                     {GL_FRAGMENT_SHADER, "transmittance.frag.glsl"}},
                                    {"ALPHA_TEST", "TRANSMITTANCE"});
    }
    return mProgram;
}

void TransmittancePass::allocate(const ShadowPass& pass) {
    mLayerTargets.clear();
    mFaceTargets.clear();
    mMaps = gl::Texture();
    mCubes = gl::Texture();
    if (const gl::Texture& depth = pass.mapDepth(); pass.mapArraySize() > 0) {
        const int size = depth.width(), layers = depth.layers();
        mMaps = gl::Texture::array2D("transmittance maps", tintFormat(), size, size, layers);
        if (!mMaps.allocated()) {
            refused(std::to_string(layers) + " layer(s) of " + std::to_string(size) + "²",
                    std::size_t(size) * std::size_t(size) * 8u * std::size_t(layers));
        }
        for (int layer = 0; layer < layers; ++layer) {
            mLayerTargets.push_back(
                target("transmittance layer " + std::to_string(layer), mMaps, depth, layer));
        }
    }
    if (const gl::Texture& depth = pass.cubes(); depth) {
        const int size = depth.width(), cubes = depth.layers() / 6;
        mCubes = gl::Texture::cubeArray("transmittance cubes", tintFormat(), size, cubes);
        if (!mCubes.allocated()) {
            refused(std::to_string(cubes) + " cube(s) of 6 x " + std::to_string(size) + "²",
                    std::size_t(size) * std::size_t(size) * 48u * std::size_t(cubes));
        }
        for (int face = 0; face < 6 * cubes; ++face) {
            mFaceTargets.push_back(
                target("transmittance face " + std::to_string(face), mCubes, depth, face));
        }
    }
    mGeneration = pass.generation();
}

void TransmittancePass::collect(const GpuScene& scene, const ShadowedLight& light,
                                const ShadowOptions& options) {
    mVisible.clear();
    const shadow::LightVolume volume(light);
    const std::vector<DrawItem>& items = scene.items();
    for (std::uint32_t i = 0; i < items.size(); ++i) {
        if (castsTint(items[i], options) && !volume.outside(items[i].bounds)) mVisible.push_back(i);
    }
}

// Clears the light's transmittance to white at the far plane and draws its blended casters:
// colour multiplied in, depth kept by MIN, tested against the opaque depth without writing it.
void TransmittancePass::drawLight(const GpuScene& scene, const ShadowedLight& light,
                                  const ShadowOptions& options) {
    const bool cube = light.frame.kind == shadow::FrameKind::Cube;
    collect(scene, light, options);
    const float white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    gl::setDepthClamp(light.depthClamp);
    for (int face = 0; face < (cube ? 6 : 1); ++face) {
        gl::Framebuffer& fb = cube ? mFaceTargets[std::size_t(6 * light.layer + face)]
                                   : mLayerTargets[std::size_t(light.layer)];
        glBindFramebuffer(GL_FRAMEBUFFER, fb.id());
        glViewport(light.origin.x, light.origin.y, light.mapSize, light.mapSize);
        glEnable(GL_SCISSOR_TEST);  // this map's square only: the layer's other maps stay
        glScissor(light.origin.x, light.origin.y, light.mapSize, light.mapSize);
        fb.clearColour(white);
        glDisable(GL_SCISSOR_TEST);
        // A face no pixel of the view looks up (ShadowMath.h: faces) is left cleared.
        if (mVisible.empty() || (cube && !light.frame.drawsFace(face))) continue;
        const glm::mat4 m =
            cube ? light.frame.faceClipFromWorld(face) : light.frame.clipFromWorld();
        drawDepthRuns(
            scene, mVisible, 1, /*standIns=*/false, [](const DrawItem&) { return true; },
            [](const DrawItem&) { return Cull::None; },
            [&](bool) {
                gl::use(program());
                gl::uniform(1, m);
            });
    }
}

int TransmittancePass::update(const GpuScene& scene, const ShadowPass& pass,
                              const std::vector<ShadowedLight>& lights,
                              const std::vector<int>& drawn, const ShadowOptions& options,
                              PassClock* clock, std::vector<PassTiming>* timings) {
    bool all = false;
    if (mGeneration != pass.generation()) {
        allocate(pass);
        all = true;
    }
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendEquationSeparate(GL_FUNC_ADD, GL_MIN);
    glBlendFuncSeparate(GL_ZERO, GL_SRC_COLOR, GL_ONE, GL_ONE);
    int maps = 0;
    auto one = [&](const ShadowedLight& light) {
        if (clock) clock->start();
        drawLight(scene, light, options);
        ++maps;
        if (clock && timings) {
            std::uint64_t triangles = 0;
            for (std::uint32_t i : mVisible)
                triangles += std::uint64_t(scene.items()[i].indexCount / 3);
            timings->push_back(
                clock->stop(mapPassName("transmittance", light), light.light, triangles));
        }
    };
    scene.bind();
    forMapsDrawn(lights, drawn, all, one);
    glBlendEquation(GL_FUNC_ADD);
    glDisable(GL_BLEND);
    gl::setDepthClamp(false);
    glDepthMask(GL_TRUE);
    return maps;
}

void TransmittancePass::release() {
    mLayerTargets.clear();
    mFaceTargets.clear();
    mMaps = gl::Texture();
    mCubes = gl::Texture();
    mGeneration = -1;
}

std::size_t TransmittancePass::bytes() const {
    std::size_t total = 0;
    for (const gl::Texture* t : {&mMaps, &mCubes}) {
        if (*t) total += std::size_t(t->width()) * std::size_t(t->height()) * t->layers() * 8u;
    }
    return total;
}

}  // namespace gnomon::render
