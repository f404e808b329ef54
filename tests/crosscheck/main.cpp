// gnomon_crosscheck SCENE [WxH]: traces SCENE (a built-in name, a model file or a scene file
// such as `scripts/quality-real.py --write-scene VIEW F` writes) with gnomon's reference and
// with the independent caster (IndependentCaster.h) and prints how far they agree. Exits 1 on
// a bad argument or scene, 0 otherwise: the numbers are for a reader (and
// scripts/crosscheck-real.py) to judge.
#include <cstdio>
#include <exception>
#include <string>

#include "IndependentCaster.h"
#include "gnomon/Error.h"
#include "gnomon/SceneFile.h"

int main(int argc, char** argv) {
    if (argc < 2 || argc > 3) {
        std::fprintf(stderr, "usage: gnomon_crosscheck SCENE [WxH]\n");
        return 1;
    }
    try {
        const std::string path = argv[1];
        const bool file = path.size() > 5 && path.substr(path.size() - 5) == ".json";
        const gnomon::Scene scene = file ? gnomon::loadSceneFile(path) : gnomon::loadScene(path);
        gnomon::RenderOptions options = gnomon::presetOptions(scene, gnomon::Preset::Default);
        if (argc == 3 && std::sscanf(argv[2], "%dx%d", &options.width, &options.height) != 2) {
            std::fprintf(stderr, "gnomon_crosscheck: size '%s' is not WxH\n", argv[2]);
            return 1;
        }
        if (options.width < 1 || options.height < 1 || options.width > 4096 ||
            options.height > 4096) {
            std::fprintf(stderr, "gnomon_crosscheck: size must be 1x1 to 4096x4096\n");
            return 1;
        }
        const gnomon::truth::Reference reference =
            gnomon::truth::traceReference(scene, options, {});
        const auto agreement = gnomon::crosscheck::compareWithReference(scene, options, reference);
        std::printf("%s %dx%d: %s\n", path.c_str(), options.width, options.height,
                    gnomon::crosscheck::describe(agreement).c_str());
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "gnomon_crosscheck: %s\n", e.what());
        return 1;
    }
}
