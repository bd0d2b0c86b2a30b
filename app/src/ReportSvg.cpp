#include <app/ReportSvg.h>

#include <base/Text.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>

namespace fl::app::svg {

namespace {

constexpr int kW = 760, kH = 300;                                // chart size, px
constexpr int kLeft = 70, kRight = 170, kTop = 30, kBottom = 40; // plot margins (legend right)

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

struct Frame {
    double x0, x1, y0, y1; // data range
    [[nodiscard]] double sx(double x) const {
        return kLeft + (x - x0) / std::max(x1 - x0, 1e-12) * (kW - kLeft - kRight);
    }
    [[nodiscard]] double sy(double y) const {
        return kH - kBottom - (y - y0) / std::max(y1 - y0, 1e-12) * (kH - kTop - kBottom);
    }
};

std::string open(const std::string& title) {
    return "<svg class=\"chart\" xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
           std::to_string(kW) + "\" height=\"" + std::to_string(kH) + "\" viewBox=\"0 0 " +
           std::to_string(kW) + " " + std::to_string(kH) + "\" role=\"img\"><title>" +
           xmlEscape(title) + "</title><text x=\"" + std::to_string(kLeft) +
           "\" y=\"18\" class=\"ct\">" + xmlEscape(title) + "</text>";
}

// Axes with ticks; x ticks only when xTicks.
std::string axes(const Frame& f, const std::string& xLabel, const std::string& yLabel,
                 bool xTicks = true) {
    std::ostringstream s;
    s << "<g class=\"axis\"><line x1=\"" << kLeft << "\" y1=\"" << kH - kBottom << "\" x2=\""
      << kW - kRight << "\" y2=\"" << kH - kBottom << "\"/><line x1=\"" << kLeft << "\" y1=\""
      << kTop << "\" x2=\"" << kLeft << "\" y2=\"" << kH - kBottom << "\"/>";
    const double ys = niceStep(f.y1 - f.y0, 5);
    for (double y = std::ceil(f.y0 / ys) * ys; y <= f.y1 + 1e-9 * ys; y += ys)
        s << "<line class=\"grid\" x1=\"" << kLeft << "\" x2=\"" << kW - kRight << "\" y1=\""
          << px(f.sy(y)) << "\" y2=\"" << px(f.sy(y)) << "\"/><text x=\"" << kLeft - 6 << "\" y=\""
          << px(f.sy(y) + 4) << "\" text-anchor=\"end\">" << num(y) << "</text>";
    if (xTicks) {
        const double xs = std::max(1.0, niceStep(f.x1 - f.x0, 8));
        for (double x = std::ceil(f.x0 / xs) * xs; x <= f.x1 + 1e-9; x += xs)
            s << "<text x=\"" << px(f.sx(x)) << "\" y=\"" << kH - kBottom + 16
              << "\" text-anchor=\"middle\">" << num(x) << "</text>";
    }
    s << "<text x=\"" << (kLeft + kW - kRight) / 2 << "\" y=\"" << kH - 6
      << "\" text-anchor=\"middle\">" << xmlEscape(xLabel) << "</text><text x=\"14\" y=\""
      << (kTop + kH - kBottom) / 2 << "\" transform=\"rotate(-90 14 " << (kTop + kH - kBottom) / 2
      << ")\" text-anchor=\"middle\">" << xmlEscape(yLabel) << "</text></g>";
    return s.str();
}

std::string legend(const std::vector<std::string>& names) {
    std::ostringstream s;
    s << "<g class=\"legend\">";
    for (std::size_t i = 0; i < names.size(); ++i) {
        const int y = kTop + 4 + static_cast<int>(i) * 16;
        s << "<rect x=\"" << kW - kRight + 12 << "\" y=\"" << y << "\" width=\"10\" height=\"10\" "
          << "fill=\"" << colour(i) << "\"/><text x=\"" << kW - kRight + 27 << "\" y=\"" << y + 9
          << "\">" << xmlEscape(names[i]) << "</text>";
    }
    return s.str() + "</g>";
}

} // namespace

const char* colour(std::size_t i) {
    static const char* kPalette[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                                     "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};
    return kPalette[i % (sizeof kPalette / sizeof kPalette[0])];
}

std::string lineChart(const std::string& title, const std::string& yLabel,
                      const std::vector<Series>& series) {
    std::size_t n = 1;
    double hi = 0.0;
    for (const Series& s : series) {
        n = std::max(n, s.values.size());
        for (double v : s.values) hi = std::max(hi, v);
    }
    const Frame f{0.0, static_cast<double>(std::max<std::size_t>(n - 1, 1)), 0.0,
                  hi > 0.0 ? hi * 1.05 : 1.0};
    std::ostringstream s;
    s << open(title) << axes(f, "frame", yLabel);
    std::vector<std::string> names;
    for (std::size_t k = 0; k < series.size(); ++k) {
        names.push_back(series[k].name);
        s << "<polyline class=\"series\" fill=\"none\" stroke-width=\"1.5\" stroke=\"" << colour(k)
          << "\" points=\"";
        for (std::size_t i = 0; i < series[k].values.size(); ++i)
            s << px(f.sx(static_cast<double>(i))) << "," << px(f.sy(series[k].values[i])) << " ";
        s << "\"/>";
        if (series[k].values.size() == 1) // a single frame: a dot, as a line needs two points
            s << "<circle r=\"3\" fill=\"" << colour(k) << "\" cx=\"" << px(f.sx(0)) << "\" cy=\""
              << px(f.sy(series[k].values[0])) << "\"/>";
    }
    return s.str() + legend(names) + "</svg>";
}

std::string stackedShareChart(const std::string& title, const std::vector<Series>& stacks) {
    std::size_t n = 1;
    for (const Series& s : stacks) n = std::max(n, s.values.size());
    const Frame f{0.0, static_cast<double>(n), 0.0, 100.0};
    std::ostringstream s;
    s << open(title) << axes(f, "frame", "% of penumbra pixels");
    const double bw = (f.sx(1.0) - f.sx(0.0));
    std::vector<std::string> names;
    for (const Series& st : stacks) names.push_back(st.name);
    for (std::size_t i = 0; i < n; ++i) {
        double base = 0.0;
        for (std::size_t k = 0; k < stacks.size(); ++k) {
            const double v = i < stacks[k].values.size() ? 100.0 * stacks[k].values[i] : 0.0;
            s << "<rect x=\"" << px(f.sx(static_cast<double>(i))) << "\" y=\"" << px(f.sy(base + v))
              << "\" width=\"" << px(std::max(bw, 0.5)) << "\" height=\""
              << px(f.sy(base) - f.sy(base + v)) << "\" fill=\"" << colour(k) << "\"/>";
            base += v;
        }
    }
    return s.str() + legend(names) + "</svg>";
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
    const int rowH = 22, height = kTop + kBottom + rowH * static_cast<int>(rows.size()) + 10;
    const double left = 150.0, right = kW - kRight;
    // Room right of the longest bar for its total.
    const double scale = (right - left) / (hi > 0.0 ? hi * 1.2 : 1.0);
    std::ostringstream s;
    s << "<svg class=\"chart\" xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kW
      << "\" height=\"" << height << "\" viewBox=\"0 0 " << kW << " " << height
      << "\" role=\"img\"><title>" << xmlEscape(title) << "</title><text x=\"" << kLeft
      << "\" y=\"18\" class=\"ct\">" << xmlEscape(title) << "</text>";
    for (std::size_t r = 0; r < rows.size(); ++r) {
        const double y = kTop + static_cast<double>(r) * rowH;
        s << "<text x=\"" << left - 6 << "\" y=\"" << px(y + 15) << "\" text-anchor=\"end\">"
          << xmlEscape(rows[r].first) << "</text>";
        double x = left, sum = 0.0;
        for (const auto& [name, ms] : rows[r].second) {
            const auto idx = static_cast<std::size_t>(
                std::find(phaseNames.begin(), phaseNames.end(), name) - phaseNames.begin());
            s << "<rect x=\"" << px(x) << "\" y=\"" << px(y + 3) << "\" width=\""
              << px(std::max(ms * scale, 0.0)) << "\" height=\"" << rowH - 6 << "\" fill=\""
              << colour(idx) << "\"><title>" << xmlEscape(name) << ": " << num(ms)
              << " ms</title></rect>";
            x += ms * scale;
            sum += ms;
        }
        s << "<text x=\"" << px(x + 4) << "\" y=\"" << px(y + 15) << "\">" << num(sum)
          << " ms</text>";
    }
    s << "<text x=\"" << (left + right) / 2 << "\" y=\"" << height - 8
      << "\" text-anchor=\"middle\">median ms per frame, by phase</text>";
    return s.str() + legend(phaseNames) + "</svg>";
}

std::string scatterChart(const std::string& title, const std::string& xLabel,
                         const std::string& yLabel, const std::vector<Point>& points) {
    double xHi = 0.0, yHi = 0.0;
    for (const Point& p : points) {
        xHi = std::max(xHi, p.x);
        yHi = std::max(yHi, p.y);
    }
    const Frame f{0.0, xHi > 0.0 ? xHi * 1.1 : 1.0, 0.0, yHi > 0.0 ? yHi * 1.1 : 1.0};
    std::ostringstream s;
    s << open(title) << axes(f, xLabel, yLabel);
    std::vector<std::string> names;
    for (std::size_t i = 0; i < points.size(); ++i) {
        names.push_back(points[i].label);
        s << "<circle class=\"point\" r=\"5\" cx=\"" << px(f.sx(points[i].x)) << "\" cy=\""
          << px(f.sy(points[i].y)) << "\" fill=\"" << colour(i) << "\"><title>"
          << xmlEscape(points[i].label) << ": " << num(points[i].x) << " ms, " << num(points[i].y)
          << "</title></circle>";
    }
    return s.str() + legend(names) + "</svg>";
}

} // namespace fl::app::svg
