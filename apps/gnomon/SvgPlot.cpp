#include "SvgPlot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gnomon::cli {

namespace {
std::string num(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.1f", v);
    return b;
}
std::string escape(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '<')
            out += "&lt;";
        else if (c == '>')
            out += "&gt;";
        else if (c == '&')
            out += "&amp;";
        else
            out += c;
    }
    return out;
}
// A round step giving about five ticks up to `top`.
double tickStep(double top) {
    const double raw = top / 5.0;
    const double p = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0, 10.0}) {
        if (m * p >= raw) return m * p;
    }
    return 10.0 * p;
}
}  // namespace

std::string toSvg(const Plot& plot) {
    const double w = 760, h = 420, left = 70, right = 230, top = 40, bottom = 60;
    const double pw = w - left - right, ph = h - top - bottom;
    double ymax = 0.0;
    for (const PlotSeries& s : plot.series)
        for (double v : s.y)
            ymax = std::max(ymax, v);
    const double step = tickStep(ymax > 0.0 ? ymax * 1.05 : 1.0);
    ymax = std::ceil((ymax > 0.0 ? ymax * 1.05 : 1.0) / step) * step;
    const double xmin = plot.x.empty() ? 0.0 : *std::min_element(plot.x.begin(), plot.x.end());
    const double xmax = plot.x.empty() ? 1.0 : *std::max_element(plot.x.begin(), plot.x.end());
    const double xspan = xmax > xmin ? xmax - xmin : 1.0;
    auto px = [&](double x) { return left + (plot.x.size() > 1 ? (x - xmin) / xspan : 0.5) * pw; };
    auto py = [&](double y) { return top + ph - y / ymax * ph; };
    static const char* const kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e",
                                           "#9467bd", "#7f7f7f", "#17becf", "#8c564b"};
    std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + num(w) +
                      "\" height=\"" + num(h) + "\" font-family=\"sans-serif\" font-size=\"12\">\n";
    svg += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    svg += "<text x=\"" + num(left) + "\" y=\"24\" font-size=\"15\">" + escape(plot.title) +
           "</text>\n";
    for (double y = 0.0; y <= ymax + 1e-9; y += step) {
        svg += "<line x1=\"" + num(left) + "\" x2=\"" + num(left + pw) + "\" y1=\"" + num(py(y)) +
               "\" y2=\"" + num(py(y)) + "\" stroke=\"#ddd\"/>\n";
        char label[32];
        std::snprintf(label, sizeof label, "%g", y);
        svg += "<text x=\"" + num(left - 8) + "\" y=\"" + num(py(y) + 4) +
               "\" text-anchor=\"end\">" + label + "</text>\n";
    }
    for (std::size_t i = 0; i < plot.x.size(); ++i) {
        if (plot.xTicks[i].empty()) continue;
        svg += "<line x1=\"" + num(px(plot.x[i])) + "\" x2=\"" + num(px(plot.x[i])) + "\" y1=\"" +
               num(top) + "\" y2=\"" + num(top + ph) + "\" stroke=\"#eee\"/>\n";
        svg += "<text x=\"" + num(px(plot.x[i])) + "\" y=\"" + num(top + ph + 18) +
               "\" text-anchor=\"middle\">" + escape(plot.xTicks[i]) + "</text>\n";
    }
    svg += "<rect x=\"" + num(left) + "\" y=\"" + num(top) + "\" width=\"" + num(pw) +
           "\" height=\"" + num(ph) + "\" fill=\"none\" stroke=\"#333\"/>\n";
    svg += "<text x=\"" + num(left + pw / 2) + "\" y=\"" + num(h - 16) +
           "\" text-anchor=\"middle\">" + escape(plot.xLabel) + "</text>\n";
    svg += "<text transform=\"translate(18," + num(top + ph / 2) +
           ") rotate(-90)\" text-anchor=\"middle\">" + escape(plot.yLabel) + "</text>\n";
    for (std::size_t s = 0; s < plot.series.size(); ++s) {
        const char* colour = kColours[s % 8];
        std::string points;
        for (std::size_t i = 0; i < plot.x.size() && i < plot.series[s].y.size(); ++i) {
            const double v = plot.series[s].y[i];
            if (v < 0.0) continue;
            points += num(px(plot.x[i])) + "," + num(py(v)) + " ";
            svg += "<circle cx=\"" + num(px(plot.x[i])) + "\" cy=\"" + num(py(v)) +
                   "\" r=\"3\" fill=\"" + colour + "\"/>\n";
        }
        if (!plot.series[s].markersOnly) {
            svg += "<polyline fill=\"none\" stroke-width=\"2\" stroke=\"" + std::string(colour) +
                   "\" points=\"" + points + "\"/>\n";
        }
        const double ly = top + 14 + 20 * double(s);
        svg += "<line x1=\"" + num(left + pw + 14) + "\" x2=\"" + num(left + pw + 36) + "\" y1=\"" +
               num(ly - 4) + "\" y2=\"" + num(ly - 4) + "\" stroke-width=\"2\" stroke=\"" + colour +
               "\"/>\n";
        svg += "<text x=\"" + num(left + pw + 42) + "\" y=\"" + num(ly) + "\">" +
               escape(plot.series[s].name) + "</text>\n";
    }
    svg += "</svg>\n";
    return svg;
}

}  // namespace gnomon::cli
