#pragma once
// Small SVG charts for the capture report, drawn by our own code so the report needs no library
// and no network. Each function returns one `<svg class="chart">` element.

#include <string>
#include <utility>
#include <vector>

namespace fl::app::svg {

struct Series {
    std::string name;
    std::vector<double> values; // one per x position (frame)
};

/// The i-th colour: twenty distinct ones, then distinct hues (never a repeat).
std::string colour(std::size_t i);

/// Lines of y over frame index, one per series, with a legend.
std::string lineChart(const std::string& title, const std::string& yLabel,
                      const std::vector<Series>& series);
/// Per-frame stacked bars of shares (each frame's stack sums to <= 1): e.g. |dI| buckets.
std::string stackedShareChart(const std::string& title, const std::vector<Series>& stacks);
/// Horizontal stacked bars: one bar per row, one segment per phase (ms).
std::string phaseBars(
    const std::string& title,
    const std::vector<std::pair<std::string, std::vector<std::pair<std::string, double>>>>& rows);

struct Point {
    std::string label;
    double x = 0.0, y = 0.0;
};
/// A labelled scatter plot (e.g. frame time against error).
std::string scatterChart(const std::string& title, const std::string& xLabel,
                         const std::string& yLabel, const std::vector<Point>& points);

} // namespace fl::app::svg
