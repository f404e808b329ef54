// A small line chart as SVG, so a sweep's result is a picture, not a spreadsheet.
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
    std::vector<std::string> xTicks;  // label of each x position ("": no tick there)
    std::vector<double> x;            // positions (already log2 where the axis is)
    std::vector<PlotSeries> series;
};

std::string toSvg(const Plot& plot);

}  // namespace gnomon::cli
