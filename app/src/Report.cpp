// The capture report: one HTML file that opens in any browser without a network. Summary table,
// SVG charts (per-frame errors, |dI| buckets against standard flooding as in thesis Fig. 5.4(a),
// time per phase as in Fig. 5.10, cost against error), and each method's worst frame next to
// the reference with a difference picture. Every chart shows a legend entry for each series,
// in colours that differ, and a column or chart that would read 0 throughout says why instead.
// A small inline script checks on load that every chart has a size and content and its legend
// fits inside it, and records what it finds in the DOM (data-charts-ok="N/M" on <body>, and
// <pre id="selfcheck">) so headless browsers in tests can read it.

#include <app/CaptureResults.h>
#include <app/ReportSvg.h>

#include <base/Text.h>

#include <algorithm>
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
.allzero{color:#555;font-style:italic}td.allzero{text-align:left;vertical-align:top;
min-width:9em;max-width:16em}#selfcheck{color:#888;font-size:11px}
</style>)";

// First in <head>: the page's errors (a script's, a resource that failed to load) and its
// console.error calls are kept for the self-check below, which a headless browser cannot
// otherwise report through --dump-dom.
const char* kErrorTrap = R"(<script>
var reportErrors = [];
window.addEventListener('error', function (e) {
  var t = e.target, src = t && t !== window ? t.src || t.href : null;
  reportErrors.push(src ? 'failed to load ' + src : 'error: ' + e.message);
}, true);
window.addEventListener('unhandledrejection', function (e) {
  reportErrors.push('unhandled rejection: ' + e.reason);
});
(function () {
  var original = console.error;
  console.error = function () {
    reportErrors.push('console.error: ' + Array.prototype.slice.call(arguments).join(' '));
    return original.apply(console, arguments);
  };
})();
</script>)";

// On load, records on <body> how many charts have a non-empty box and drawn content, and how
// many images decoded, and writes into <pre id="selfcheck"> every problem found: a legend entry
// outside its chart, over the plot or over another entry, two entries of one colour, a series
// without a legend entry, and the errors kept above. Tests read these from the DOM a headless
// browser dumps.
const char* kCheckScript = R"(<script>
window.addEventListener('load', function () {
  var problems = [], charts = document.querySelectorAll('svg.chart'), ok = 0;
  function outside(q, r) {
    return q.left < r.left - 0.5 || q.right > r.right + 0.5 || q.top < r.top - 0.5 ||
           q.bottom > r.bottom + 0.5;
  }
  charts.forEach(function (c) {
    var r = c.getBoundingClientRect(), b = c.getBBox(), name = c.querySelector('title').textContent;
    if (r.width > 0 && r.height > 0 && b.width > 0 && b.height > 0 &&
        c.querySelectorAll('polyline,rect,circle,path').length > 0) ok++;
    else problems.push(name + ': nothing drawn');
    var k = r.width / c.viewBox.baseVal.width;
    var plotRight = r.left + k * parseFloat(c.getAttribute('data-plot-right'));
    var entries = c.querySelectorAll('.legend .entry'), named = {}, colours = {}, last = null;
    entries.forEach(function (e) {
      var s = e.getAttribute('data-series'), col = e.getAttribute('data-colour');
      var q = e.getBoundingClientRect();
      named[s] = true;
      if (outside(q, r)) problems.push(name + ': legend entry "' + s + '" outside its chart');
      if (q.left < plotRight) problems.push(name + ': legend entry "' + s + '" over the plot');
      if (last && q.top < last.bottom - 0.5)
        problems.push(name + ': legend entry "' + s + '" over the one before');
      if (colours[col]) problems.push(name + ': "' + s + '" and "' + colours[col] +
                                      '" share the colour ' + col);
      colours[col] = s;
      last = q;
    });
    c.querySelectorAll('[data-series]').forEach(function (e) {
      var s = e.getAttribute('data-series');
      if (named[s]) return;
      named[s] = true;
      problems.push(name + ': series "' + s + '" has no legend entry');
    });
  });
  var imgs = document.querySelectorAll('img'), shown = 0;
  imgs.forEach(function (i) { if (i.complete && i.naturalWidth > 0) shown++; });
  document.body.setAttribute('data-charts-ok', ok + '/' + charts.length);
  document.body.setAttribute('data-images-ok', shown + '/' + imgs.length);
  problems = problems.concat(reportErrors);
  document.getElementById('selfcheck').textContent = 'self-check: ' + problems.length +
      ' problem(s)' + (problems.length ? '\n' + problems.join('\n') : '');
});
</script>)";

// Whether a cell reads as zero ("0.00000", "-0.00", not "-" nor "0.00 (3.15)").
bool readsZero(const std::string& cell) {
    return cell.find('0') != std::string::npos &&
           cell.find_first_not_of("-0.") == std::string::npos;
}

// Why a summary column reads 0 for every method; its key is the summary's field.
std::string whyAllZero(const std::string& key, const nlohmann::json& summary) {
    const bool oneFrame = summary["frames"].get<int>() < 2;
    if ((key == "addedFlicker" || key == "addedFlickerScreen") && oneFrame)
        return "a single frame, and flicker compares consecutive ones";
    if (key == "addedFlicker")
        return "no method's visibility changed on a surface point between frames by more than "
               "the reference's (camera motion alone adds none)";
    if (key == "addedFlickerScreen")
        return "on the pixels that are receivers in consecutive frames, no method's visibility "
               "changed more than the reference's did";
    if (key == "acne") return "no method darkens a lit receiver facing the light by over 0.1";
    if (key == "peterPanning")
        return "no method lights the reference's umbra beside a contact by over 0.1";
    return "every method matches the reference here, to the precision shown";
}

std::string summaryTable(const nlohmann::json& summary) {
    struct Column {
        const char* header;
        const char* key; // the summary's field, for why it may read 0
        std::vector<std::string> cells;
    };
    std::vector<Column> cols{{"RMSE", "rmse", {}},
                             {"RMSE penumbra", "rmsePenumbra", {}},
                             {"misclassified %", "misclassifiedPercent", {}},
                             {"|width error| px", "meanAbsWidthErrorPx", {}},
                             {"width px (ref.)", "meanWidthPx", {}},
                             {"added flicker", "addedFlicker", {}},
                             {"(same pixel)", "addedFlickerScreen", {}},
                             {"frame ms (median)", "medianFrameMs", {}},
                             {"time / hard", "frameTimeOverHard", {}},
                             {"acne %", "acne", {}},
                             {"peter-panning %", "peterPanning", {}}};
    const auto& methods = summary["methods"];
    for (const auto& m : methods) {
        const auto value = [&](const char* key, double scale, int precision) {
            return m.contains(key) ? fmt(scale * m[key].get<double>(), precision)
                                   : std::string("-");
        };
        const std::string cells[] = {value("rmse", 1, 4),
                                     value("rmsePenumbra", 1, 4),
                                     value("misclassifiedPercent", 1, 2),
                                     value("meanAbsWidthErrorPx", 1, 2),
                                     value("meanWidthPx", 1, 2) + " (" +
                                         value("meanReferenceWidthPx", 1, 2) + ")",
                                     value("addedFlicker", 1, 5),
                                     value("addedFlickerScreen", 1, 5),
                                     value("medianFrameMs", 1, 2),
                                     value("frameTimeOverHard", 1, 2),
                                     value("acne", 100, 2),
                                     value("peterPanning", 100, 2)};
        for (std::size_t c = 0; c < cols.size(); ++c) cols[c].cells.push_back(cells[c]);
    }
    std::ostringstream s;
    s << "<table id=\"summary\"><tr><th>method</th>";
    for (const Column& c : cols) s << "<th>" << c.header << "</th>";
    s << "</tr>";
    // A column that reads 0 for every method says so once, and why, in one cell down it (one
    // cell across neighbours with the same reason).
    std::vector<std::string> why;
    for (const Column& c : cols)
        why.push_back(!c.cells.empty() && std::all_of(c.cells.begin(), c.cells.end(), readsZero)
                          ? whyAllZero(c.key, summary)
                          : std::string());
    for (std::size_t r = 0; r < methods.size(); ++r) {
        s << "<tr><td>" << xmlEscape(methods[r]["label"].get<std::string>()) << "</td>";
        for (std::size_t c = 0; c < cols.size(); ++c) {
            if (why[c].empty()) {
                s << "<td>" << cols[c].cells[r] << "</td>";
                continue;
            }
            std::size_t span = 1;
            while (c + span < cols.size() && why[c + span] == why[c]) ++span;
            if (r == 0)
                s << "<td class=\"allzero\" rowspan=\"" << methods.size() << "\" colspan=\"" << span
                  << "\">0 for every method: " << xmlEscape(why[c]) << "</td>";
            c += span - 1;
        }
        s << "</tr>";
    }
    return s.str() + "</table>";
}

// The flicker chart clamps each frame at 0 (a method flickering less than the reference adds
// none); when every value is then 0 the chart would be a flat line, so a sentence says why.
std::string errorCharts(const CaptureResults& r, const nlohmann::json& summary) {
    std::vector<svg::Series> all, pen, flicker;
    bool anyFlicker = false;
    for (const MethodRun& m : r.runs) {
        if (m.spec.method == r.script->reference.method().name) continue; // zero against itself
        svg::Series a{m.label, {}}, p{m.label, {}}, f{m.label, {}};
        for (const FrameRow& row : m.rows) {
            a.values.push_back(row.metrics.rmse);
            p.values.push_back(row.metrics.rmsePenumbra);
            f.values.push_back(row.flicker ? std::max(0.0, *row.flicker) : 0.0);
            anyFlicker = anyFlicker || f.values.back() > 0.0;
        }
        all.push_back(std::move(a));
        pen.push_back(std::move(p));
        flicker.push_back(std::move(f));
    }
    if (all.empty()) return "<p>Only the reference was captured: nothing to compare.</p>";
    std::string out = svg::lineChart("RMSE of visibility per frame (receivers)", "RMSE", all) +
                      svg::lineChart("RMSE of visibility per frame (reference penumbra pixels)",
                                     "RMSE (penumbra)", pen);
    const bool meansZero =
        std::all_of(summary["methods"].begin(), summary["methods"].end(),
                    [](const nlohmann::json& m) { return m["addedFlicker"].get<double>() == 0.0; });
    if (anyFlicker)
        out += svg::lineChart("Added flicker per frame (clamped at 0)", "mean |dV| - reference's",
                              flicker);
    else
        out += "<p class=\"allzero\" id=\"no-flicker-chart\">Added flicker per frame: not drawn, "
               "as it is 0 in every frame for every method: " +
               xmlEscape(meansZero ? whyAllZero("addedFlicker", summary)
                                   : "no method's visibility changed more than the reference's "
                                     "in any frame (the table's means are negative where a "
                                     "method changed less)") +
               ".</p>";
    return out;
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
      << xmlEscape(s.file.filename().string()) << "</title>" << kStyle << kErrorTrap << kCheckScript
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
      << errorCharts(r, summary) << "\n<h2>|dI| against standard flooding</h2>\n"
      << bucketCharts(r) << "\n<h2>Time and cost</h2>\n"
      << timeAndCostCharts(summary) << "\n<h2>Worst frames</h2>\n"
      << worstFrames(r, imageDir) << "\n<p>Data: <a href=\"frames.csv\">frames.csv</a>, "
      << "<a href=\"summary.json\">summary.json</a>.</p>\n"
      << "<pre id=\"selfcheck\">self-check: did not run</pre>\n</body></html>\n";
    return h.str();
}

} // namespace fl::app
