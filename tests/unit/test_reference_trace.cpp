// The reference traced in slices (truth::ReferenceTrace, what a web page's score and tune
// step through between frames) is traceReference's bit for bit, however the rows are split
// and on however many threads; each slice traces at least one row and stops taking rows at
// its deadline; a cancelled trace throws.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>

#include "gnomon/Error.h"
#include "gnomon/Scene.h"
#include "truth/Reference.h"

namespace gnomon {
namespace {

using Clock = std::chrono::steady_clock;

// mixed-lights (every kind of light) small, with soft rays and contacts: every field a
// reference has is filled.
struct Case {
    Scene scene = builtinScene("mixed-lights");
    RenderOptions options;
    truth::ReferenceOptions ro;
    Case() {
        options = scene.options;
        options.width = 40;
        options.height = 30;
        ro.softSamples = 8;
        ro.contactRange = 0.5f;
    }
};

void expectIdentical(const truth::Reference& a, const truth::Reference& b) {
    EXPECT_EQ(a.width, b.width);
    EXPECT_EQ(a.height, b.height);
    EXPECT_EQ(a.lights, b.lights);
    EXPECT_EQ(a.object, b.object);
    EXPECT_EQ(a.pixelWorld, b.pixelWorld);
    EXPECT_EQ(a.surfacePoint, b.surfacePoint);
    EXPECT_EQ(a.surfaceNormal, b.surfaceNormal);
    EXPECT_EQ(a.applies, b.applies);
    EXPECT_EQ(a.hard, b.hard);
    EXPECT_EQ(a.tint, b.tint);
    EXPECT_EQ(a.lightCosine, b.lightCosine);
    EXPECT_EQ(a.soft, b.soft);
    EXPECT_EQ(a.nearOccluder, b.nearOccluder);
    EXPECT_TRUE(b.rays != nullptr);
}

TEST(ReferenceTrace, OneRowPerSliceIsTheWholeTrace) {
    const Case c;
    const truth::Reference whole = truth::traceReference(c.scene, c.options, c.ro);
    ASSERT_GT(whole.lights, 4);
    long shadowed = 0, soft = 0;
    for (std::size_t i = 0; i < whole.hard.size(); ++i) {
        shadowed += whole.applies[i] && whole.hard[i] == 0.0f;
        soft += whole.applies[i] && whole.soft[i] > 0.0f && whole.soft[i] < 1.0f;
    }
    EXPECT_GT(shadowed, 50);  // a case with shadows to get wrong
    EXPECT_GT(soft, 5);

    truth::ReferenceOptions one = c.ro;
    one.threads = 1;
    truth::ReferenceTrace trace(c.scene, c.options, one);
    EXPECT_EQ(trace.rows(), 30);
    EXPECT_EQ(trace.rowsDone(), 0);
    EXPECT_THROW(trace.finish(), Error);  // nothing traced yet
    // A deadline already past: every slice takes its one row and no more.
    for (int row = 1; row <= 30; ++row) {
        const bool done = trace.traceRows(Clock::now());
        EXPECT_EQ(trace.rowsDone(), row);
        EXPECT_EQ(done, row == 30);
    }
    expectIdentical(whole, trace.finish());
}

TEST(ReferenceTrace, SlicesOnThreadsAreTheWholeTrace) {
    const Case c;
    const truth::Reference whole = truth::traceReference(c.scene, c.options, c.ro);
    truth::ReferenceOptions two = c.ro;
    two.threads = 2;
    truth::ReferenceTrace trace(c.scene, c.options, two);
    int slices = 0, before = 0;
    while (!trace.traceRows(Clock::now())) {
        ++slices;
        EXPECT_GE(trace.rowsDone() - before, 1);
        EXPECT_LE(trace.rowsDone() - before, 2);  // a row per thread at most
        before = trace.rowsDone();
    }
    EXPECT_GE(slices, 14);
    EXPECT_EQ(trace.rowsDone(), 30);
    expectIdentical(whole, trace.finish());
    // And one slice with time to spare traces every row.
    truth::ReferenceTrace once(c.scene, c.options, two);
    EXPECT_TRUE(once.traceRows(Clock::now() + std::chrono::hours(1)));
    expectIdentical(whole, once.finish());
}

TEST(ReferenceTrace, CancelledTraceThrows) {
    const Case c;
    std::atomic<bool> cancel{false};
    std::atomic<int> counted{0};
    truth::ReferenceOptions ro = c.ro;
    ro.threads = 1;
    ro.cancel = &cancel;
    ro.rowsDone = &counted;
    truth::ReferenceTrace trace(c.scene, c.options, ro);
    EXPECT_FALSE(trace.traceRows(Clock::now()));
    EXPECT_EQ(counted.load(), 1);
    cancel = true;
    EXPECT_THROW(trace.traceRows(Clock::now()), Error);
    EXPECT_EQ(trace.rowsDone(), 1);  // no row taken once cancelled
    EXPECT_EQ(counted.load(), 1);
}

}  // namespace
}  // namespace gnomon
