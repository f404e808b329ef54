// Orchestrates a frame: validate, sync the GPU scene, sample the view's depth where fitted
// lights need it, plan the frame (shadow/FramePlan), render the shadow maps, render the main
// pass into an offscreen target, read back.
#include "gnomon/Renderer.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <optional>

#include "gl/Caps.h"
#include "gl/Context.h"
#include "gl/State.h"
#include "gnomon/Error.h"
#include "render/DebugPass.h"
#include "render/GpuScene.h"
#include "render/MainPass.h"
#include "render/PassClock.h"
#include "render/RayScene.h"
#include "render/RelativeScene.h"
#include "render/ShadowPasses.h"
#include "render/TiledLights.h"
#include "render/ViewDepthPass.h"
#include "render/VisibilityTarget.h"
#include "scene/SceneUtil.h"
#include "shadow/FramePlan.h"

namespace gnomon {

namespace {
#ifdef NDEBUG
constexpr bool kDebugBuild = false;
#else
constexpr bool kDebugBuild = true;
#endif

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
    gl::ContextCaps caps;  // read next, before the passes that follow them
    render::GpuScene scene;
    render::ShadowPasses shadows;  // depth maps, moments, transmittance
    render::MainPass mainPass;
    render::TiledLights tiled;
    render::DebugPass debugPass;
    gl::Texture colour, depth;
    render::VisibilityTarget visibilityTarget;  // gnomon score only
    gl::Framebuffer target;
    gl::Texture colourView;   // the colour target as RGBA8 (no sRGB decode), for display
    gl::Texture panelColour;  // drawShadowMapPanel's target
    gl::Framebuffer panelTarget;
    render::ViewDepthPass viewDepth;
    shadow::FramePlan plan;
    render::RelativeScene relative;  // the scene near the origin (RelativeScene.h)
    render::RayScene rays;           // the casters' BVH for --shadow-rays
    Camera relativeFit;              // the fit camera moved as the scene is
    Camera lastCamera;               // the last frame's view and size, for mapUsage()
    int lastWidth = 1, lastHeight = 1;
    std::uint64_t validRevision = 0;  // the last Scene::revision whose content was valid
    // The last main pass drawn, for measureMainFloor() (lights: plan's records).
    std::optional<render::MainPassInputs> lastMain;
    RenderOptions lastMainOptions;
    FrameStats stats;
    bool passTiming = false;
    std::unique_ptr<render::PassClock> clock;  // made when timing is first switched on

    explicit Impl(const ContextOptions& o) : context(openContext(o)) {
        // View depth ranges, moments and score's visibility are float render targets.
        if (!caps.get().floatTargets) {
            throw Error(ErrorKind::Gl,
                        "no usable OpenGL ES: gnomon renders to float textures "
                        "(EXT_color_buffer_float), which this driver does not offer");
        }
        // PCF taps may cross cube faces (ES filters across faces always).
        if (caps.get().seamlessCubes) glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    }

    // Runs before any other member is made: they create GL objects.
    static std::optional<gl::HeadlessContext> openContext(const ContextOptions& o) {
        if (!o.currentContext) {
            return std::optional<gl::HeadlessContext>(std::in_place, o.debug || kDebugBuild,
                                                      o.verbose,
                                                      o.gles ? gl::Api::Gles3 : gl::Api::Gl45);
        }
        if (!gl::hasCurrentContext()) {
            throw Error(ErrorKind::Gl,
                        "Renderer: ContextOptions::currentContext is set but no OpenGL context "
                        "is current on this thread");
        }
        gl::requireUsable();
        if (o.debug || kDebugBuild) gl::installDebugOutput();
        return std::nullopt;
    }

    void makeCurrent() {
        if (context) context->makeCurrent();
        caps.activate();
    }

    void ensureTarget(int width, int height, OutputEncoding encoding) {
        const GLenum format = encoding == OutputEncoding::Srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8;
        if (target && colour.width() == width && colour.height() == height &&
            colour.format() == format) {
            return;
        }
        colour = gl::Texture::plain2D("output colour", format, width, height);
        // Without texture views (ES), frameTexture() hands out the target itself.
        if (caps.get().textureViews) {
            colourView = gl::Texture::view2D("output colour as stored", colour, GL_RGBA8);
        }
        // The view depth pass's format, so its depth can be copied in (bindClearedTarget).
        depth = gl::Texture::plain2D("output depth", GL_DEPTH_COMPONENT32F, width, height);
        // Read by texelFetch (RayMarks): ES counts a depth texture filtered LINEAR without
        // comparison as incomplete.
        depth.setParameter(GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        depth.setParameter(GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        target = gl::Framebuffer("output");
        target.attach(GL_COLOR_ATTACHMENT0, colour);
        target.attach(GL_DEPTH_ATTACHMENT, depth);
        target.checkComplete();
    }

    // The frame's target bound and cleared (black, far), the viewport on it. With
    // `withViewDepth`, the depth is the view depth pass's instead (MainPassInputs::depthReady).
    void bindClearedTarget(int width, int height, bool withViewDepth = false) {
        glBindFramebuffer(GL_FRAMEBUFFER, target.id());
        glViewport(0, 0, width, height);
        const float black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
        const float far = 1.0f;
        target.clearColour(black);
        glDepthMask(GL_TRUE);  // clears and blits obey the mask
        if (withViewDepth) {
            target.blitDepthFrom(viewDepth.target(), width, height);
        } else {
            target.clearDepth(far);
        }
    }

    // Bad input stops here, in words: the options, the scene, what the driver can hold.
    void check(const Scene& s, const RenderOptions& options) {
        if (auto problems = options.validate(); !problems.empty()) invalid(problems);
        // The content check reads every vertex: only for a revision not yet found valid.
        if (s.revision.value() != validRevision) {
            if (auto problems = s.validateContent(); !problems.empty()) invalid(problems);
            validRevision = s.revision.value();
        }
        if (auto problems = s.validateLightsAndCamera(); !problems.empty()) invalid(problems);
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
    }

    // The frame in `target`, not read back; `fitCamera`: the maps' camera (null: the scene's).
    void draw(const Scene& world, const RenderOptions& options, ShadowVisibility* visibility,
              const Camera* fitCamera = nullptr) {
        check(world, options);
        makeCurrent();
        // Everything from here on works in coordinates near the scene (RelativeScene.h).
        const Scene& s = relative.of(world, options.time);
        if (fitCamera) relativeFit = relative.moved(*fitCamera);
        drawRelative(s, options, visibility, fitCamera ? &relativeFit : nullptr);
    }

    void drawRelative(const Scene& s, const RenderOptions& options, ShadowVisibility* visibility,
                      const Camera* fitCamera) {
        scene.sync(s, options.time, options.shadow.casterDetail);
        if (render::EdgeMaps::wanted(options.shadow))
            shadows.depth().edges().sync(s, scene, options.time);

        const float aspect = float(options.width) / float(options.height);
        // The view's own depth (the view depth pass, the main pass, what is read back from
        // them) spans what is drawn; the lights' fits keep the scene's camera, and so does
        // the light-frusta debug view, whose volumes reach past the scene.
        const Camera view = options.debugView == DebugView::LightFrusta
                                ? s.camera
                                : shadow::depthFitted(s.camera, scene.bounds());
        const glm::mat4 viewFromWorld = gnomon::viewFromWorld(view);
        std::vector<PassTiming> keep = std::move(stats.passes);
        keep.clear();
        stats = {};
        stats.passes = std::move(keep);  // keeps its capacity
        render::PassClock* timer = passTiming ? clock.get() : nullptr;
        const shadow::ViewSamples* samples = nullptr;
        const bool contact = options.shadow.enabled && options.shadow.contactLength > 0.0f;
        if (shadow::FramePlan::wantsViewSamples(s, options) || contact ||
            render::TiledLights::wantsDepth(s, options)) {
            if (timer) timer->start();
            samples = &viewDepth.sample(scene, fitCamera ? *fitCamera : view, options.width,
                                        options.height);
            if (timer) {
                stats.passes.push_back(timer->stop("view depth", -1, viewDepth.trianglesDrawn()));
            }
        }
        // Drawn for the tiles alone, the samples do not fit the lights.
        const bool fitSamples = shadow::FramePlan::wantsViewSamples(s, options) || contact;
        plan.setRecordLimit(mainPass.maxLights());
        plan.setMapBudget(std::size_t(1) << 30, gl::activeCaps().maxArrayLayers);
        plan.plan(s, options, scene.planScene(), fitSamples ? samples : nullptr, fitCamera,
                  shadows.depth().held());
        if (fitCamera) {
            // The samples were the fit camera's view: contact shadows need the drawn one's,
            // and the tiles are not worth it for this rare frame.
            if (contact) viewDepth.sample(scene, view, options.width, options.height);
            samples = nullptr;
        }
        lastCamera = view;
        lastWidth = options.width;
        lastHeight = options.height;
        if (plan.records().size() > std::size_t(mainPass.maxLights())) {
            throw Error(ErrorKind::InvalidInput,
                        "scene '" + s.name + "' needs " + std::to_string(plan.records().size()) +
                            " light records with its cascades; this OpenGL driver allows " +
                            std::to_string(mainPass.maxLights()));
        }

        render::MainPassInputs in;
        shadows.draw(scene, plan, options, timer, stats, in);
        stats.mapBudgetNote = plan.budgetNote();
        for (const render::DrawItem& item : scene.items())
            stats.mainTriangles += item.indexCount / 3;

        ensureTarget(options.width, options.height, options.shading.output);
        // The view depth pass, when drawn for this very view, spares the main pass its
        // overdraw (not under the shadow-map debug view, which draws no scene).
        in.depthReady = options.shading.depthPrepass && options.debugView != DebugView::ShadowMap &&
                        viewDepth.holds(scene, view, options.width, options.height);
        bindClearedTarget(options.width, options.height, in.depthReady);
        stats.mainFromViewDepth = in.depthReady;
        in.viewFromWorld = viewFromWorld;
        in.clipFromView = gnomon::clipFromView(view, aspect);
        in.pixelRays = render::pixelRayCamera(view, options.width, options.height);
        const glm::mat4 fitView = fitCamera ? gnomon::viewFromWorld(*fitCamera) : viewFromWorld;
        in.cascadeDepth = -glm::vec4(fitView[0][2], fitView[1][2], fitView[2][2], fitView[3][2]);
        in.ambient = s.ambient;
        in.lights = &plan.records();
        // Screen tiles with fewer lights, where that is exact: an unlit surface or the
        // shadowed-factor rule darkens by a light's shadow whatever its falloff.
        // The view's depth bounds each tile's volume, when blended surfaces (not in it) do
        // not lie over it.
        const shadow::DepthCells cells = viewDepth.cells();
        tiled.setOrderCapacity(mainPass.orderCapacity());
        tiled.plan(
            plan.records(), plan.ranges(), in.viewFromWorld, in.clipFromView, options.width,
            options.height, stats.mainTriangles,
            !fitCamera && options.shading.shadowedRule != ShadowedRule::Factor && !scene.hasUnlit()
                ? options.shading.lightTiles
                : LightTiles::Off,
            samples && !scene.hasBlended() ? &cells : nullptr);
        in.tiled = &tiled;
        stats.lightTiles = int(tiled.tiles().size());
        stats.lightLists = int(tiled.lists().texels.size());
        in.hasCascades = plan.hasCascades();
        in.pointFaces = plan.hasPointFaces();
        in.singleMapKind = plan.singleMapKind();
        in.constantFalloff = plan.constantFalloff();
        in.viewDepth = contact ? &viewDepth.depth() : nullptr;
        in.rays = rays.forFrame(s, options, scene, stats.shadowRayBuilds);
        in.targetColour = &colour;
        in.targetDepth = &depth;
        if (timer) timer->start();
        drawMain(s, options, in, visibility != nullptr);
        if (timer) stats.passes.push_back(timer->stop("main", -1, stats.mainTriangles));
    }

    // The main pass (or a debug view instead) into the cleared target; with `scored`, each
    // light's visibility per pixel too.
    void drawMain(const Scene& s, const RenderOptions& options, const render::MainPassInputs& in,
                  bool scored) {
        const std::vector<render::ShadowedLight>& shadowed = plan.shadowed();
        if (options.debugView == DebugView::ShadowMap) {
            const int light = options.lightOnly >= 0 ? options.lightOnly
                              : shadowed.empty()     ? -1
                                                     : shadowed.front().light;
            if (!debugPass.drawMaps(shadows.depth(), shadowed, light, options.width,
                                    options.height)) {
                throw Error(ErrorKind::InvalidInput,
                            light < 0 ? "debug-view shadow-map: no light of scene '" + s.name +
                                            "' has a shadow map in this frame"
                                      : "debug-view shadow-map: light " + std::to_string(light) +
                                            " of scene '" + s.name +
                                            "' has no shadow map in this frame (off, not "
                                            "casting, or nothing in view to shadow)");
            }
        } else {
            if (scored) {
                visibilityTarget.clear(options.width, options.height, int(s.lights.size()),
                                       in.transmittance != nullptr, depth);
            }
            // sRGB output: the target is SRGB8_ALPHA8, so writes (and blending) encode.
            const bool srgb = options.shading.output == OutputEncoding::Srgb;
            if (srgb) gl::setSrgbWrites(true);
            mainPass.render(scene, in, options, scored ? &visibilityTarget : nullptr);
            stats.shadowRayPasses = mainPass.rayPasses();
            lastMain = in;
            lastMainOptions = options;
            if (options.debugView == DebugView::LightFrusta) {
                debugPass.drawFrusta(shadowed, in.clipFromView * in.viewFromWorld);
            }
            if (srgb) gl::setSrgbWrites(false);
        }
    }

    GlTexture drawPanel(int light, int width, int height) {
        makeCurrent();
        // The maps first: drawing any left out binds their targets.
        const render::ShadowPass& maps = shadows.shownDepth(scene, plan);
        if (!panelTarget || panelColour.width() != width || panelColour.height() != height) {
            panelColour = gl::Texture::plain2D("shadow map panel", GL_RGBA8, width, height);
            panelColour.setParameter(GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            panelColour.setParameter(GL_TEXTURE_MAG_FILTER, GL_NEAREST);
            panelTarget = gl::Framebuffer("shadow map panel");
            panelTarget.attach(GL_COLOR_ATTACHMENT0, panelColour);
            panelTarget.checkComplete();
        }
        glBindFramebuffer(GL_FRAMEBUFFER, panelTarget.id());
        glViewport(0, 0, width, height);
        const float black[4] = {0.0f, 0.0f, 0.0f, 1.0f};
        panelTarget.clearColour(black);
        if (!debugPass.drawMaps(maps, plan.shadowed(), light, width, height)) return {};
        return {panelColour.id(), width, height};
    }

    Image render(const Scene& s, const RenderOptions& options, ShadowVisibility* visibility,
                 const Camera* fitCamera = nullptr) {
        draw(s, options, visibility, fitCamera);
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
        if (visibility) {
            visibilityTarget.read(options.width, options.height, int(s.lights.size()),
                                  options.debugView != DebugView::ShadowMap, *visibility);
        }
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

Image Renderer::render(const Scene& scene, const RenderOptions& options,
                       ShadowVisibility& visibility, const Camera& fitCamera) {
    return mImpl->render(scene, options, &visibility, &fitCamera);
}

void Renderer::draw(const Scene& scene, const RenderOptions& options) {
    mImpl->draw(scene, options, nullptr);
}

GlTexture Renderer::frameTexture() const {
    const gl::Texture& t = mImpl->colourView ? mImpl->colourView : mImpl->colour;
    return {t.id(), t.width(), t.height()};
}

GlTexture Renderer::drawShadowMapPanel(int light, int width, int height) {
    if (width < 1 || height < 1 || width > 16384 || height > 16384) {
        throw Error(ErrorKind::InvalidInput, "shadow map panel size must be in 1..16384, got " +
                                                 std::to_string(width) + "x" +
                                                 std::to_string(height));
    }
    return mImpl->drawPanel(light, width, height);
}

std::vector<ShadowMapImage> Renderer::shadowMaps() {
    Impl& m = *mImpl;
    m.makeCurrent();
    std::vector<ShadowMapImage> out;
    const render::ShadowPass& maps = m.shadows.shownDepth(m.scene, m.plan);
    for (const render::ShadowedLight& sl : m.plan.shadowed())
        out.push_back({sl.light, sl.cascade, sl.face, maps.readBack(sl)});
    return out;
}

const FrameStats& Renderer::lastFrameStats() const {
    return mImpl->stats;
}

std::vector<MapUsage> Renderer::mapUsage() {
    Impl& m = *mImpl;
    std::vector<MapUsage> out;
    if (m.plan.shadowed().empty()) return out;
    m.makeCurrent();
    const shadow::ViewSamples& samples =
        m.viewDepth.sample(m.scene, m.lastCamera, m.lastWidth, m.lastHeight);
    for (const render::ShadowedLight& sl : m.plan.shadowed()) {
        out.push_back(
            {sl.light, sl.cascade, sl.mapSize,
             shadow::mapShareUsed(samples, sl.frame, sl.mapSize, sl.depthFrom, sl.depthTo),
             sl.frame.kind == shadow::FrameKind::Cube,
             sl.frame.kind == shadow::FrameKind::Cube ? std::popcount(sl.frame.faces) : 1, sl.face,
             sl.waiting});
    }
    return out;
}

void Renderer::setFollowing(bool on) {
    mImpl->plan.setFollowing(on);
}

void Renderer::setPassTiming(bool on) {
    mImpl->makeCurrent();
    if (on && !mImpl->clock) mImpl->clock = std::make_unique<render::PassClock>();
    mImpl->passTiming = on;
}

void Renderer::invalidateShadowMaps() {
    mImpl->shadows.depth().invalidate();
    mImpl->viewDepth.invalidate();
}

double Renderer::measureBareDepthPass(int size) {
    if (size < 1 || size > 16384) {
        throw Error(ErrorKind::InvalidInput,
                    "bare depth pass size must be in 1..16384, got " + std::to_string(size));
    }
    mImpl->makeCurrent();
    for (const render::ShadowedLight& sl : mImpl->plan.shadowed()) {
        if (sl.frame.kind == shadow::FrameKind::Cube) continue;
        return mImpl->shadows.depth().bareDepthPass(mImpl->scene, sl.frame.clipFromWorld(), size);
    }
    return -1.0;
}

double Renderer::measureMainFloor() {
    Impl& m = *mImpl;
    if (!m.lastMain) return -1.0;
    m.makeCurrent();
    const RenderOptions& o = m.lastMainOptions;
    render::MainPassInputs in = *m.lastMain;
    in.depthReady = in.depthReady && m.viewDepth.holds(m.scene, m.lastCamera, o.width, o.height);
    m.bindClearedTarget(o.width, o.height, in.depthReady);
    glFinish();  // the clears are not the floor's
    const auto start = std::chrono::steady_clock::now();
    m.mainPass.render(m.scene, in, o, nullptr, true);
    glFinish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

std::string Renderer::glInfo() const {
    mImpl->makeCurrent();
    return gl::currentGlInfo();
}

}  // namespace gnomon
