// Renders the book triangle through the installed public API only. Usage: gnomon_consumer
// OUT.png. Exit 0: rendered and written; 77: no usable OpenGL (skipped); 1: failure.
#include <cstdio>
#include <cstring>
#include <exception>
#include <memory>

#include <gnomon/gnomon.h>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s OUT.png\n", argv[0]);
        return 1;
    }
    try {
        const gnomon::Scene scene = gnomon::builtinScene("book-triangle");
        gnomon::RenderOptions options = scene.options;
        options.width = 64;
        options.height = 64;

        std::unique_ptr<gnomon::Renderer> renderer;
        try {
            renderer = std::make_unique<gnomon::Renderer>();
        } catch (const gnomon::Error& e) {
            if (e.kind() != gnomon::ErrorKind::Gl) throw;
            std::printf("skipped: %s\n", e.what());
            return 77;
        }
        const gnomon::Image image = renderer->render(scene, options);

        if (image.width != 64 || image.height != 64 || image.channels < 1 ||
            image.pixels.size() != std::size_t(64) * 64 * image.channels) {
            std::fprintf(stderr, "unexpected image %dx%d with %d channels, %zu bytes\n",
                         image.width, image.height, image.channels, image.pixels.size());
            return 1;
        }
        bool varied = false;
        for (int y = 0; y < image.height && !varied; ++y) {
            for (int x = 0; x < image.width && !varied; ++x) {
                varied = std::memcmp(image.at(x, y), image.at(0, 0), image.channels) != 0;
            }
        }
        if (!varied) {
            std::fprintf(stderr, "the rendered image is a single colour\n");
            return 1;
        }
        gnomon::writePng(argv[1], image);
        std::printf("gnomon %s: rendered %s at %dx%d to %s\n", gnomon::version(),
                    scene.name.c_str(), image.width, image.height, argv[1]);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
}
