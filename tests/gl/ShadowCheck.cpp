#include "ShadowCheck.h"

#include <gtest/gtest.h>

#include "GeometryShadows.h"
#include "GlTest.h"

namespace gnomon::test {
namespace {
// On failure: the render, the shadows-off render and the oracle's classes (red shadowed,
// green lit, grey unknown, black background) go to the output folder.
void writeDiagnostics(const std::string& name, const Image& on, const Image& off,
                      const GeometryShadows& truth) {
    Image classes(truth.width, truth.height, 3);
    for (size_t i = 0; i < truth.classes.size(); ++i) {
        static const std::uint8_t kColours[4][3] = {
            {90, 90, 90}, {255, 0, 0}, {0, 200, 0}, {0, 0, 0}};
        const auto* c = kColours[int(truth.classes[i])];
        std::copy(c, c + 3, &classes.pixels[i * 3]);
    }
    const std::string base = outputDir() + "/" + name;
    writePng(base + ".on.png", on);
    writePng(base + ".off.png", off);
    writePng(base + ".classes.png", classes);
}

}  // namespace

void expectShadowsMatchGeometry(const Scene& scene, RenderOptions options) {
    options.width = options.height = 256;
    RenderOptions off = options;
    off.shadow.enabled = false;
    const Image on = sharedRenderer().render(scene, options);
    const Image plain = sharedRenderer().render(scene, off);
    const GeometryShadows truth = classifyPixels(scene, options, 2);

    int shadowed = 0, darker = 0, lit = 0, unchanged = 0;
    std::string failures;
    for (int y = 0; y < truth.height; ++y) {
        for (int x = 0; x < truth.width; ++x) {
            const PixelClass c = truth.classes[size_t(y) * truth.width + x];
            const int a = luminance(on.at(x, y)), b = luminance(plain.at(x, y));
            if (c == PixelClass::Shadowed) {
                ++shadowed;
                // Shadowed: darker by at least 6 levels of R+G+B (the oracle only calls a
                // pixel shadowed where the light adds 15 or more).
                if (a <= b - 6) {
                    ++darker;
                } else if (failures.size() < 400) {
                    failures += " shadow expected at (" + std::to_string(x) + "," +
                                std::to_string(y) + ") on=" + std::to_string(a) +
                                " off=" + std::to_string(b) + ";";
                }
            } else if (c == PixelClass::Lit) {
                ++lit;
                bool same = true;
                for (int k = 0; k < 3; ++k)
                    same &= std::abs(on.at(x, y)[k] - plain.at(x, y)[k]) <= 2;
                if (same) {
                    ++unchanged;
                } else if (failures.size() < 400) {
                    failures += " lit pixel changed at (" + std::to_string(x) + "," +
                                std::to_string(y) + ") on=" + std::to_string(a) +
                                " off=" + std::to_string(b) + ";";
                }
            }
        }
    }
    // Enough decided pixels that the test means something.
    EXPECT_GE(shadowed, 40) << "too few robustly shadowed pixels to judge";
    EXPECT_GE(lit, 400) << "too few robustly lit pixels to judge";
    EXPECT_EQ(darker, shadowed) << failures;
    // A lit pixel may darken only where a filter's footprint reaches under a caster's foot
    // (PCF compares the receiver's plane there, and the plane runs into the caster): single
    // pixels along contact lines, at most 1 in 2000 of the lit ones.
    const int allowed = lit / 2000;
    EXPECT_GE(unchanged, lit - allowed) << failures;
    if (shadowed < 40 || lit < 400 || darker != shadowed || unchanged < lit - allowed) {
        std::string name = scene.name + "-" + toString(options.shadow.filter);
        writeDiagnostics(name, on, plain, truth);
        ADD_FAILURE() << "diagnostic images: " << outputDir() << "/" << name << ".*.png";
    }
}

}  // namespace gnomon::test
