// The renderer on its own: this program links gnomon_render and what lies below it, not the
// lab nor the ray-traced reference (Embree), as a build without Embree (the browser's) does.
// It renders a built-in scene with and without its shadows and checks that the shadow darkens
// a good part of the picture and nothing else; exit 77 (skipped) where no OpenGL context can
// be made.
#include <cstdio>

#include "gnomon/Error.h"
#include "gnomon/Renderer.h"
#include "gnomon/Scene.h"

int main() {
    using namespace gnomon;
    try {
        Renderer renderer;
        const Scene scene = builtinScene("book-triangle");
        RenderOptions options;
        options.width = options.height = 64;
        const Image shadowed = renderer.render(scene, options);
        Scene unshadowed = scene;
        for (Light& light : unshadowed.lights)
            light.castsShadows = false;
        const Image lit = renderer.render(unshadowed, options);
        // Pixels the shadow darkens (by more than rounding) and pixels it brightens.
        int darker = 0, brighter = 0;
        for (int y = 0; y < shadowed.height; ++y) {
            for (int x = 0; x < shadowed.width; ++x) {
                const std::uint8_t *s = shadowed.at(x, y), *l = lit.at(x, y);
                const int d = (int(s[0]) + s[1] + s[2]) - (int(l[0]) + l[1] + l[2]);
                darker += d < -30;
                brighter += d > 3;
            }
        }
        // The book's triangle shadows a patch of the plane below it; shadows only take light.
        if (darker < 100 || brighter > 0) {
            std::fprintf(stderr, "render_alone: %d pixels darkened, %d brightened by shadows\n",
                         darker, brighter);
            return 1;
        }
        return 0;
    } catch (const Error& e) {
        std::fprintf(stderr, "render_alone: %s\n", e.what());
        return e.kind() == ErrorKind::Gl ? 77 : 1;
    }
}
