#include "SvgPlot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gnomon::cli {

namespace {

constexpr double kFont = 12, kTitleFont = 15;
constexpr double kPlotWidth = 460, kPlotHeight = 320, kTop = 40, kBottom = 60;
constexpr double kGap = 8;  // the least room between two labels

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
// The box of a text whose baseline starts at x, y ("start"), or is centred on x ("middle"),
// or ends at x ("end").
TextBox boxOf(const std::string& text, double fontSize, double x, double y, char anchor) {
    const double w = textWidth(text, fontSize);
    const double x0 = anchor == 's' ? x : anchor == 'm' ? x - w / 2 : x - w;
    return {x0, y - fontSize, x0 + w, y + 0.25 * fontSize};
}
TextBox grown(const TextBox& b, double by) {
    return {b.x0 - by / 2, b.y0 - by / 2, b.x1 + by / 2, b.y1 + by / 2};
}
// A round step (1, 2 or 5 times a power of ten) giving at most `count` steps over `span`.
double roundStep(double span, int count) {
    const double raw = span / std::max(count, 1);
    const double p = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0}) {
        if (m * p >= raw * (1.0 - 1e-9)) return m * p;
    }
    return 10.0 * p;
}
// The value as a tick label: as many decimals as the step needs, none for whole steps.
std::string tickLabel(double v, double step) {
    const int decimals = std::max(0, int(-std::floor(std::log10(step) + 1e-9)));
    char b[32];
    std::snprintf(b, sizeof b, "%.*f", decimals, std::abs(v) < step * 1e-6 ? 0.0 : v);
    return b;
}
// The y axis's title, which says when the axis is logarithmic.
std::string yTitle(const Plot& plot, const PlotLayout& l) {
    return plot.yLabel + (l.logY ? " (log scale)" : "");
}
// Keeps, left to right (or top to bottom), each tick whose label clears the last one kept.
void dropOverlapping(std::vector<PlotTick>& ticks) {
    std::vector<PlotTick> kept;
    for (PlotTick& t : ticks) {
        if (kept.empty() || !grown(kept.back().box, kGap).overlaps(t.box)) kept.push_back(t);
    }
    ticks = std::move(kept);
}

// The y axis: its range, linear or logarithmic, and its ticks (not yet placed).
void yAxis(const Plot& plot, PlotLayout& l) {
    double largest = 0.0, smallest = 0.0;  // smallest above 0
    for (const PlotSeries& s : plot.series) {
        for (double v : s.y) {
            largest = std::max(largest, v);
            if (v > 0.0 && (smallest == 0.0 || v < smallest)) smallest = v;
        }
    }
    // Labels at least two lines apart: they cannot touch.
    const int most = std::min(6, int(kPlotHeight / (2 * kFont)));
    l.logY = plot.logYWhenWide && smallest > 0.0 && largest / smallest > 10.0;
    if (l.logY) {
        const int lo = int(std::floor(std::log10(smallest))),
                  hi = int(std::ceil(std::log10(largest)));
        l.yMin = std::pow(10.0, lo);
        l.yMax = std::pow(10.0, hi);
        const int stride = (hi - lo + most - 1) / most;
        for (int e = lo; e <= hi; e += stride) {
            const double decade = std::pow(10.0, e);
            char b[32];
            for (double m : {1.0, 2.0, 5.0}) {
                // Between decades only where there are few of them.
                if (m > 1.0 && (hi - lo > 2 || e == hi)) continue;
                std::snprintf(b, sizeof b, "%g", m * decade);
                l.yTicks.push_back({m * decade, 0, b, {}});
            }
        }
        return;
    }
    const double top = largest > 0.0 ? largest * 1.05 : 1.0;
    const double step = roundStep(top, most);
    l.yMin = 0.0;
    l.yMax = std::ceil(top / step - 1e-9) * step;
    for (int i = 0; i * step <= l.yMax + step * 1e-9; ++i)
        l.yTicks.push_back({i * step, 0, tickLabel(i * step, step), {}});
}

// The x axis: the given labels where they fit, or round steps whose labels fit.
void xAxis(const Plot& plot, PlotLayout& l) {
    const double baseline = l.top + l.plotHeight + 18;
    auto place = [&](PlotTick& t) {
        t.at = l.xOf(t.value);
        t.box = boxOf(t.label, kFont, t.at, baseline, 'm');
    };
    if (!plot.xTicks.empty()) {
        for (std::size_t i = 0; i < plot.x.size() && i < plot.xTicks.size(); ++i) {
            if (plot.xTicks[i].empty()) continue;
            l.xTicks.push_back({plot.x[i], 0, plot.xTicks[i], {}});
            place(l.xTicks.back());
        }
        std::sort(l.xTicks.begin(), l.xTicks.end(),
                  [](const PlotTick& a, const PlotTick& b) { return a.at < b.at; });
        dropOverlapping(l.xTicks);
        return;
    }
    // Fewer and fewer steps until no two labels touch.
    for (int count = int(l.plotWidth / 40); count >= 1; --count) {
        const double step = roundStep(l.xMax - l.xMin, count);
        l.xTicks.clear();
        for (double v = std::ceil(l.xMin / step - 1e-9) * step; v <= l.xMax + step * 1e-9;
             v += step) {
            l.xTicks.push_back({v, 0, tickLabel(v, step), {}});
            place(l.xTicks.back());
        }
        bool clear = true;
        for (std::size_t i = 1; i < l.xTicks.size(); ++i)
            clear = clear && !grown(l.xTicks[i - 1].box, kGap).overlaps(l.xTicks[i].box);
        if (clear) return;
    }
    dropOverlapping(l.xTicks);
}

}  // namespace

double textWidth(const std::string& text, double fontSize) {
    std::size_t letters = 0;
    for (unsigned char c : text)
        letters += (c & 0xC0) != 0x80;  // UTF-8: count the first byte of each letter
    return 0.62 * fontSize * double(letters);
}

double PlotLayout::xOf(double x) const {
    return left + (xMax > xMin ? (x - xMin) / (xMax - xMin) : 0.5) * plotWidth;
}
double PlotLayout::yOf(double y) const {
    const double f = logY ? (std::log10(std::max(y, yMin)) - std::log10(yMin)) /
                                (std::log10(yMax) - std::log10(yMin))
                          : (y - yMin) / (yMax - yMin);
    return top + plotHeight - f * plotHeight;
}

PlotLayout layOut(const Plot& plot) {
    PlotLayout l;
    l.top = kTop;
    l.plotWidth = kPlotWidth;
    l.plotHeight = kPlotHeight;
    l.height = kTop + kPlotHeight + kBottom;
    yAxis(plot, l);
    // Room on the left for the widest tick label and the axis title beside it.
    double widest = 0.0;
    for (const PlotTick& t : l.yTicks)
        widest = std::max(widest, textWidth(t.label, kFont));
    l.left = std::max(70.0, 34.0 + widest + kGap);
    for (PlotTick& t : l.yTicks) {
        t.at = l.yOf(t.value);
        t.box = boxOf(t.label, kFont, l.left - kGap, t.at + 4, 'e');
    }
    if (!plot.x.empty()) {
        l.xMin = *std::min_element(plot.x.begin(), plot.x.end());
        l.xMax = *std::max_element(plot.x.begin(), plot.x.end());
    }
    if (plot.xTicks.empty()) {  // numbered: a margin either side, some width for one value
        const double pad =
            l.xMax > l.xMin ? 0.05 * (l.xMax - l.xMin) : std::max(0.1 * std::abs(l.xMax), 0.5);
        l.xMin -= pad;
        l.xMax += pad;
    }
    xAxis(plot, l);
    l.title = boxOf(plot.title, kTitleFont, l.left, 24, 's');
    l.xLabel = boxOf(plot.xLabel, kFont, l.left + l.plotWidth / 2, l.height - 16, 'm');
    // Drawn turned a quarter left about (18, middle): its length runs up the page.
    const double yLength = textWidth(yTitle(plot, l), kFont);
    const double middle = l.top + l.plotHeight / 2;
    l.yLabel = {18 - kFont, middle - yLength / 2, 18 + 0.25 * kFont, middle + yLength / 2};
    // The legend beside the plot; the picture as wide as what it holds.
    double right = l.left + l.plotWidth + 30;
    for (std::size_t s = 0; s < plot.series.size(); ++s) {
        const double x = l.left + l.plotWidth + 14, y = l.top + 14 + 20 * double(s);
        TextBox b = boxOf(plot.series[s].name, kFont, x + 28, y, 's');
        b.x0 = x;
        l.legend.push_back(b);
        right = std::max(right, b.x1 + 10);
    }
    for (const TextBox& b : {l.title, l.xLabel})
        right = std::max(right, b.x1 + 10);
    if (!l.xTicks.empty()) right = std::max(right, l.xTicks.back().box.x1 + 10);
    l.width = std::ceil(right);
    return l;
}

std::string toSvg(const Plot& plot) {
    const PlotLayout l = layOut(plot);
    const double pw = l.plotWidth, ph = l.plotHeight, left = l.left, top = l.top;
    static const char* const kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e",
                                           "#9467bd", "#7f7f7f", "#17becf", "#8c564b"};
    std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + num(l.width) +
                      "\" height=\"" + num(l.height) + "\" viewBox=\"0 0 " + num(l.width) + " " +
                      num(l.height) + "\" font-family=\"sans-serif\" font-size=\"12\">\n";
    svg += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    svg += "<text x=\"" + num(l.title.x0) + "\" y=\"24\" font-size=\"15\">" + escape(plot.title) +
           "</text>\n";
    for (const PlotTick& t : l.yTicks) {
        svg += "<line x1=\"" + num(left) + "\" x2=\"" + num(left + pw) + "\" y1=\"" + num(t.at) +
               "\" y2=\"" + num(t.at) + "\" stroke=\"#ddd\"/>\n";
        svg += "<text x=\"" + num(left - kGap) + "\" y=\"" + num(t.at + 4) +
               "\" text-anchor=\"end\">" + escape(t.label) + "</text>\n";
    }
    for (const PlotTick& t : l.xTicks) {
        svg += "<line x1=\"" + num(t.at) + "\" x2=\"" + num(t.at) + "\" y1=\"" + num(top) +
               "\" y2=\"" + num(top + ph) + "\" stroke=\"#eee\"/>\n";
        svg += "<text x=\"" + num(t.at) + "\" y=\"" + num(top + ph + 18) +
               "\" text-anchor=\"middle\">" + escape(t.label) + "</text>\n";
    }
    svg += "<rect x=\"" + num(left) + "\" y=\"" + num(top) + "\" width=\"" + num(pw) +
           "\" height=\"" + num(ph) + "\" fill=\"none\" stroke=\"#333\"/>\n";
    svg += "<text x=\"" + num(left + pw / 2) + "\" y=\"" + num(l.height - 16) +
           "\" text-anchor=\"middle\">" + escape(plot.xLabel) + "</text>\n";
    svg += "<text transform=\"translate(18," + num(top + ph / 2) +
           ") rotate(-90)\" text-anchor=\"middle\">" + escape(yTitle(plot, l)) + "</text>\n";
    for (std::size_t s = 0; s < plot.series.size(); ++s) {
        const char* colour = kColours[s % 8];
        std::string points;
        for (std::size_t i = 0; i < plot.x.size() && i < plot.series[s].y.size(); ++i) {
            const double v = plot.series[s].y[i];
            if (v < 0.0) continue;
            points += num(l.xOf(plot.x[i])) + "," + num(l.yOf(v)) + " ";
            svg += "<circle cx=\"" + num(l.xOf(plot.x[i])) + "\" cy=\"" + num(l.yOf(v)) +
                   "\" r=\"3\" fill=\"" + colour + "\"/>\n";
        }
        if (!plot.series[s].markersOnly) {
            svg += "<polyline fill=\"none\" stroke-width=\"2\" stroke=\"" + std::string(colour) +
                   "\" points=\"" + points + "\"/>\n";
        }
        const TextBox& b = l.legend[s];
        const double ly = b.y1 - 0.25 * kFont;  // the name's baseline
        svg += "<line x1=\"" + num(b.x0) + "\" x2=\"" + num(b.x0 + 22) + "\" y1=\"" + num(ly - 4) +
               "\" y2=\"" + num(ly - 4) + "\" stroke-width=\"2\" stroke=\"" + colour + "\"/>\n";
        svg += "<text x=\"" + num(b.x0 + 28) + "\" y=\"" + num(ly) + "\">" +
               escape(plot.series[s].name) + "</text>\n";
    }
    svg += "</svg>\n";
    return svg;
}

}  // namespace gnomon::cli
