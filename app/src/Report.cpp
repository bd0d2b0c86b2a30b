// The capture report: one HTML file that opens in any browser without a network. Summary table,
// SVG charts (per-frame errors, |dI| buckets against standard flooding as in thesis Fig. 5.4(a),
// time per phase as in Fig. 5.10, cost against error), and each method's worst frame next to
// the reference with a difference picture. A tiny inline script checks on load that every chart
// has a size and content, and records the result on <body> (data-charts-ok="N/M") so headless
// browsers in tests can read it from the DOM.

#include <app/CaptureResults.h>
#include <app/ReportSvg.h>

#include <base/Text.h>

#include <iomanip>
#include <sstream>

namespace fl::app {

namespace {

std::string fmt(double v, int precision) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(precision) << v;
    return s.str();
}

const char* kStyle = R"(<style>
body{font-family:sans-serif;margin:24px;color:#222;max-width:1200px}
table{border-collapse:collapse;margin:12px 0}th,td{border:1px solid #ccc;padding:4px 8px;
text-align:right}th{background:#f2f2f2}td:first-child,th:first-child{text-align:left}
svg.chart{display:block;margin:16px 0;background:#fff;border:1px solid #ddd}
svg.chart text{font-size:11px;fill:#333}svg.chart .ct{font-size:13px;font-weight:bold}
svg.chart .axis line{stroke:#444}svg.chart line.grid{stroke:#e4e4e4}
figure{display:inline-block;margin:8px 16px 8px 0}figure img{max-width:100%;min-width:480px;
image-rendering:pixelated;border:1px solid #ccc}dt{font-weight:bold}
</style>)";

// Records on <body> how many charts have a non-empty box and drawn content, and how many images
// decoded; tests read these from the DOM a headless browser dumps.
const char* kCheckScript = R"(<script>
window.addEventListener('load', function () {
  var charts = document.querySelectorAll('svg.chart'), ok = 0;
  charts.forEach(function (c) {
    var r = c.getBoundingClientRect(), b = c.getBBox();
    if (r.width > 0 && r.height > 0 && b.width > 0 && b.height > 0 &&
        c.querySelectorAll('polyline,rect,circle').length > 0) ok++;
  });
  var imgs = document.querySelectorAll('img'), shown = 0;
  imgs.forEach(function (i) { if (i.complete && i.naturalWidth > 0) shown++; });
  document.body.setAttribute('data-charts-ok', ok + '/' + charts.length);
  document.body.setAttribute('data-images-ok', shown + '/' + imgs.length);
});
</script>)";

std::string summaryTable(const nlohmann::json& summary) {
    std::ostringstream s;
    s << "<table id=\"summary\"><tr><th>method</th><th>RMSE</th><th>RMSE penumbra</th>"
         "<th>misclassified %</th><th>|width error| px</th><th>width px (ref.)</th>"
         "<th>added flicker</th><th>(same pixel)</th><th>frame ms (median)</th>"
         "<th>time / hard</th><th>acne %</th><th>peter-panning %</th></tr>";
    for (const auto& m : summary["methods"]) {
        s << "<tr><td>" << xmlEscape(m["label"].get<std::string>()) << "</td><td>"
          << fmt(m["rmse"].get<double>(), 4) << "</td><td>"
          << fmt(m["rmsePenumbra"].get<double>(), 4) << "</td><td>"
          << fmt(m["misclassifiedPercent"].get<double>(), 2) << "</td><td>"
          << fmt(m["meanAbsWidthErrorPx"].get<double>(), 2) << "</td><td>"
          << fmt(m["meanWidthPx"].get<double>(), 2) << " ("
          << fmt(m["meanReferenceWidthPx"].get<double>(), 2) << ")</td><td>"
          << fmt(m["addedFlicker"].get<double>(), 5) << "</td><td>"
          << fmt(m["addedFlickerScreen"].get<double>(), 5) << "</td><td>"
          << fmt(m["medianFrameMs"].get<double>(), 2) << "</td><td>"
          << (m.contains("frameTimeOverHard") ? fmt(m["frameTimeOverHard"].get<double>(), 2)
                                              : std::string("-"))
          << "</td><td>" << fmt(100.0 * m["acne"].get<double>(), 2) << "</td><td>"
          << fmt(100.0 * m["peterPanning"].get<double>(), 2) << "</td></tr>";
    }
    return s.str() + "</table>";
}

std::string errorCharts(const CaptureResults& r) {
    std::vector<svg::Series> all, pen, flicker;
    for (const MethodRun& m : r.runs) {
        if (m.spec.method == r.script->reference.method().name) continue; // zero against itself
        svg::Series a{m.label, {}}, p{m.label, {}}, f{m.label, {}};
        for (const FrameRow& row : m.rows) {
            a.values.push_back(row.metrics.rmse);
            p.values.push_back(row.metrics.rmsePenumbra);
            f.values.push_back(row.flicker ? std::max(0.0, *row.flicker) : 0.0);
        }
        all.push_back(std::move(a));
        pen.push_back(std::move(p));
        flicker.push_back(std::move(f));
    }
    if (all.empty()) return "<p>Only the reference was captured: nothing to compare.</p>";
    return svg::lineChart("RMSE of visibility per frame (receivers)", "RMSE", all) +
           svg::lineChart("RMSE of visibility per frame (reference penumbra pixels)",
                          "RMSE (penumbra)", pen) +
           svg::lineChart("Added flicker per frame (clamped at 0)", "mean |dV| - reference's",
                          flicker);
}

std::string bucketCharts(const CaptureResults& r) {
    std::ostringstream s;
    for (const MethodRun& m : r.runs) {
        if (m.counterpart.empty()) continue;
        std::vector<svg::Series> stacks{
            {"|dI| < 0.05", {}}, {"0.05 - 0.1", {}}, {"0.1 - 0.2", {}}, {">= 0.2", {}}};
        for (const FrameRow& row : m.rows)
            for (std::size_t k = 0; k < 4; ++k)
                stacks[k].values.push_back(row.deltaBuckets ? (*row.deltaBuckets)[k] : 0.0);
        s << svg::stackedShareChart("|dI| of " + m.label + " against " + m.counterpart +
                                        " per frame (penumbra pixels of either)",
                                    stacks);
    }
    const std::string out = s.str();
    return out.empty() ? "<p>No JFA method with its standard-flooding counterpart in the script "
                         "(list jfa-l with flood-l, or jfa-e with flood-e).</p>"
                       : out;
}

std::string timeAndCostCharts(const nlohmann::json& summary) {
    std::vector<std::pair<std::string, std::vector<std::pair<std::string, double>>>> rows;
    std::vector<svg::Point> points;
    for (const auto& m : summary["methods"]) {
        std::vector<std::pair<std::string, double>> phases;
        for (const auto& [name, ms] : m["medianPhaseMs"].items())
            phases.emplace_back(name, ms.get<double>());
        rows.emplace_back(m["label"].get<std::string>(), std::move(phases));
        if (m["method"] != summary["reference"]["method"])
            points.push_back({m["label"].get<std::string>(), m["medianFrameMs"].get<double>(),
                              m["rmsePenumbra"].get<double>()});
    }
    std::string out = svg::phaseBars("Time per phase (median over frames)", rows);
    if (!points.empty())
        out += svg::scatterChart("Cost against error (every method and preset)", "median frame ms",
                                 "RMSE over penumbra pixels", points);
    return out;
}

std::string worstFrames(const CaptureResults& r, const std::string& imageDir) {
    std::ostringstream s;
    for (const MethodRun& m : r.runs) {
        if (m.spec.method == r.script->reference.method().name) continue;
        s << "<figure><img src=\"" << xmlEscape(imageDir + "/worst_" + safeName(m.label) + ".png")
          << "\" alt=\"" << xmlEscape(m.label) << " worst frame\"><figcaption>"
          << xmlEscape(m.label) << ": frame " << m.worstFrame << ", RMSE " << fmt(m.worstRmse, 4)
          << " (method | reference | |difference| x4)</figcaption></figure>";
    }
    return s.str();
}

} // namespace

std::string reportHtml(const CaptureResults& r, const nlohmann::json& summary,
                       const std::string& imageDir) {
    const CaptureScript& s = *r.script;
    std::ostringstream h;
    h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>Floodlight "
         "capture: "
      << xmlEscape(s.file.filename().string()) << "</title>" << kStyle << kCheckScript
      << "</head><body>\n<h1>Floodlight capture report</h1>\n<dl><dt>script</dt><dd>"
      << xmlEscape(s.file.string()) << "</dd><dt>scene</dt><dd>" << xmlEscape(r.sceneName)
      << "</dd><dt>frames</dt><dd>" << s.frames << " at";
    for (const auto& [w, h2] : s.resolutions) h << " " << w << "x" << h2;
    h << "</dd><dt>shadow map</dt><dd>" << xmlEscape(s.shadowMapProvider) << " " << s.shadowMapSize
      << "&sup2;, flooding passes " << xmlEscape(s.jfaPasses)
      << (s.jfaPasses == "auto" ? " (chosen per frame: frames.csv, jfa_passes)" : "")
      << "</dd><dt>reference</dt><dd>" << xmlEscape(referenceText(s.reference)) << " ("
      << xmlEscape(std::string(s.reference.method().help)) << "), "
      << fmt(summary["reference"]["medianFrameMs"].get<double>(), 1)
      << " ms per frame (median)</dd><dt>GL</dt><dd>" << xmlEscape(r.context) << "</dd></dl>\n"
      << "<p>Metrics against the reference count the receivers only: visible surfaces that "
         "face the light (N&middot;L &gt; 0), where the visibility changes the image. Penumbra "
         "pixels are receivers the reference has in "
         "(0.02, 0.98); classes umbra &le; 0.02 &lt; penumbra &lt; 0.98 &le; lit; RMSEs are "
         "pooled over all frames; the 10&ndash;90% width is the median of 0.8/|&nabla;V| over "
         "receivers with 0.1 &le; V &le; 0.9; added flicker is the mean |V<sub>t</sub>(p) &minus; "
         "V<sub>t&minus;1</sub>(reproject(p))| on the same surface point (beyond the range the "
         "previous frame's pixels around it held), over receivers seen at the same depth in both "
         "frames, of a method minus the reference's own (camera motion alone adds none); "
         "&ldquo;same pixel&rdquo; is the older screen-space figure, "
         "|V<sub>t</sub> &minus; V<sub>t&minus;1</sub>| per pixel.</p>\n"
      << "<h2>Summary</h2>\n"
      << summaryTable(summary) << "\n<h2>Error per frame</h2>\n"
      << errorCharts(r) << "\n<h2>|dI| against standard flooding</h2>\n"
      << bucketCharts(r) << "\n<h2>Time and cost</h2>\n"
      << timeAndCostCharts(summary) << "\n<h2>Worst frames</h2>\n"
      << worstFrames(r, imageDir) << "\n<p>Data: <a href=\"frames.csv\">frames.csv</a>, "
      << "<a href=\"summary.json\">summary.json</a>.</p>\n</body></html>\n";
    return h.str();
}

} // namespace fl::app
