// The charts tune (front.svg) and bench --sweep (sweep.svg) write: no two tick labels
// overlap, whatever the values; the legend, the title and every label lie inside the picture
// its viewBox declares; the error axis turns logarithmic when the values span more than a
// decade, and only then.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "SvgPlot.h"

namespace gnomon::cli {
namespace {

bool inside(const TextBox& b, const PlotLayout& l) {
    return b.x0 >= 0.0 && b.y0 >= 0.0 && b.x1 <= l.width && b.y1 <= l.height;
}
void expectApart(const std::vector<PlotTick>& ticks) {
    for (std::size_t i = 0; i < ticks.size(); ++i) {
        for (std::size_t j = i + 1; j < ticks.size(); ++j) {
            EXPECT_FALSE(ticks[i].box.overlaps(ticks[j].box))
                << "'" << ticks[i].label << "' overlaps '" << ticks[j].label << "'";
        }
    }
}
void expectInside(const PlotLayout& l) {
    EXPECT_TRUE(inside(l.title, l)) << "title";
    EXPECT_TRUE(inside(l.xLabel, l)) << "x label";
    EXPECT_TRUE(inside(l.yLabel, l)) << "y label";
    for (const PlotTick& t : l.xTicks)
        EXPECT_TRUE(inside(t.box, l)) << t.label;
    for (const PlotTick& t : l.yTicks)
        EXPECT_TRUE(inside(t.box, l)) << t.label;
    for (const TextBox& b : l.legend)
        EXPECT_TRUE(inside(b, l)) << "legend " << b.x0 << ".." << b.x1 << " of " << l.width;
}

// What tune draws: trials crowded at nearly the same frame time, errors over three decades.
Plot tuneLike() {
    Plot p;
    p.title = "gnomon tune: tutorial-room (budget 12 ms; 14 of 15 trials shown)";
    p.xLabel = "frame ms";
    p.yLabel = "misclassified + away from edges, %";
    p.logYWhenWide = true;
    PlotSeries all{"every trial", {}, true}, front{"front", {}, false};
    const double ms[] = {10.1, 10.15, 10.2, 10.22, 10.3, 10.31, 10.9,
                         11.0, 11.02, 11.4, 11.9,  12.0, 12.3,  13.7};
    const double error[] = {2.5,  1.9, 0.8,  0.9,   0.3, 0.31,  0.05,
                            0.04, 0.2, 0.01, 0.009, 0.4, 0.008, 0.006};
    for (int i = 0; i < 14; ++i) {
        p.x.push_back(ms[i]);
        all.y.push_back(error[i]);
        front.y.push_back(i % 3 == 0 ? error[i] : -1.0);
    }
    p.series = {all, front};
    return p;
}

// What bench --sweep draws: a label per swept value, the longest legend names.
Plot sweepLike(int values) {
    Plot p;
    p.title = "gnomon bench: tutorial-room, sweep of map-size (1280x720, median of 50 frames)";
    p.xLabel = "map-size";
    p.yLabel = "milliseconds";
    p.series = {{"frame", {}},
                {"shadow passes", {}},
                {"main pass", {}},
                {"shadows off (reference)", {}},
                {"bare depth draw, 1 map (reference)", {}}};
    for (int i = 0; i < values; ++i) {
        p.xTicks.push_back(std::to_string(256 * (i + 1)));
        p.x.push_back(double(i));
        for (PlotSeries& s : p.series)
            s.y.push_back(3.0 + i);
    }
    return p;
}

TEST(SvgPlot, TuneTicksNeverOverlapAndTheErrorAxisIsLogarithmic) {
    const PlotLayout l = layOut(tuneLike());
    EXPECT_TRUE(l.logY) << "errors from 0.006 to 2.5 span more than a decade";
    ASSERT_GE(l.xTicks.size(), 3u);
    ASSERT_GE(l.yTicks.size(), 3u);
    expectApart(l.xTicks);
    expectApart(l.yTicks);
    expectInside(l);
    // Decades: 0.001 below the smallest error up to 10 above the largest, in order.
    EXPECT_DOUBLE_EQ(l.yMin, 0.001);
    EXPECT_DOUBLE_EQ(l.yMax, 10.0);
    for (std::size_t i = 1; i < l.yTicks.size(); ++i)
        EXPECT_LT(l.yTicks[i].at, l.yTicks[i - 1].at) << "larger values higher up";
    // Equal ratios, equal distances: 0.01 to 0.1 as far as 0.1 to 1.
    EXPECT_NEAR(l.yOf(0.01) - l.yOf(0.1), l.yOf(0.1) - l.yOf(1.0), 1e-9);
    // The numbered x axis spans every trial.
    EXPECT_LE(l.xMin, 10.1);
    EXPECT_GE(l.xMax, 13.7);
}

TEST(SvgPlot, LinearAxisWithinADecade) {
    Plot p = tuneLike();
    for (double& v : p.series[0].y)
        v = 0.5 + v / 10.0;  // 0.5006 .. 0.75
    p.series[1].y.assign(p.series[1].y.size(), -1.0);
    const PlotLayout l = layOut(p);
    EXPECT_FALSE(l.logY);
    EXPECT_EQ(l.yMin, 0.0);
    expectApart(l.yTicks);
    // Not asked for: linear however wide the values.
    p = tuneLike();
    p.logYWhenWide = false;
    EXPECT_FALSE(layOut(p).logY);
}

TEST(SvgPlot, CrowdedLabelsAreThinnedNotOverlapped) {
    const PlotLayout few = layOut(sweepLike(4));
    EXPECT_EQ(few.xTicks.size(), 4u) << "room for all four";
    for (int values : {4, 20, 60}) {
        const PlotLayout l = layOut(sweepLike(values));
        SCOPED_TRACE(values);
        ASSERT_FALSE(l.xTicks.empty());
        EXPECT_EQ(l.xTicks.front().label, "256") << "the first value keeps its label";
        expectApart(l.xTicks);
        expectInside(l);
    }
}

TEST(SvgPlot, LegendFitsInsideTheViewBox) {
    const Plot p = sweepLike(5);
    const PlotLayout l = layOut(p);
    ASSERT_EQ(l.legend.size(), p.series.size());
    expectInside(l);
    for (std::size_t i = 1; i < l.legend.size(); ++i)
        EXPECT_FALSE(l.legend[i - 1].overlaps(l.legend[i]));
    // The picture is no wider than its longest name needs, and says how big it is.
    EXPECT_LT(l.width, l.legend.back().x1 + 40);
    char viewBox[64];
    std::snprintf(viewBox, sizeof viewBox, "viewBox=\"0 0 %.1f %.1f\"", l.width, l.height);
    EXPECT_NE(toSvg(p).find(viewBox), std::string::npos) << viewBox;
}

TEST(SvgPlot, TextWidthCountsLettersNotBytes) {
    EXPECT_DOUBLE_EQ(textWidth("10²", 12), textWidth("100", 12));
    EXPECT_GT(textWidth("bare depth draw, 1 map (reference)", 12), 200.0);
}

}  // namespace
}  // namespace gnomon::cli
