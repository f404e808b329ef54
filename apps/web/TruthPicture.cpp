// The reference, traced once, turned into a shaded picture of one light (TruthPicture.h).
#include "TruthPicture.h"

#include <algorithm>
#include <cmath>

#include "scene/SceneUtil.h"
#include "truth/Reference.h"

namespace gnomon::web {
namespace {

constexpr float kUnlit = 0.25f;  // the share of its colour a surface keeps without the light
const glm::vec3 kBackground{0.02f, 0.02f, 0.03f};  // linear, where the view ray meets nothing

std::uint8_t srgb8(float linear) {
    const float v = std::clamp(linear, 0.0f, 1.0f);
    const float encoded = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
    return std::uint8_t(std::lround(encoded * 255.0f));
}

}  // namespace

int pictureLight(const Scene& scene, const RenderOptions& options) {
    if (scene.lights.empty()) return -1;
    if (options.lightOnly >= 0) return options.lightOnly;
    for (std::size_t l = 0; l < scene.lights.size(); ++l)
        if (scene.lights[l].castsShadows && lightIsOn(scene, options, l)) return int(l);
    return 0;
}

Image truthPicture(const Scene& scene, const RenderOptions& options, truth::TracerKind tracer) {
    truth::ReferenceOptions ro;
    ro.threads = 1;
    ro.tracer = tracer;
    // Only the light shown is traced (the scene's others would cost rays and show nothing).
    const int light = pictureLight(scene, options);
    RenderOptions traced = options;
    if (light >= 0 && lightIsOn(scene, options, std::size_t(light))) traced.lightOnly = light;
    const truth::Reference ref = truth::traceReference(scene, traced, ro);
    Image image(ref.width, ref.height, 4);
    for (int y = 0; y < ref.height; ++y) {
        for (int x = 0; x < ref.width; ++x) {
            const int object = ref.object[std::size_t(y) * std::size_t(ref.width) + std::size_t(x)];
            glm::vec3 colour = kBackground;
            if (object >= 0) {
                const Object& o = scene.objects[std::size_t(object)];
                float lit = 0.0f;
                if (light >= 0) {
                    const std::size_t cell = ref.at(x, y, light);
                    if (ref.applies[cell]) lit = ref.hard[cell] * ref.lightCosine[cell];
                }
                colour = scene.materials[o.material].baseColour * (kUnlit + (1.0f - kUnlit) * lit);
            }
            std::uint8_t* p = image.at(x, y);
            p[0] = srgb8(colour.r);
            p[1] = srgb8(colour.g);
            p[2] = srgb8(colour.b);
            p[3] = 255;
        }
    }
    return image;
}

}  // namespace gnomon::web
