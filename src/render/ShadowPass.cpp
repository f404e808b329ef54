#include "render/ShadowPass.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cstdio>
#include <span>

#include "gl/Caps.h"
#include "gl/Program.h"
#include "gl/State.h"
#include "gnomon/Error.h"
#include "render/DepthRuns.h"
#include "render/PassClock.h"
#include "shadow/DepthPacking.h"

namespace gnomon::render {

ShadowPass::ShadowPass(bool layeredCubes)
    : mLayered(layeredCubes && gl::activeCaps().layeredFromVertex) {
    program(kPlain, false);  // the one every shadow needs: shader errors show up front
}

const gl::Program& ShadowPass::program(int variant, bool alphaTested, bool opaqueParts) {
    gl::Program& p = mPrograms[variant][alphaTested ? (opaqueParts ? 2 : 1) : 0];
    if (p) return p;
    static const char* const kPacking[3] = {"PACK_R8", "PACK_256", "PACK_255"};
    std::vector<std::string> defines;
    if (alphaTested) defines.push_back("ALPHA_TEST");
    if (alphaTested && opaqueParts) defines.push_back("BLEND_OPAQUE_PARTS");
    std::string name = variant == kPlain  ? "shadow depth"
                       : variant == kCube ? "shadow depth cube"
                                          : "shadow depth ";
    if (variant >= kColour) {
        defines.push_back(kPacking[variant - kColour]);
        name += kPacking[variant - kColour];
    }
    if (alphaTested)
        name += opaqueParts ? " (alpha-tested, blended: opaque parts)" : " (alpha-tested)";
    p = gl::buildProgram(
        name,
        {{GL_VERTEX_SHADER, variant == kCube ? "depth_cube.vert.glsl" : "depth.vert.glsl"},
         {GL_FRAGMENT_SHADER, variant >= kColour ? "depth_colour.frag.glsl" : "depth.frag.glsl"}},
        defines);
    return p;
}

namespace {
gl::Framebuffer depthOnlyFramebuffer(const std::string& label) {
    gl::Framebuffer fb(label);
    fb.depthOnly();
    return fb;
}
}  // namespace

GLenum nativeFormat(DepthFormat format) {
    switch (format) {
        case DepthFormat::Depth16:
            return GL_DEPTH_COMPONENT16;
        case DepthFormat::Depth24:
            return GL_DEPTH_COMPONENT24;
        default:
            return GL_DEPTH_COMPONENT32F;  // depth32f, and cubes of colour formats
    }
}

namespace {
std::size_t texelBytes(GLenum format) {
    return format == GL_DEPTH_COMPONENT16 ? 2 : 4;  // 24-bit depth is stored in 32 bits
}

// The driver would not store the maps a frame needs: one sentence with what was asked, its
// size and what to lower, instead of an incomplete framebuffer later.
[[noreturn]] void refused(const std::string& what, std::size_t bytes) {
    char size[32];
    std::snprintf(size, sizeof size, "%.2f GiB", double(bytes) / double(1u << 30));
    GLint maxLayers = 0, maxSize = 0;
    glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &maxLayers);
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    throw Error(ErrorKind::InvalidInput,
                "shadow maps: " + what + " need " + size +
                    " in one texture, which the OpenGL driver refused (its limits: " +
                    std::to_string(maxSize) + "² texels, " + std::to_string(maxLayers) +
                    " layers, and the memory it can allocate); lower --map-size or the number "
                    "of shadowed lights");
}
}  // namespace

void ShadowPass::allocate2D(int size, int layers, DepthFormat format) {
    const bool colour = isColourFormat(format);
    mMapFormat = format;
    ++mGeneration;
    mFramebuffers.clear();
    mColourDepth = gl::Texture();
    if (colour) {
        mMaps = gl::Texture::array2D("shadow maps (encoded depth)", GL_RGBA8, size, size, layers);
        mColourDepth = gl::Texture::array2D("shadow maps depth test", GL_DEPTH_COMPONENT24, size,
                                            size, layers);
    } else {
        mMaps = gl::Texture::array2D("shadow maps", nativeFormat(format), size, size, layers);
        mMaps.setDepthCompare();
    }
    if (!mMaps.allocated() || (colour && !mColourDepth.allocated())) {
        const std::size_t perTexel = colour ? 8 : texelBytes(nativeFormat(format));
        refused(
            std::to_string(layers) + " maps of " + std::to_string(size) + "² " + toString(format),
            std::size_t(size) * std::size_t(size) * std::size_t(layers) * perTexel);
    }
    for (int layer = 0; layer < layers; ++layer) {
        const std::string label = "shadow map layer " + std::to_string(layer);
        gl::Framebuffer fb = colour ? gl::Framebuffer(label) : depthOnlyFramebuffer(label);
        if (colour) {
            fb.attachLayer(GL_COLOR_ATTACHMENT0, mMaps, layer);
            fb.attachLayer(GL_DEPTH_ATTACHMENT, mColourDepth, layer);
            fb.drawColour0();
        } else {
            fb.attachLayer(GL_DEPTH_ATTACHMENT, mMaps, layer);
        }
        fb.checkComplete();
        mFramebuffers.push_back(std::move(fb));
    }
    // Every map is drawn again into the new texture.
    mHeld.layout.size2D = size;
    mHeld.layout.layers2D = layers;
    mHeld.layout.format2D = format;
    mHeld.maps2D.clear();
}

void ShadowPass::allocateCubes(int size, int cubes, DepthFormat format) {
    ++mGeneration;
    mCubes = gl::Texture::cubeArray("point shadow cubes", nativeFormat(format), size, cubes);
    if (!mCubes.allocated()) {
        refused(std::to_string(cubes) + " cube maps of 6 x " + std::to_string(size) + "² " +
                    toString(isColourFormat(format) ? DepthFormat::Depth32F : format),
                std::size_t(size) * std::size_t(size) * 6u * std::size_t(cubes) *
                    texelBytes(nativeFormat(format)));
    }
    mCubes.setDepthCompare();
    mCubeFaceFramebuffers.clear();
    if (mLayered) {
        mCubeFramebuffer = depthOnlyFramebuffer("point shadow cubes (layered)");
        mCubeFramebuffer.attach(GL_DEPTH_ATTACHMENT, mCubes);
        mCubeFramebuffer.checkComplete();
    } else {
        for (int face = 0; face < 6 * cubes; ++face) {
            gl::Framebuffer fb = depthOnlyFramebuffer("point shadow face " + std::to_string(face));
            fb.attachLayer(GL_DEPTH_ATTACHMENT, mCubes, face);
            fb.checkComplete();
            mCubeFaceFramebuffers.push_back(std::move(fb));
        }
    }
    mHeld.layout.sizeCube = size;
    mHeld.layout.cubes = cubes;
    mHeld.layout.formatCube = isColourFormat(format) ? DepthFormat::Depth32F : format;
    mHeld.cubes.assign(size_t(cubes), shadow::MapKey{});
    mHeld.drawnCubes.assign(size_t(cubes), 0);
}

std::size_t ShadowPass::bytes() const {
    std::size_t total = 0;
    for (const gl::Texture* t : {&mMaps, &mColourDepth, &mCubes}) {
        if (*t)
            total += std::size_t(t->width()) * t->height() * t->layers() * texelBytes(t->format());
    }
    return total + (mEdges.allocated() ? mEdges.bytes() : 0);
}

void ShadowPass::setDepthState(const ShadowOptions& options, bool depthClamp) const {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(options.biasSlope, options.biasUnits);
    if (options.cull != CullMode::None) {
        glCullFace(options.cull == CullMode::Front ? GL_FRONT : GL_BACK);
    }
    gl::setDepthClamp(depthClamp);
}

template <typename SetUniforms>
void ShadowPass::drawCasters(const GpuScene& scene, const shadow::FramePlan& plan,
                             const ShadowedLight& light, const ShadowOptions& options, int variant,
                             GLsizei instances, const SetUniforms& setUniforms) {
    const std::span<const std::uint32_t> casters(plan.casters().data() + light.firstCaster,
                                                 light.casterCount);
    const DrawItem* items = scene.items().data();
    mHoldsLight.resize(scene.items().size());
    for (std::uint32_t k = 0; k < light.casterCount; ++k)
        mHoldsLight[casters[k]] = char(plan.castersHoldLight()[light.firstCaster + k]);
    // Stand-in casters always: at --caster-detail 1 they are the full meshes.
    drawDepthRuns(
        scene, casters, instances, /*standIns=*/true,
        [&](const DrawItem& item) { return alphaTestedCaster(item, options); },
        [&](const DrawItem& item) {
            return casterCull(item, options, mHoldsLight[std::size_t(&item - items)] != 0);
        },
        [&](bool alpha) {
            gl::use(program(variant, alpha, options.blendShadows == BlendShadows::Coloured));
            setUniforms();
        });
}

// The 2D maps held in other slots whose squares `key` draws over no longer hold what their
// keys say (a map of another light drew there since), so none may stand in for a map later.
void ShadowPass::forgetOverlapping(const shadow::MapKey& key, std::size_t slot) {
    const glm::ivec3 p = key.place;
    for (std::size_t i = 0; i < mHeld.maps2D.size(); ++i) {
        shadow::MapKey& other = mHeld.maps2D[i];
        const glm::ivec3 q = other.place;
        if (i == slot || q.z != p.z || other.castersHash == ~0ull) continue;
        const bool apart = q.x >= p.x + key.mapSize || p.x >= q.x + other.mapSize ||
                           q.y >= p.y + key.mapSize || p.y >= q.y + other.mapSize;
        if (!apart) other = shadow::MapKey{};
    }
}

void ShadowPass::invalidate() {
    for (shadow::MapKey& k : mHeld.maps2D)
        k = shadow::MapKey{};
    for (shadow::MapKey& k : mHeld.cubes)
        k = shadow::MapKey{};
}

double ShadowPass::bareDepthPass(const GpuScene& scene, const glm::mat4& clipFromWorld, int size) {
    if (!mBareDepth || mBareDepth.width() != size) {
        mBareDepth = gl::Texture::plain2D("bare depth pass", GL_DEPTH_COMPONENT32F, size, size);
        mBareFramebuffer = depthOnlyFramebuffer("bare depth pass");
        mBareFramebuffer.attach(GL_DEPTH_ATTACHMENT, mBareDepth);
        mBareFramebuffer.checkComplete();
    }
    glFinish();
    const auto start = std::chrono::steady_clock::now();
    glBindFramebuffer(GL_FRAMEBUFFER, mBareFramebuffer.id());
    const float one = 1.0f;
    mBareFramebuffer.clearDepth(one);
    glViewport(0, 0, size, size);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glEnable(GL_CULL_FACE);  // the cheapest state: back faces culled, no offsets, no clamp
    glCullFace(GL_BACK);
    glDisable(GL_POLYGON_OFFSET_FILL);
    gl::setDepthClamp(false);
    gl::use(program(kPlain, false));
    gl::uniform(1, clipFromWorld);
    scene.bind();
    std::uint32_t runStart = 0, runLength = 0;
    const std::vector<DrawItem>& items = scene.items();
    for (std::uint32_t i = 0; i < items.size(); ++i) {
        if (!items[i].casts) continue;
        if (i != runStart + runLength) {
            scene.drawRange(runStart, runLength);
            runStart = i;
            runLength = 0;
        }
        ++runLength;
    }
    scene.drawRange(runStart, runLength);
    glFinish();
    glDisable(GL_CULL_FACE);
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

void ShadowPass::allocate(const shadow::MapLayout& layout) {
    const shadow::MapLayout& have = mHeld.layout;
    if (layout.layers2D > 0 &&
        (!mMaps || have.size2D != layout.size2D || have.layers2D != layout.layers2D ||
         have.format2D != layout.format2D)) {
        allocate2D(layout.size2D, layout.layers2D, layout.format2D);
    }
    if (layout.cubes > 0 && (!mCubes || have.sizeCube != layout.sizeCube ||
                             have.cubes != layout.cubes || have.formatCube != layout.formatCube)) {
        allocateCubes(layout.sizeCube, layout.cubes, layout.format2D);
    }
    // A kind of map no light has this frame gives its memory back (and the frame's
    // statistics stop counting it).
    if (layout.cubes == 0 && mCubes) {
        mCubes = gl::Texture();
        mCubeFramebuffer = gl::Framebuffer();
        mCubeFaceFramebuffers.clear();
        mHeld.cubes.clear();
        mHeld.layout.sizeCube = mHeld.layout.cubes = 0;
    }
    if (layout.layers2D == 0 && mMaps) {
        mMaps = gl::Texture();
        mColourDepth = gl::Texture();
        mFramebuffers.clear();
        mHeld.maps2D.clear();
        mHeld.layout.size2D = mHeld.layout.layers2D = 0;
    }
}

// Clears `light`'s map and draws its casters into it through `m` (a cube's six faces).
void ShadowPass::drawMap(const GpuScene& scene, const shadow::FramePlan& plan,
                         const ShadowedLight& light, const ShadowOptions& options) {
    const std::array<glm::mat4, 6>& m = light.key.clipFromWorld;
    const bool cube = light.frame.kind == shadow::FrameKind::Cube;
    const DepthFormat format = options.depthFormat;
    const float one = 1.0f;
    if (!cube) {
        const bool colour = isColourFormat(format);
        const int variant = !colour                                 ? kPlain
                            : format == DepthFormat::R8             ? kColour
                            : format == DepthFormat::Rgba8Packed256 ? kColour + 1
                                                                    : kColour + 2;
        gl::Framebuffer& fb = mFramebuffers[size_t(light.layer)];
        glBindFramebuffer(GL_FRAMEBUFFER, fb.id());
        // Clear this map's square only (clears ignore the viewport but not the scissor):
        // the other maps of the layer stay. Lookups never leave the square, so no stale
        // depth is read. Encoded depth clears to all ones, which every packing decodes as
        // >= 1 (far). A layer whose every map is drawn again is cleared whole, once.
        LayerClear& clear = mLayerClears[size_t(light.layer)];
        if (clear != LayerClear::Done) {
            const bool square = clear == LayerClear::Squares;
            if (square) {
                glEnable(GL_SCISSOR_TEST);
                glScissor(light.origin.x, light.origin.y, light.mapSize, light.mapSize);
            } else {
                clear = LayerClear::Done;
            }
            fb.clearDepth(one);
            if (colour) {
                const float white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
                fb.clearColour(white);
            }
            if (square) glDisable(GL_SCISSOR_TEST);
        }
        drawCasters(scene, plan, light, options, variant, 1, [&] { gl::uniform(1, m[0]); });
        if (mEdgesOn) {
            mEdges.draw(scene, plan, light, m[0]);
            scene.bind();
        }
    } else {
        // Only this light's six faces are cleared; other cubes keep their maps. Without
        // texture clears (ES), through the faces' framebuffers, which that path always has.
        if (gl::activeCaps().clearTexture) {
            mCubes.clearCubeDepth(light.layer, one);
        } else {
            for (int face = 0; face < 6; ++face)
                mCubeFaceFramebuffers[size_t(6 * light.layer + face)].clearDepth(one);
        }
        // Faces the view does not look up are cleared and left empty.
        std::array<GLint, 6> faces{};
        GLsizei count = 0;
        for (int face = 0; face < 6; ++face) {
            if (light.frame.drawsFace(face)) faces[size_t(count++)] = face;
        }
        if (mLayered) {
            glBindFramebuffer(GL_FRAMEBUFFER, mCubeFramebuffer.id());
            drawCasters(scene, plan, light, options, kCube, count, [&] {
                gl::uniform(1, std::span<const glm::mat4>(m));
                gl::uniform(7, 6 * light.layer);
                gl::uniform(8, std::span<const GLint>(faces.data(), std::size_t(count)));
            });
        } else {
            for (int face : std::span(faces.data(), size_t(count))) {
                glBindFramebuffer(GL_FRAMEBUFFER,
                                  mCubeFaceFramebuffers[size_t(6 * light.layer + face)].id());
                drawCasters(scene, plan, light, options, kPlain, 1,
                            [&] { gl::uniform(1, m[size_t(face)]); });
            }
        }
    }
}

std::size_t ShadowPass::orderPasses(const std::vector<ShadowedLight>& lights) {
    mPasses.clear();
    mLayerClears.assign(mFramebuffers.size(), LayerClear::Whole);
    std::size_t count2D = 0;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        const ShadowedLight& light = lights[i];
        const bool cube = light.frame.kind == shadow::FrameKind::Cube;
        mPasses.push_back(
            {i, cube ? std::size_t(light.layer) : count2D++, cube ? -1 : light.layer});
        // A map kept from an earlier frame keeps its layer's other squares from a whole clear.
        if (!cube && !light.redraw) mLayerClears[size_t(light.layer)] = LayerClear::Squares;
    }
    std::stable_sort(mPasses.begin(), mPasses.end(),
                     [](const Pass& a, const Pass& b) { return a.layer < b.layer; });
    return count2D;
}

ShadowPassStats ShadowPass::render(const GpuScene& scene, const shadow::FramePlan& plan,
                                   const ShadowOptions& options, PassClock* clock,
                                   std::vector<PassTiming>* timings) {
    allocate(plan.layout());
    const bool edges = EdgeMaps::wanted(options) && mMaps && !isColourFormat(mMapFormat);
    if (edges) {
        mEdges.allocate(mMaps.width(), mMaps.layers());
    } else {
        mEdges.release();
    }
    mEdgesOn = edges;
    const std::vector<ShadowedLight>& lights = plan.shadowed();
    const std::size_t count2D = orderPasses(lights);
    mHeld.maps2D.resize(count2D);
    mHeld.drawn2D.resize(count2D);
    ++mHeld.frame;

    ShadowPassStats stats;
    stats.culled = plan.castersCulled();
    bool any = false;
    mDrawn.clear();
    for (const Pass& pass : mPasses) {
        const std::size_t li = pass.light, slot = pass.slot;
        const ShadowedLight& light = lights[li];
        const bool cube = light.frame.kind == shadow::FrameKind::Cube;
        if (!light.redraw) continue;  // nothing changed (or it waits): keep the map
        if (!cube) forgetOverlapping(light.key, slot);
        (cube ? mHeld.cubes : mHeld.maps2D)[slot] = light.key;
        (cube ? mHeld.drawnCubes : mHeld.drawn2D)[slot] = mHeld.frame;
        if (clock) clock->start();
        if (!any) {
            scene.bind();
            any = true;
        }
        setDepthState(options, light.depthClamp);
        glViewport(light.origin.x, light.origin.y, light.mapSize, light.mapSize);
        drawMap(scene, plan, light, options);
        mDrawn.push_back(int(li));
        ++stats.rendered;
        std::uint64_t triangles = 0;
        for (std::uint32_t k = 0; k < light.casterCount; ++k) {
            const DrawItem& item = scene.items()[plan.casters()[light.firstCaster + k]];
            triangles += std::uint64_t(item.standInIndexCount / 3) *
                         std::uint64_t(cube ? std::popcount(light.frame.faces) : 1);
        }
        stats.triangles += triangles;
        if (clock && timings) {
            timings->push_back(clock->stop(mapPassName("shadow", light), light.light, triangles));
        }
    }
    if (any) {
        glDisable(GL_POLYGON_OFFSET_FILL);
        gl::setDepthClamp(false);
        glDisable(GL_CULL_FACE);
    }
    return stats;
}

namespace {
void toGrey(const std::vector<float>& depth, int size, Image16& out, int xOffset) {
    for (int y = 0; y < size; ++y) {
        const float* row = &depth[size_t(size - 1 - y) * size];  // GL rows are bottom-up
        for (int x = 0; x < size; ++x) {
            const float d = std::clamp(row[x], 0.0f, 1.0f);
            out.pixels[size_t(y) * out.width + xOffset + x] = std::uint16_t(d * 65535.0f + 0.5f);
        }
    }
}
}  // namespace

Image16 ShadowPass::readBack(const ShadowedLight& light) const {
    const int size = light.mapSize;
    const bool cube = light.frame.kind == shadow::FrameKind::Cube;
    const bool colour = !cube && isColourFormat(mMapFormat);
    const int faces = cube ? 6 : 1;
    Image16 out;
    out.width = size * faces;
    out.height = size;
    out.pixels.resize(size_t(out.width) * out.height);
    std::vector<float> depth(size_t(size) * size);
    std::vector<std::uint8_t> encoded(colour ? depth.size() * 4 : 0);
    for (int face = 0; face < faces; ++face) {
        const gl::Texture& texture = cube ? mCubes : mMaps;
        const int layer = cube ? 6 * light.layer + face : light.layer;
        const int x = cube ? 0 : light.origin.x, y = cube ? 0 : light.origin.y;
        if (colour) {
            // Decoded on the CPU by the same scheme the shaders use (shadow/DepthPacking).
            texture.read(x, y, layer, size, size, GL_RGBA, GL_UNSIGNED_BYTE, encoded.size(),
                         encoded.data());
            for (size_t i = 0; i < depth.size(); ++i) {
                const glm::vec4 c(encoded[4 * i], encoded[4 * i + 1], encoded[4 * i + 2],
                                  encoded[4 * i + 3]);
                depth[i] = shadow::decodeDepth(mMapFormat, c / 255.0f);
            }
        } else {
            texture.read(x, y, layer, size, size, GL_DEPTH_COMPONENT, GL_FLOAT,
                         depth.size() * sizeof(float), depth.data());
        }
        toGrey(depth, size, out, face * size);
    }
    return out;
}

}  // namespace gnomon::render
