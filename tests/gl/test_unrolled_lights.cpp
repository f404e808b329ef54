// The main pass writes its light loops out per light for draws with few lights
// (MainPass::kMaxUnrolledLights; main.frag.glsl's UNROLLED_LIGHTS) and keeps them loops for
// more. Both must light and shadow every light alike: a frame at the limit, of every kind of
// light, must give the image it gives with one light more, too faint to show, which turns
// the loops back on.
#include <gtest/gtest.h>

#include "GlTest.h"
#include "render/MainPass.h"

namespace gnomon::test {
namespace {

// tutorial-room's sun, point and spot lights and an area light, in turn, up to `count`.
Scene lightsOfEveryKind(int count) {
    Scene s = builtinScene("tutorial-room");
    const std::vector<Light> kinds = {
        builtinScene("tutorial-room").lights.front(), builtinScene("tutorial-point").lights.front(),
        builtinScene("tutorial-spot").lights.front(), builtinScene("tutorial-area").lights.front()};
    s.lights.clear();
    for (int i = 0; i < count; ++i) {
        Light l = kinds[std::size_t(i) % kinds.size()];
        l.intensity /= float(count);
        if (l.type != LightType::Directional && l.type != LightType::Area)
            l.position.x += float(i % 3) - 1.0f;  // each its own shadow
        s.lights.push_back(l);
    }
    return s;
}

Image renderUntiled(const Scene& s) {
    RenderOptions o = s.options;
    o.width = o.height = 128;
    o.shading.lightTiles = LightTiles::Off;  // one draw, with every light
    return sharedRenderer().render(s, o);
}

TEST(UnrolledLights, WrittenOutLoopsShadeAsLoops) {
    const int limit = render::MainPass::kMaxUnrolledLights;
    const Scene written = lightsOfEveryKind(limit);
    Scene looped = written;
    Light faint = looped.lights.front();
    faint.intensity = 1e-20f;
    looped.lights.push_back(faint);
    const Image a = renderUntiled(written), b = renderUntiled(looped);
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    long differing = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i)
        differing += a.pixels[i] != b.pixels[i];
    EXPECT_EQ(differing, 0) << "written-out loops changed " << differing << " bytes";
    // Each light shadows: the frame is not lit flat (some pixel of the floor is darker than
    // its brightest by a third).
    int darkest = 3 * 255, brightest = 0;
    for (std::size_t i = 0; i + 3 < a.pixels.size(); i += 4) {
        darkest = std::min(darkest, luminance(&a.pixels[i]));
        brightest = std::max(brightest, luminance(&a.pixels[i]));
    }
    EXPECT_LT(3 * darkest, 2 * brightest);
}

}  // namespace
}  // namespace gnomon::test
