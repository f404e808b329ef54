// Orchestrates a frame (SPEC S1): validate, sync the GPU scene, place each shadowed light's
// camera, render the shadow maps, render the main pass into an offscreen target, read back.
#include "gnomon/Renderer.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "gl/Context.h"
#include "gnomon/Error.h"
#include "render/DebugPass.h"
#include "render/GpuScene.h"
#include "render/MainPass.h"
#include "render/PassClock.h"
#include "render/ShadowPass.h"
#include "scene/SceneUtil.h"

namespace gnomon {

namespace {
#ifdef NDEBUG
constexpr bool kDebugBuild = false;
#else
constexpr bool kDebugBuild = true;
#endif

// LightData.vsPosition.w in shaders/lights.glsl.
int lightTypeCode(LightType type) {
    switch (type) {
        case LightType::Directional:
            return 0;
        case LightType::Spot:
            return 1;
        case LightType::Point:
            return 2;
        case LightType::Area:
            return 3;
    }
    return 0;
}

[[noreturn]] void invalid(const std::vector<std::string>& problems) {
    std::string message;
    for (const auto& p : problems)
        message += (message.empty() ? "" : "; ") + p;
    throw Error(ErrorKind::InvalidInput, message);
}
}  // namespace

struct Renderer::Impl {
    // First: destroyed last, after every GL object below. Empty when drawing in the caller's
    // context (ContextOptions::currentContext).
    std::optional<gl::HeadlessContext> context;
    render::GpuScene scene;
    render::ShadowPass shadowPass;
    render::MainPass mainPass;
    render::DebugPass debugPass;
    gl::Texture colour, depth;
    gl::Texture visibilityTexture;  // RG32F, a layer per light: gnomon score only
    gl::Framebuffer target;
    gl::Texture colourView;   // the colour target as RGBA8 (no sRGB decode), for display
    gl::Texture panelColour;  // drawShadowMapPanel's target
    gl::Framebuffer panelTarget;
    std::vector<render::ShadowedLight> shadowed;
    std::vector<render::GpuLight> lights;          // scene lights, then cascade records
    std::vector<render::GpuLight> cascadeRecords;  // reused every frame
    std::vector<render::GpuLight> ordered;         // reused every frame
    std::vector<int> remap;                        // scene light -> record, reused
    std::vector<std::uint8_t> hasMap;              // scene light has a map this frame
    glm::ivec4 ranges{0};                          // ends of the record kinds
    shadow::FitScene fit;                          // reused every frame
    FrameStats stats;
    bool passTiming = false;
    std::unique_ptr<render::PassClock> clock;  // made when timing is first switched on

    explicit Impl(const ContextOptions& o) : context(openContext(o)) {
        glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);  // PCF taps may cross cube faces
    }

    // Runs before any other member is made: they create GL objects.
    static std::optional<gl::HeadlessContext> openContext(const ContextOptions& o) {
        if (!o.currentContext) {
            return std::optional<gl::HeadlessContext>(std::in_place, o.debug || kDebugBuild,
                                                      o.verbose);
        }
        if (!gl::hasCurrentContext()) {
            throw Error(ErrorKind::Gl,
                        "Renderer: ContextOptions::currentContext is set but no OpenGL context "
                        "is current on this thread");
        }
        gl::requireGl45();
        if (o.debug || kDebugBuild) gl::installDebugOutput();
        return std::nullopt;
    }

    void makeCurrent() {
        if (context) context->makeCurrent();
    }

    void ensureTarget(int width, int height, OutputEncoding encoding) {
        const GLenum format = encoding == OutputEncoding::Srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8;
        if (target && colour.width() == width && colour.height() == height &&
            colour.format() == format) {
            return;
        }
        colour = gl::Texture::plain2D("output colour", format, width, height);
        colourView = gl::Texture::view2D("output colour as stored", colour, GL_RGBA8);
        depth = gl::Texture::plain2D("output depth", GL_DEPTH_COMPONENT24, width, height);
        target = gl::Framebuffer("output");
        glNamedFramebufferTexture(target.id(), GL_COLOR_ATTACHMENT0, colour.id(), 0);
        glNamedFramebufferTexture(target.id(), GL_DEPTH_ATTACHMENT, depth.id(), 0);
        target.checkComplete();
    }

    // Every light's record for the main pass, and the light cameras of those that cast
    // shadows this frame (map layers are assigned by the shadow pass, see finishLights).
    void planLights(const Scene& s, const RenderOptions& options, const glm::mat4& viewFromWorld) {
        shadowed.clear();
        lights.clear();
        cascadeRecords.clear();
        const float aspect = float(options.width) / float(options.height);
        // What fitted light cameras look at: the items' boxes and the view (SPEC S8).
        fit.casters.clear();
        fit.receivers.clear();
        for (const render::DrawItem& item : scene.items()) {
            if (item.indexCount == 0) continue;
            if (render::castsShadow(item, options.shadow)) fit.casters.push_back(item.bounds);
            if (item.receives) fit.receivers.push_back(item.bounds);
        }
        fit.viewKnown = true;
        fit.viewClipFromWorld = shadow::clipFromView(s.camera, aspect) * viewFromWorld;
        for (size_t i = 0; i < s.lights.size(); ++i) {
            const Light& light = s.lights[i];
            render::GpuLight g;
            const glm::vec3 direction = glm::length(light.direction) > 0.0f
                                            ? glm::normalize(light.direction)
                                            : glm::vec3(0, -1, 0);
            g.vsPosition = glm::vec4(glm::vec3(viewFromWorld * glm::vec4(light.position, 1.0f)),
                                     float(lightTypeCode(light.type)));
            // w: 0 off; on: the range (point, spot), or -1 for none.
            const bool ranged = light.range > 0.0f &&
                                (light.type == LightType::Point || light.type == LightType::Spot);
            g.vsDirection =
                glm::vec4(glm::mat3(viewFromWorld) * direction, !lightIsOn(s, options, i) ? 0.0f
                                                                : ranged ? light.range
                                                                         : -1.0f);
            g.colour = glm::vec4(light.colour * light.intensity, -1.0f);
            g.attenuation = {light.attenuation.constant, light.attenuation.linear,
                             light.attenuation.quadratic,
                             std::cos(glm::radians(light.outerConeDegrees))};
            g.shadow.x = std::cos(glm::radians(light.innerConeDegrees));
            g.soft.w = float(i);  // the scene's index, for the visibility pass
            const int mapSize =
                options.shadow.mapSize > 0 ? options.shadow.mapSize : light.shadowMapSize;
            const bool shadowing =
                options.shadow.enabled && light.castsShadows && g.vsDirection.w != 0.0f;
            g.shadowBias.x = options.shadow.biasConstant;
            g.shadowBias.y = options.shadow.normalOffset;
            if (shadowing && light.type == LightType::Directional &&
                light.shadowCamera.policy == ShadowCameraPolicy::Fit &&
                options.shadow.cascades > 1 && !scene.bounds().empty()) {
                planCascades(s, options, i, direction, mapSize, aspect, g);
            } else if (shadowing) {
                const shadow::LightCameraFrame frame =
                    shadow::lightCameraFrame(light, s.camera, fit, mapSize);
                if (frame.valid) {
                    fillShadowRecord(g, frame, light, options.shadow);
                    g.soft.w = float(i);
                    if (frame.kind == shadow::FrameKind::Cube) {
                        g.wsPosition = glm::vec4(light.position, frame.near);
                    }
                    shadowed.push_back({int(i), mapSize, frame,
                                        light.shadowCamera.policy == ShadowCameraPolicy::Fit, 0,
                                        int(i), -1});
                }
            }
            lights.push_back(g);
        }
        orderLights(s.lights.size());
    }

    // Orders the records by kind for the main pass's loops (shaders/lights.glsl): lights
    // that are off are dropped; unshadowed, single-map, cube and cascaded lights follow each
    // other, then the cascade records. Indices into the records (shadowed lights, cascaded
    // lights' first cascade) are rewritten to match.
    void orderLights(std::size_t sceneLights) {
        ordered.clear();
        remap.assign(sceneLights, -1);
        hasMap.assign(sceneLights, 0);
        for (const render::ShadowedLight& sl : shadowed)
            hasMap[std::size_t(sl.light)] = 1;
        // (Map layers are assigned later, by the shadow pass: colour.w says nothing yet.)
        auto kindOf = [&](std::size_t i) {
            const render::GpuLight& g = lights[i];
            if (g.vsDirection.w == 0.0f) return -1;
            if (!hasMap[i]) return 0;
            return g.shadow.z == 2.0f ? 2 : g.shadow.z == 3.0f ? 3 : 1;
        };
        for (int kind = 0; kind < 4; ++kind) {
            for (std::size_t i = 0; i < sceneLights; ++i) {
                if (kindOf(i) != kind) continue;
                remap[i] = int(ordered.size());
                ordered.push_back(lights[i]);
            }
            ranges[kind] = int(ordered.size());
        }
        const int base = int(ordered.size());
        for (render::GpuLight& g : ordered) {
            if (g.shadow.z == 3.0f) g.wsPosition.x += float(base) - float(sceneLights);
        }
        ordered.insert(ordered.end(), cascadeRecords.begin(), cascadeRecords.end());
        for (render::ShadowedLight& sl : shadowed) {
            sl.record = sl.cascade >= 0 ? sl.record - int(sceneLights) + base
                                        : remap[std::size_t(sl.record)];
        }
        lights.swap(ordered);
    }

    // The map-related fields of a light record for a single-frustum or cube frame.
    static void fillShadowRecord(render::GpuLight& g, const shadow::LightCameraFrame& frame,
                                 const Light& light, const ShadowOptions& options) {
        g.shadow.y = frame.texelWorldSize;
        g.wsPosition.w = frame.near;
        g.shadowBias.w = frame.far;
        // PCSS's emitter: a disc of lightRadius at the light (area lights: on their plane,
        // which may lie off the map's depth origin), or the directional light's angle.
        if (light.type == LightType::Directional) {
            g.soft = glm::vec4(std::tan(glm::radians(options.lightAngle)), 1.0f, 0.0f, 0.0f);
        } else {
            const glm::vec3 eye = glm::vec3(glm::inverse(frame.lightFromWorld)[3]);
            const float offset =
                light.type == LightType::Area && glm::length(light.direction) > 0.0f
                    ? glm::dot(eye - light.position, glm::normalize(light.direction))
                    : 0.0f;
            g.soft = glm::vec4(options.lightRadius, 0.0f, offset, 0.0f);
        }
        g.shadow.z = frame.kind == shadow::FrameKind::Cube           ? 2.0f
                     : frame.kind == shadow::FrameKind::Orthographic ? 1.0f
                                                                     : 0.0f;
        if (frame.kind != shadow::FrameKind::Cube) {
            g.textureFromWorld = shadow::textureFromClip() * frame.clipFromWorld();
        }
    }

    // SPEC S22: `cascades` stabilised maps along the view, from the camera's near plane to
    // where the scene ends (or the camera's far plane).
    void planCascades(const Scene& s, const RenderOptions& options, size_t lightIndex,
                      const glm::vec3& direction, int mapSize, float aspect, render::GpuLight& g) {
        const Camera& cam = s.camera;
        const glm::vec3 forward = glm::normalize(cam.centre - cam.eye);
        float farthest = cam.near * 2.0f;
        for (const glm::vec3& c : scene.bounds().corners()) {
            farthest = std::max(farthest, glm::dot(c - cam.eye, forward));
        }
        const float far = std::min(cam.far, farthest);
        const int count = options.shadow.cascades;
        const std::vector<float> splits =
            shadow::cascadeSplits(cam.near, far, count, options.shadow.cascadeLambda);
        const int first = int(s.lights.size() + cascadeRecords.size());
        g.shadow.z = 3.0f;
        g.colour.w = 0.0f;  // has shadows; the maps are the cascade records'
        g.wsPosition = glm::vec4(float(first), float(count), options.shadow.cascadeBlend, 0.0f);
        for (int k = 0; k < count; ++k) {
            const shadow::LightCameraFrame frame =
                shadow::cascadeFrame(direction, cam, aspect, splits[size_t(k)],
                                     splits[size_t(k) + 1], scene.bounds(), mapSize);
            render::GpuLight c = g;
            fillShadowRecord(c, frame, s.lights[lightIndex], options.shadow);
            c.soft.w = float(lightIndex);
            c.attenuation.x = splits[size_t(k) + 1];
            c.wsPosition = glm::vec4(0.0f, 0.0f, 0.0f, frame.near);
            cascadeRecords.push_back(c);
            shadowed.push_back({int(lightIndex), mapSize, frame, true, 0, first + k, k});
        }
    }

    // The visibility pass's layers as ShadowVisibility's interleaved, top-down values. With
    // the shadow-map debug view nothing was drawn: every pixel reads lit.
    void readVisibility(const Scene& s, const RenderOptions& options, ShadowVisibility& out) {
        out.width = options.width;
        out.height = options.height;
        out.lights = int(s.lights.size());
        const std::size_t pixels = std::size_t(out.width) * std::size_t(out.height);
        out.visibility.assign(pixels * std::size_t(out.lights), 1.0f);
        out.texelWorld.assign(pixels * std::size_t(out.lights), 0.0f);
        if (out.lights == 0 || options.debugView == DebugView::ShadowMap) return;
        std::vector<float> layers(pixels * 2 * std::size_t(out.lights));
        glGetTextureImage(visibilityTexture.id(), 0, GL_RG, GL_FLOAT,
                          GLsizei(layers.size() * sizeof(float)), layers.data());
        for (int l = 0; l < out.lights; ++l) {
            for (int y = 0; y < out.height; ++y) {
                const float* src =
                    &layers[(std::size_t(l) * pixels +
                             std::size_t(out.height - 1 - y) * std::size_t(out.width)) *
                            2];
                for (int x = 0; x < out.width; ++x) {
                    const std::size_t cell =
                        (std::size_t(y) * std::size_t(out.width) + std::size_t(x)) *
                            std::size_t(out.lights) +
                        std::size_t(l);
                    out.visibility[cell] = src[2 * x];
                    out.texelWorld[cell] = src[2 * x + 1];
                }
            }
        }
    }

    // After the shadow pass placed each map: layer, and the map's share of its array.
    void finishLights() {
        for (const render::ShadowedLight& sl : shadowed) {
            render::GpuLight& g = lights[size_t(sl.record)];
            const bool cube = sl.frame.kind == shadow::FrameKind::Cube;
            const int arraySize = cube ? shadowPass.cubes().width() : shadowPass.mapArraySize();
            g.colour.w = float(sl.layer);
            g.shadow.w = float(sl.mapSize) / float(arraySize);
            g.shadowBias.z = 1.0f / float(arraySize);
        }
    }

    // The frame in `target`, not read back.
    void draw(const Scene& s, const RenderOptions& options, ShadowVisibility* visibility) {
        if (auto problems = options.validate(); !problems.empty()) invalid(problems);
        if (auto problems = s.validate(); !problems.empty()) invalid(problems);
        if (s.lights.size() > std::size_t(mainPass.maxLights())) {
            throw Error(ErrorKind::InvalidInput,
                        "scene '" + s.name + "' has " + std::to_string(s.lights.size()) +
                            " lights; this OpenGL driver allows at most " +
                            std::to_string(mainPass.maxLights()) + " per frame");
        }
        if (options.lightOnly >= int(s.lights.size())) {
            throw Error(ErrorKind::InvalidInput, "light-only " + std::to_string(options.lightOnly) +
                                                     ": scene '" + s.name + "' has " +
                                                     std::to_string(s.lights.size()) + " lights");
        }
        makeCurrent();
        scene.sync(s, options.time);

        const float aspect = float(options.width) / float(options.height);
        const glm::mat4 viewFromWorld = shadow::viewFromWorld(s.camera);
        planLights(s, options, viewFromWorld);
        if (lights.size() > std::size_t(mainPass.maxLights())) {
            throw Error(ErrorKind::InvalidInput,
                        "scene '" + s.name + "' needs " + std::to_string(lights.size()) +
                            " light records with its cascades; this OpenGL driver allows " +
                            std::to_string(mainPass.maxLights()));
        }

        std::vector<PassTiming> keep = std::move(stats.passes);
        keep.clear();
        stats = {};
        stats.passes = std::move(keep);  // keeps its capacity
        render::PassClock* timer = passTiming ? clock.get() : nullptr;
        const render::ShadowPassStats passStats =
            shadowPass.render(scene, shadowed, options.shadow, timer, &stats.passes);
        stats.shadowPasses = passStats.rendered;
        stats.shadowTriangles = passStats.triangles;
        stats.castersCulled = passStats.culled;
        stats.shadowMaps = int(shadowed.size());
        for (const render::DrawItem& item : scene.items())
            stats.mainTriangles += item.indexCount / 3;
        stats.shadowMapBytes = shadowed.empty() ? 0 : shadowPass.bytes();
        finishLights();

        ensureTarget(options.width, options.height, options.shading.output);
        glBindFramebuffer(GL_FRAMEBUFFER, target.id());
        glViewport(0, 0, options.width, options.height);
        const float black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
        const float far = 1.0f;
        glClearNamedFramebufferfv(target.id(), GL_COLOR, 0, black);
        glClearNamedFramebufferfv(target.id(), GL_DEPTH, 0, &far);
        render::MainPassInputs in;
        in.viewFromWorld = viewFromWorld;
        in.clipFromView = shadow::clipFromView(s.camera, aspect);
        in.ambient = s.ambient;
        in.lights = &lights;
        in.lightRanges = ranges;
        in.hasCascades = !cascadeRecords.empty();
        // Only maps made this frame: an array left from another format must not be bound.
        bool any2D = false, anyCube = false;
        for (const render::ShadowedLight& sl : shadowed) {
            (sl.frame.kind == shadow::FrameKind::Cube ? anyCube : any2D) = true;
        }
        in.shadowMaps = any2D ? &shadowPass.maps() : nullptr;
        in.shadowCubes = anyCube ? &shadowPass.cubes() : nullptr;
        if (timer) timer->start();
        if (options.debugView == DebugView::ShadowMap) {
            const int light = options.lightOnly >= 0 ? options.lightOnly
                              : shadowed.empty()     ? -1
                                                     : shadowed.front().light;
            if (!debugPass.drawMaps(shadowPass, shadowed, light, options.width, options.height)) {
                throw Error(ErrorKind::InvalidInput,
                            light < 0 ? "debug-view shadow-map: no light of scene '" + s.name +
                                            "' has a shadow map in this frame"
                                      : "debug-view shadow-map: light " + std::to_string(light) +
                                            " of scene '" + s.name +
                                            "' has no shadow map in this frame (off, not "
                                            "casting, or nothing in view to shadow)");
            }
        } else {
            const gl::Texture* visibilityTarget = nullptr;
            if (visibility) {
                const int layers = std::max<int>(1, int(s.lights.size()));
                if (!visibilityTexture || visibilityTexture.width() != options.width ||
                    visibilityTexture.height() != options.height ||
                    visibilityTexture.layers() != layers) {
                    visibilityTexture = gl::Texture::array2D("shadow visibility", GL_RG32F,
                                                             options.width, options.height, layers);
                }
                const float unset[2] = {1.0f, 0.0f};
                glClearTexImage(visibilityTexture.id(), 0, GL_RG, GL_FLOAT, unset);
                visibilityTarget = &visibilityTexture;
            }
            // sRGB output: the target is SRGB8_ALPHA8, so writes (and blending) encode.
            const bool srgb = options.shading.output == OutputEncoding::Srgb;
            if (srgb) glEnable(GL_FRAMEBUFFER_SRGB);
            mainPass.render(scene, in, options, visibilityTarget);
            if (options.debugView == DebugView::LightFrusta) {
                debugPass.drawFrusta(shadowed, in.clipFromView * viewFromWorld);
            }
            if (srgb) glDisable(GL_FRAMEBUFFER_SRGB);
        }

        if (timer) stats.passes.push_back(timer->stop("main", -1, stats.mainTriangles));
    }

    GLuint drawPanel(int light, int width, int height) {
        makeCurrent();
        if (!panelTarget || panelColour.width() != width || panelColour.height() != height) {
            panelColour = gl::Texture::plain2D("shadow map panel", GL_RGBA8, width, height);
            glTextureParameteri(panelColour.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTextureParameteri(panelColour.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
            panelTarget = gl::Framebuffer("shadow map panel");
            glNamedFramebufferTexture(panelTarget.id(), GL_COLOR_ATTACHMENT0, panelColour.id(), 0);
            panelTarget.checkComplete();
        }
        glBindFramebuffer(GL_FRAMEBUFFER, panelTarget.id());
        glViewport(0, 0, width, height);
        const float black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
        glClearNamedFramebufferfv(panelTarget.id(), GL_COLOR, 0, black);
        return debugPass.drawMaps(shadowPass, shadowed, light, width, height) ? panelColour.id()
                                                                              : 0;
    }

    Image render(const Scene& s, const RenderOptions& options, ShadowVisibility* visibility) {
        draw(s, options, visibility);
        render::PassClock* timer = passTiming ? clock.get() : nullptr;
        if (timer) timer->start();
        glBindFramebuffer(GL_FRAMEBUFFER, target.id());
        Image image(options.width, options.height, 4);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, options.width, options.height, GL_RGBA, GL_UNSIGNED_BYTE,
                     image.pixels.data());
        // GL rows run bottom-up; images top-down.
        const size_t row = size_t(options.width) * 4;
        for (int y = 0; y < options.height / 2; ++y) {
            std::swap_ranges(image.at(0, y), image.at(0, y) + row,
                             image.at(0, options.height - 1 - y));
        }
        if (timer) stats.passes.push_back(timer->stop("read-back", -1, 0));
        if (visibility) readVisibility(s, options, *visibility);
        return image;
    }
};

Renderer::Renderer(const ContextOptions& options) : mImpl(std::make_unique<Impl>(options)) {}
Renderer::~Renderer() = default;

Image Renderer::render(const Scene& scene, const RenderOptions& options) {
    return mImpl->render(scene, options, nullptr);
}

Image Renderer::render(const Scene& scene, const RenderOptions& options,
                       ShadowVisibility& visibility) {
    return mImpl->render(scene, options, &visibility);
}

void Renderer::draw(const Scene& scene, const RenderOptions& options) {
    mImpl->draw(scene, options, nullptr);
}

unsigned Renderer::frameTexture() const {
    return mImpl->colourView.id();
}

unsigned Renderer::drawShadowMapPanel(int light, int width, int height) {
    if (width < 1 || height < 1 || width > 16384 || height > 16384) {
        throw Error(ErrorKind::InvalidInput, "shadow map panel size must be in 1..16384, got " +
                                                 std::to_string(width) + "x" +
                                                 std::to_string(height));
    }
    return mImpl->drawPanel(light, width, height);
}

std::vector<ShadowMapImage> Renderer::shadowMaps() {
    mImpl->makeCurrent();
    std::vector<ShadowMapImage> out;
    for (const render::ShadowedLight& sl : mImpl->shadowed) {
        out.push_back({sl.light, sl.cascade, mImpl->shadowPass.readBack(sl)});
    }
    return out;
}

FrameStats Renderer::lastFrameStats() const {
    return mImpl->stats;
}

void Renderer::setPassTiming(bool on) {
    mImpl->makeCurrent();
    if (on && !mImpl->clock) mImpl->clock = std::make_unique<render::PassClock>();
    mImpl->passTiming = on;
}

void Renderer::invalidateShadowMaps() {
    mImpl->shadowPass.invalidate();
}

double Renderer::measureBareDepthPass(int size) {
    if (size < 1 || size > 16384) {
        throw Error(ErrorKind::InvalidInput,
                    "bare depth pass size must be in 1..16384, got " + std::to_string(size));
    }
    mImpl->makeCurrent();
    for (const render::ShadowedLight& sl : mImpl->shadowed) {
        if (sl.frame.kind == shadow::FrameKind::Cube) continue;
        return mImpl->shadowPass.bareDepthPass(mImpl->scene, sl.frame.clipFromWorld(), size);
    }
    return -1.0;
}

std::string Renderer::glInfo() const {
    mImpl->makeCurrent();
    return gl::currentGlInfo();
}

}  // namespace gnomon
