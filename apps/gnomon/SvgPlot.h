// A small line chart as SVG, so a sweep's result is a picture, not a spreadsheet. The layout
// is worked out first (PlotLayout: every label's box, the legend's, the picture's size) so
// that no two labels overlap and nothing falls outside the picture; toSvg draws it.
#pragma once

#include <string>
#include <vector>

namespace gnomon::cli {

struct PlotSeries {
    std::string name;
    std::vector<double> y;     // one per x value; negative = missing
    bool markersOnly = false;  // points not joined (a scatter rather than a curve)
};

struct Plot {
    std::string title, xLabel, yLabel;
    // A label for each x position ("": none there), such as a sweep's values; labels that
    // would overlap the one before are left out. Empty: the x axis is numbered at round steps.
    std::vector<std::string> xTicks;
    std::vector<double> x;  // positions (already log2 where the axis is)
    std::vector<PlotSeries> series;
    // A logarithmic y axis when the values span more than a decade (largest over smallest
    // above 10), so small values are not squashed flat against the axis by large ones.
    bool logYWhenWide = false;
};

// A text's box in the picture's coordinates (y down), estimated from its length.
struct TextBox {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    bool overlaps(const TextBox& o) const {
        return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1;
    }
};

struct PlotTick {
    double value = 0;  // on the axis (log y: the value itself)
    double at = 0;     // its place in the picture: x for the x axis, y for the y axis
    std::string label;
    TextBox box;
};

struct PlotLayout {
    double width = 0, height = 0;  // the picture and its viewBox, from 0, 0
    double left = 0, top = 0, plotWidth = 0, plotHeight = 0;
    double xMin = 0, xMax = 1, yMin = 0, yMax = 1;  // what the plot area spans
    bool logY = false;
    std::vector<PlotTick> xTicks, yTicks;
    TextBox title, xLabel, yLabel;
    std::vector<TextBox> legend;  // per series: its swatch and name
    double xOf(double x) const;   // picture coordinates of a value
    double yOf(double y) const;
};

// Estimated width of `text` at `fontSize` in a sans-serif font: a little more than the
// average letter, so an estimate that leaves room is rarely too small.
double textWidth(const std::string& text, double fontSize);
PlotLayout layOut(const Plot& plot);
std::string toSvg(const Plot& plot);

}  // namespace gnomon::cli
