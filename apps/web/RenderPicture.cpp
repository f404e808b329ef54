#include "RenderPicture.h"

#include <emscripten/html5_webgl.h>

#include <chrono>
#include <memory>

#include "gl/Context.h"
#include "gnomon/Error.h"
#include "gnomon/Renderer.h"

namespace gnomon::web {
namespace {

// The context and the renderer, made at the first picture and kept: programs, maps and the
// scene's buffers stay on the GPU between pictures.
Renderer& renderer() {
    static std::unique_ptr<Renderer> made;
    if (made) return *made;
    EmscriptenWebGLContextAttributes a;
    emscripten_webgl_init_context_attributes(&a);
    a.majorVersion = 2;
    a.minorVersion = 0;
    a.alpha = a.depth = a.stencil = a.antialias = false;
    const EMSCRIPTEN_WEBGL_CONTEXT_HANDLE context = emscripten_webgl_create_context("#gl", &a);
    if (context <= 0) {
        throw Error(ErrorKind::Gl, "this browser gives the page no WebGL2 context");
    }
    emscripten_webgl_make_context_current(context);
    gl::enableWebGlExtensions();
    ContextOptions options;
    options.currentContext = true;
    made = std::make_unique<Renderer>(options);
    return *made;
}

}  // namespace

Image renderPicture(const Scene& scene, const RenderOptions& options) {
    return renderer().render(scene, options);
}

ScoreResult scorePicture(const Scene& scene, const RenderOptions& options) {
    ScoreOptions so;
    so.threads = 1;  // no threads without cross-origin isolation
    return score(renderer(), scene, options, so);
}

std::vector<double> benchPicture(const Scene& scene, const RenderOptions& options, int warmup,
                                 int frames) {
    Renderer& r = renderer();
    std::vector<double> ms;
    for (int i = 0; i < warmup + frames; ++i) {
        r.invalidateShadowMaps();
        const auto start = std::chrono::steady_clock::now();
        r.render(scene, options);
        const auto stop = std::chrono::steady_clock::now();
        if (i >= warmup)
            ms.push_back(std::chrono::duration<double, std::milli>(stop - start).count());
    }
    return ms;
}

}  // namespace gnomon::web
