#include <app/ReportSvg.h>

#include <base/Text.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace fl::app::svg {

namespace {

// Every chart has a plot of kPlotW x (kH - kTop - kBottom) px and its legend to the right of the
// plot, one entry per kEntryH px; a chart grows wider for long names and taller for many entries,
// so that no legend entry is ever cut off.
constexpr int kPlotW = 520, kH = 300;
constexpr int kLeft = 70, kTop = 30, kBottom = 40;
constexpr int kEntryH = 16, kMinLegendW = 170;

std::string num(double v) {
    std::ostringstream s;
    s << std::setprecision(4) << v;
    return s.str();
}

std::string px(double v) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(1) << v;
    return s.str();
}

// A "nice" tick step (1, 2 or 5 times a power of ten) giving about `ticks` ticks over span.
double niceStep(double span, int ticks) {
    if (!(span > 0.0)) return 1.0;
    const double raw = span / ticks, p = std::pow(10.0, std::floor(std::log10(raw)));
    const double f = raw / p;
    return (f < 1.5 ? 1.0 : f < 3.5 ? 2.0 : f < 7.5 ? 5.0 : 10.0) * p;
}

// A chart's size: the plot's right edge, where the legend starts, and the whole box.
struct Box {
    int plotRight = kLeft + kPlotW;
    int width = kLeft + kPlotW + kMinLegendW;
    int height = kH;
};

// Room for a legend of `names` right of a plot ending at plotRight, in a chart at least
// `minHeight` tall. Widths are estimated at 7 px a character (11 px sans-serif averages about
// 6); the report's self-check measures the drawn text and flags an entry outside its chart.
Box boxFor(const std::vector<std::string>& names, int minHeight = kH,
           int plotRight = kLeft + kPlotW) {
    std::size_t longest = 0;
    for (const std::string& n : names) longest = std::max(longest, n.size());
    Box b;
    b.plotRight = plotRight;
    b.width = plotRight + std::max(kMinLegendW, 12 + 34 + 7 * static_cast<int>(longest) + 8);
    b.height = std::max(minHeight, kTop + 4 + kEntryH * static_cast<int>(names.size()) + 8);
    return b;
}

struct Frame {
    double x0, x1, y0, y1;           // data range
    double left, right, top, bottom; // plot area, px
    [[nodiscard]] double sx(double x) const {
        return left + (x - x0) / std::max(x1 - x0, 1e-12) * (right - left);
    }
    [[nodiscard]] double sy(double y) const {
        return bottom - (y - y0) / std::max(y1 - y0, 1e-12) * (bottom - top);
    }
};

Frame frameIn(const Box& b, double x0, double x1, double y0, double y1) {
    return {x0,    x1,
            y0,    y1,
            kLeft, static_cast<double>(b.plotRight),
            kTop,  static_cast<double>(kH - kBottom)};
}

std::string open(const std::string& title, const Box& b) {
    std::ostringstream s;
    s << "<svg class=\"chart\" xmlns=\"http://www.w3.org/2000/svg\" width=\"" << b.width
      << "\" height=\"" << b.height << "\" viewBox=\"0 0 " << b.width << " " << b.height
      << "\" data-plot-right=\"" << b.plotRight << "\" role=\"img\"><title>" << xmlEscape(title)
      << "</title><text x=\"" << kLeft << "\" y=\"18\" class=\"ct\">" << xmlEscape(title)
      << "</text>";
    return s.str();
}

// Axes with ticks; x ticks only when xTicks.
std::string axes(const Frame& f, const std::string& xLabel, const std::string& yLabel,
                 bool xTicks = true) {
    std::ostringstream s;
    s << "<g class=\"axis\"><line x1=\"" << f.left << "\" y1=\"" << f.bottom << "\" x2=\""
      << f.right << "\" y2=\"" << f.bottom << "\"/><line x1=\"" << f.left << "\" y1=\"" << f.top
      << "\" x2=\"" << f.left << "\" y2=\"" << f.bottom << "\"/>";
    const double ys = niceStep(f.y1 - f.y0, 5);
    for (double y = std::ceil(f.y0 / ys) * ys; y <= f.y1 + 1e-9 * ys; y += ys)
        s << "<line class=\"grid\" x1=\"" << f.left << "\" x2=\"" << f.right << "\" y1=\""
          << px(f.sy(y)) << "\" y2=\"" << px(f.sy(y)) << "\"/><text x=\"" << f.left - 6 << "\" y=\""
          << px(f.sy(y) + 4) << "\" text-anchor=\"end\">" << num(y) << "</text>";
    if (xTicks) {
        const double xs = std::max(1.0, niceStep(f.x1 - f.x0, 8));
        for (double x = std::ceil(f.x0 / xs) * xs; x <= f.x1 + 1e-9; x += xs)
            s << "<text x=\"" << px(f.sx(x)) << "\" y=\"" << f.bottom + 16
              << "\" text-anchor=\"middle\">" << num(x) << "</text>";
    }
    const double midY = (f.top + f.bottom) / 2;
    s << "<text x=\"" << px((f.left + f.right) / 2) << "\" y=\"" << f.bottom + 34
      << "\" text-anchor=\"middle\">" << xmlEscape(xLabel) << "</text><text x=\"14\" y=\""
      << px(midY) << "\" transform=\"rotate(-90 14 " << px(midY) << ")\" text-anchor=\"middle\">"
      << xmlEscape(yLabel) << "</text></g>";
    return s.str();
}

// Dash patterns for lines: the first series solid, every later one dashed, each unlike its
// neighbours. A series drawn over an equal one (a standard-flooding method over its JFA
// method) then leaves gaps where the one below shows.
const char* dash(std::size_t i) {
    static const char* kDash[] = {"7 4", "2 3", "10 3 2 3", "5 5", "12 4", "3 3 8 3"};
    return i == 0 ? "" : kDash[(i - 1) % std::size(kDash)];
}

// A hollow marker of shape i (circle, square, triangle, diamond, triangle down, cross) of radius
// about r at (x, y): markers of series drawn at the same point stay visible through each other.
std::string marker(std::size_t i, double x, double y, const std::string& colour, double r = 3.6) {
    std::ostringstream s;
    const auto at = [&](double dx, double dy) { return px(x + dx * r) + "," + px(y + dy * r); };
    s << "<";
    switch (i % 6) {
    case 0:
        s << "circle cx=\"" << px(x) << "\" cy=\"" << px(y) << "\" r=\"" << px(r) << "\"";
        break;
    case 1:
        s << "path d=\"M" << at(-0.85, -0.85) << "H" << px(x + 0.85 * r) << "V" << px(y + 0.85 * r)
          << "H" << px(x - 0.85 * r) << "Z\"";
        break;
    case 2:
        s << "path d=\"M" << at(0, -1.15) << "L" << at(1.05, 0.75) << "L" << at(-1.05, 0.75)
          << "Z\"";
        break;
    case 3:
        s << "path d=\"M" << at(0, -1.2) << "L" << at(1.2, 0) << "L" << at(0, 1.2) << "L"
          << at(-1.2, 0) << "Z\"";
        break;
    case 4:
        s << "path d=\"M" << at(0, 1.15) << "L" << at(1.05, -0.75) << "L" << at(-1.05, -0.75)
          << "Z\"";
        break;
    default:
        s << "path d=\"M" << at(-1, -1) << "L" << at(1, 1) << "M" << at(1, -1) << "L" << at(-1, 1)
          << "\"";
        break;
    }
    s << " class=\"marker\" fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"1.5\"/>";
    return s.str();
}

enum class Key { Line, Swatch, Marker };

// The legend right of the plot: one entry (a group with the series' name and colour, for the
// report's self-check) per name, drawn as the series is: a line with its dash and marker, a
// colour swatch, or a marker.
std::string legend(const std::vector<std::string>& names, const Box& b, Key key) {
    std::ostringstream s;
    s << "<g class=\"legend\">";
    const int x = b.plotRight + 12;
    for (std::size_t i = 0; i < names.size(); ++i) {
        const int y = kTop + 4 + static_cast<int>(i) * kEntryH;
        s << "<g class=\"entry\" data-series=\"" << xmlEscape(names[i]) << "\" data-colour=\""
          << colour(i) << "\">";
        switch (key) {
        case Key::Line:
            s << "<line x1=\"" << x << "\" x2=\"" << x + 26 << "\" y1=\"" << y + 5 << "\" y2=\""
              << y + 5 << "\" stroke=\"" << colour(i) << "\" stroke-width=\"1.5\" "
              << "stroke-dasharray=\"" << dash(i) << "\"/>" << marker(i, x + 13, y + 5, colour(i));
            break;
        case Key::Swatch:
            s << "<rect x=\"" << x + 8 << "\" y=\"" << y << "\" width=\"10\" height=\"10\" fill=\""
              << colour(i) << "\"/>";
            break;
        case Key::Marker:
            s << marker(i, x + 13, y + 5, colour(i), 4.5);
            break;
        }
        s << "<text x=\"" << x + 34 << "\" y=\"" << y + 9 << "\">" << xmlEscape(names[i])
          << "</text></g>";
    }
    return s.str() + "</g>";
}

} // namespace

std::string colour(std::size_t i) {
    // Twenty colours a reader tells apart: the ten of d3/Tableau 10, then ten of other hues or
    // clearly lighter or darker; past twenty, hues spaced by the golden angle.
    static const char* kPalette[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                                     "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf",
                                     "#000000", "#aec7e8", "#ffbb78", "#98df8a", "#ff9896",
                                     "#c5b0d5", "#393b79", "#e7ba52", "#637939", "#7b4173"};
    if (i < std::size(kPalette)) return kPalette[i];
    const std::size_t k = i - std::size(kPalette);
    const double hue = std::fmod(static_cast<double>(k) * 137.508 + 20.0, 360.0);
    return "hsl(" + px(hue) + ",70%," + (k % 2 ? "35%)" : "55%)");
}

std::string lineChart(const std::string& title, const std::string& yLabel,
                      const std::vector<Series>& series) {
    std::size_t n = 1;
    double hi = 0.0;
    std::vector<std::string> names;
    for (const Series& s : series) {
        n = std::max(n, s.values.size());
        for (double v : s.values) hi = std::max(hi, v);
        names.push_back(s.name);
    }
    const Box b = boxFor(names);
    const Frame f = frameIn(b, 0.0, static_cast<double>(std::max<std::size_t>(n - 1, 1)), 0.0,
                            hi > 0.0 ? hi * 1.05 : 1.0);
    // Markers on every frame up to 24 frames, else on every step-th, staggered by series so
    // that markers of equal series do not sit on each other.
    const std::size_t step = (n + 23) / 24;
    std::ostringstream s;
    s << open(title, b) << axes(f, "frame", yLabel);
    for (std::size_t k = 0; k < series.size(); ++k) {
        const std::vector<double>& v = series[k].values;
        s << "<g class=\"series\" data-series=\"" << xmlEscape(series[k].name)
          << "\"><polyline fill=\"none\" stroke-width=\"1.5\" stroke=\"" << colour(k)
          << "\" stroke-dasharray=\"" << dash(k) << "\" points=\"";
        for (std::size_t i = 0; i < v.size(); ++i)
            s << px(f.sx(static_cast<double>(i))) << "," << px(f.sy(v[i])) << " ";
        s << "\"/>";
        const std::size_t offset = series.size() > 1 ? k * step / series.size() : 0;
        for (std::size_t i = offset; i < v.size(); i += step)
            s << marker(k, f.sx(static_cast<double>(i)), f.sy(v[i]), colour(k));
        s << "</g>";
    }
    return s.str() + legend(names, b, Key::Line) + "</svg>";
}

std::string stackedShareChart(const std::string& title, const std::vector<Series>& stacks) {
    std::size_t n = 1;
    std::vector<std::string> names;
    for (const Series& st : stacks) {
        n = std::max(n, st.values.size());
        names.push_back(st.name);
    }
    const Box b = boxFor(names);
    const Frame f = frameIn(b, 0.0, static_cast<double>(n), 0.0, 100.0);
    std::ostringstream s;
    s << open(title, b) << axes(f, "frame", "% of penumbra pixels");
    const double bw = (f.sx(1.0) - f.sx(0.0));
    for (std::size_t i = 0; i < n; ++i) {
        double base = 0.0;
        for (std::size_t k = 0; k < stacks.size(); ++k) {
            const double v = i < stacks[k].values.size() ? 100.0 * stacks[k].values[i] : 0.0;
            s << "<rect data-series=\"" << xmlEscape(stacks[k].name) << "\" x=\""
              << px(f.sx(static_cast<double>(i))) << "\" y=\"" << px(f.sy(base + v))
              << "\" width=\"" << px(std::max(bw, 0.5)) << "\" height=\""
              << px(f.sy(base) - f.sy(base + v)) << "\" fill=\"" << colour(k) << "\"/>";
            base += v;
        }
    }
    return s.str() + legend(names, b, Key::Swatch) + "</svg>";
}

std::string phaseBars(
    const std::string& title,
    const std::vector<std::pair<std::string, std::vector<std::pair<std::string, double>>>>& rows) {
    std::vector<std::string> phaseNames;
    double hi = 0.0;
    for (const auto& [label, phases] : rows) {
        double sum = 0.0;
        for (const auto& [name, ms] : phases) {
            sum += ms;
            if (std::find(phaseNames.begin(), phaseNames.end(), name) == phaseNames.end())
                phaseNames.push_back(name);
        }
        hi = std::max(hi, sum);
    }
    const int rowH = 22, barsH = kTop + kBottom + rowH * static_cast<int>(rows.size()) + 10;
    const Box b = boxFor(phaseNames, barsH);
    const double left = 150.0, right = b.plotRight;
    // Room right of the longest bar for its total.
    const double scale = (right - left) / (hi > 0.0 ? hi * 1.2 : 1.0);
    std::ostringstream s;
    s << open(title, b);
    for (std::size_t r = 0; r < rows.size(); ++r) {
        const double y = kTop + static_cast<double>(r) * rowH;
        s << "<text x=\"" << left - 6 << "\" y=\"" << px(y + 15) << "\" text-anchor=\"end\">"
          << xmlEscape(rows[r].first) << "</text>";
        double x = left, sum = 0.0;
        for (const auto& [name, ms] : rows[r].second) {
            const auto idx = static_cast<std::size_t>(
                std::find(phaseNames.begin(), phaseNames.end(), name) - phaseNames.begin());
            s << "<rect data-series=\"" << xmlEscape(name) << "\" x=\"" << px(x) << "\" y=\""
              << px(y + 3) << "\" width=\"" << px(std::max(ms * scale, 0.0)) << "\" height=\""
              << rowH - 6 << "\" fill=\"" << colour(idx) << "\"><title>" << xmlEscape(name) << ": "
              << num(ms) << " ms</title></rect>";
            x += ms * scale;
            sum += ms;
        }
        s << "<text x=\"" << px(x + 4) << "\" y=\"" << px(y + 15) << "\">" << num(sum)
          << " ms</text>";
    }
    s << "<text x=\"" << (left + right) / 2 << "\" y=\"" << barsH - 8
      << "\" text-anchor=\"middle\">median ms per frame, by phase</text>";
    return s.str() + legend(phaseNames, b, Key::Swatch) + "</svg>";
}

std::string scatterChart(const std::string& title, const std::string& xLabel,
                         const std::string& yLabel, const std::vector<Point>& points) {
    double xHi = 0.0, yHi = 0.0;
    std::vector<std::string> names;
    for (const Point& p : points) {
        xHi = std::max(xHi, p.x);
        yHi = std::max(yHi, p.y);
        names.push_back(p.label);
    }
    const Box b = boxFor(names);
    const Frame f = frameIn(b, 0.0, xHi > 0.0 ? xHi * 1.1 : 1.0, 0.0, yHi > 0.0 ? yHi * 1.1 : 1.0);
    std::ostringstream s;
    s << open(title, b) << axes(f, xLabel, yLabel);
    for (std::size_t i = 0; i < points.size(); ++i) {
        s << "<g class=\"point\" data-series=\"" << xmlEscape(points[i].label) << "\"><title>"
          << xmlEscape(points[i].label) << ": " << num(points[i].x) << " ms, " << num(points[i].y)
          << "</title>" << marker(i, f.sx(points[i].x), f.sy(points[i].y), colour(i), 4.5)
          << "</g>";
    }
    return s.str() + legend(names, b, Key::Marker) + "</svg>";
}

} // namespace fl::app::svg
