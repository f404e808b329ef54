#include "RenderPicture.h"

#include <emscripten/html5_webgl.h>

#include <memory>

#include "gnomon/Error.h"
#include "gnomon/Renderer.h"

namespace gnomon::web {
namespace {

// The extensions the renderer's WebGL2 path uses where they exist (gl::Caps finds them):
// WebGL hands an extension's features over only once it is enabled.
constexpr const char* kExtensions[] = {"EXT_color_buffer_float", "OES_texture_float_linear",
                                       "EXT_depth_clamp", "EXT_float_blend"};

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
    for (const char* name : kExtensions)
        emscripten_webgl_enable_extension(context, name);
    emscripten_webgl_enable_WEBGL_multi_draw(context);
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

}  // namespace gnomon::web
