// The CSV and the JSON summary of a capture run, and what it prints at the end.

#include <app/CaptureResults.h>

#include <base/Numbers.h>
#include <base/Stats.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>

namespace fl::app {

namespace {

// Every phase any run timed, in the order first seen (absent phases read 0 in a row).
std::vector<std::string> allPhases(const CaptureResults& r) {
    std::vector<const PhaseTimes*> times;
    for (const MethodRun& m : r.runs) times.push_back(&m.times);
    return phaseNames(times);
}

} // namespace

double outsideRendering(const PhaseSplit& split) {
    return split.wall > 0.0 ? (split.wall - split.render) / split.wall : 0.0;
}

double progressShare(const CaptureResults& r) {
    std::vector<double> share;
    for (std::size_t i = 0; i < r.progressMs.size() && i < r.renderMs.size(); ++i)
        if (r.renderMs[i] > 0.0) share.push_back(r.progressMs[i] / r.renderMs[i]);
    return fl::median(std::move(share));
}

std::string safeName(const std::string& label) {
    std::string out;
    for (char c : label) {
        if (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.')
            out += c;
        else if (c == '/')
            out += '-';
        else if (c == ':' || c == ' ')
            out += out.empty() || out.back() == '_' ? "" : "_";
    }
    return out.empty() ? "method" : out;
}

CsvTable resultsCsv(const CaptureResults& r) {
    const std::vector<std::string> phases = allPhases(r);
    std::vector<std::string> columns = {"frame",
                                        "method",
                                        "width",
                                        "height",
                                        "rmse",
                                        "rmse_penumbra",
                                        "penumbra_pixels",
                                        "misclassified_percent",
                                        "width_method_px",
                                        "width_reference_px",
                                        "width_error_px",
                                        "added_flicker",
                                        "added_flicker_screen",
                                        "dI_lt_0.05",
                                        "dI_0.05_0.1",
                                        "dI_0.1_0.2",
                                        "dI_ge_0.2",
                                        "frame_ms",
                                        "jfa_passes",
                                        "active_share"};
    for (const std::string& p : phases) columns.push_back(csvName(p) + "_ms");
    for (const char* c :
         {"acne_percent", "acne_candidates", "peter_panning_percent", "peter_panning_candidates"})
        columns.push_back(c);
    CsvTable csv(columns);
    for (const MethodRun& m : r.runs)
        for (std::size_t i = 0; i < m.rows.size(); ++i) {
            const FrameRow& row = m.rows[i];
            const FrameMetrics& f = row.metrics;
            csv << row.frame << csvName(m.label) << m.width << m.height << f.rmse << f.rmsePenumbra
                << f.penumbraPixels << 100.0 * f.misclassified << f.widthMethod << f.widthReference
                << f.widthError;
            for (const std::optional<double>& flicker : {row.flicker, row.screenFlicker}) {
                if (flicker)
                    csv << *flicker;
                else
                    csv.blank();
            }
            for (std::size_t k = 0; k < 4; ++k) {
                if (row.deltaBuckets)
                    csv << 100.0 * (*row.deltaBuckets)[k];
                else
                    csv.blank();
            }
            csv << m.times.frameMs().at(i);
            if (const std::optional<FloodSample>& fl = m.times.flood(i))
                csv << fl->passes << fl->activeShare;
            else
                csv.blank().blank();
            for (const std::string& p : phases) csv << m.times.phaseMs(i, p);
            csv << 100.0 * row.bias.acneShare() << row.bias.acneCandidates
                << 100.0 * row.bias.peterPanningShare() << row.bias.peterPanningCandidates;
            csv.endRow();
        }
    return csv;
}

namespace {

// One method's entry of the summary: its frames' metrics pooled, its median times.
nlohmann::json methodSummary(const MethodRun& m, const std::vector<std::string>& phases,
                             std::optional<double> hardMs) {
    double sq = 0.0, sqPen = 0.0, miscl = 0.0, widthErr = 0.0, flick = 0.0, screen = 0.0;
    double pixels = 0.0, penPixels = 0.0, wm = 0.0, wr = 0.0;
    int flickN = 0;
    std::array<double, 4> buckets{};
    int bucketN = 0;
    BiasArtifactCounts bias; // pooled over the frames
    for (const FrameRow& row : m.rows) {
        const FrameMetrics& f = row.metrics;
        bias += row.bias;
        sq += f.sumSquared;
        sqPen += f.sumSquaredPenumbra;
        pixels += static_cast<double>(f.pixels);
        penPixels += static_cast<double>(f.penumbraPixels);
        miscl += f.misclassified;
        widthErr += std::abs(f.widthError);
        wm += f.widthMethod;
        wr += f.widthReference;
        if (row.flicker) {
            flick += *row.flicker;
            screen += row.screenFlicker.value_or(0.0);
            ++flickN;
        }
        if (row.deltaBuckets) {
            for (std::size_t k = 0; k < 4; ++k) buckets[k] += (*row.deltaBuckets)[k];
            ++bucketN;
        }
    }
    const double n = std::max<double>(1.0, static_cast<double>(m.rows.size()));
    nlohmann::json e;
    e["label"] = m.label;
    e["method"] = m.spec.method;
    e["width"] = m.width;
    e["height"] = m.height;
    e["frames"] = m.rows.size();
    e["rmse"] = pixels > 0 ? std::sqrt(sq / pixels) : 0.0;
    e["rmsePenumbra"] = penPixels > 0 ? std::sqrt(sqPen / penPixels) : 0.0;
    e["meanPenumbraPixels"] = penPixels / n;
    e["misclassifiedPercent"] = 100.0 * miscl / n;
    e["meanAbsWidthErrorPx"] = widthErr / n;
    e["meanWidthPx"] = wm / n;
    e["meanReferenceWidthPx"] = wr / n;
    e["addedFlicker"] = flickN > 0 ? flick / flickN : 0.0;
    e["addedFlickerScreen"] = flickN > 0 ? screen / flickN : 0.0;
    e["acne"] = bias.acneShare();
    e["peterPanning"] = bias.peterPanningShare();
    const double frameMs = m.times.medianFrameMs();
    e["medianFrameMs"] = frameMs;
    if (hardMs && *hardMs > 0) e["frameTimeOverHard"] = frameMs / *hardMs;
    nlohmann::json ph = nlohmann::json::object();
    for (const std::string& p : phases)
        if (m.times.ran(p)) ph[p] = m.times.medianPhaseMs(p);
    e["medianPhaseMs"] = ph;
    if (const std::optional<FloodSample> fl = m.times.medianFlood()) {
        e["medianJfaPasses"] = fl->passes;
        e["medianActiveShare"] = fl->activeShare;
    }
    e["worstFrame"] = m.worstFrame;
    e["worstFrameRmse"] = m.worstRmse;
    if (bucketN > 0) {
        e["deltaBucketsAgainst"] = m.counterpart;
        e["meanShareDelta"] = {{"below0.05", buckets[0] / bucketN},
                               {"0.05to0.1", buckets[1] / bucketN},
                               {"0.1to0.2", buckets[2] / bucketN},
                               {"atLeast0.2", buckets[3] / bucketN}};
    }
    return e;
}

// What each figure of the summary means (its "definitions").
nlohmann::json summaryDefinitions() {
    return {
        {"receivers", "the pixels counted: visible surfaces facing the light (N.L > 0), where the "
                      "visibility changes the image"},
        {"penumbra", "receivers with reference visibility in (0.02, 0.98)"},
        {"classes", "umbra <= 0.02, lit >= 0.98, penumbra between"},
        {"rmse", "pooled over the receivers of all frames"},
        {"rmsePenumbra", "pooled over the reference's penumbra pixels of all frames"},
        {"width", "median over receivers with 0.1 <= v <= 0.9 of 0.8 / |grad v|, pixels"},
        {"addedFlicker", "mean |v_t(p) - v_t-1(reproject(p))| over the receivers whose surface "
                         "point was a receiver at the same depth in the previous frame, where "
                         "v_t-1 there is the range its pixels around the point held (a change "
                         "within it is resampling), of the method minus that of the reference"},
        {"addedFlickerScreen", "mean |v_t - v_t-1| on the same pixel over receivers in both "
                               "frames, of the method minus that of the reference (camera "
                               "motion counts too)"},
        {"acne", "pooled over the frames: the share of the receivers whose triangle faces the "
                 "light's centre and whose reference visibility is >= 0.99 that the method "
                 "darkens by more than 0.1"},
        {"peterPanning", "pooled over the frames: the share of the receivers in the reference's "
                         "umbra (<= 0.01) within 3 pixels (Chebyshev) of a contact pixel (a "
                         "receiver with a neighbour whose surface point rises more than half a "
                         "pixel footprint off its plane within 3 footprints of it) that the "
                         "method lights by more than 0.1"}};
}

// An option's value as JSON by its kind: 256, 0.5, "spiral", true.
nlohmann::json optionJson(const MethodOptions& values, const MethodOption& o) {
    switch (o.kind) {
    case OptionKind::Int:
        return values.integer(o);
    case OptionKind::Float: {
        double v = 0.0; // as written (0.1), not rounded to the method's float
        parseNumber(values.text(o), v);
        return v;
    }
    case OptionKind::Flag:
        return values.flag(o);
    case OptionKind::Choice:
        break;
    }
    return values.text(o);
}

// The ground truth: its kind, its method and each option of its row by capture key (a flag
// option only when the script sets it: off is its absence, as on the command line).
nlohmann::json referenceSummary(const CaptureScript::Reference& ref) {
    const MethodDescriptor& truth = ref.method();
    nlohmann::json j = {{"kind", ref.kind}, {"method", std::string(truth.name)}};
    for (const MethodOption* o : truth.options)
        if (o->kind != OptionKind::Flag || ref.options.has(o->flag))
            j[std::string(o->key)] = optionJson(ref.options, *o);
    return j;
}

} // namespace

nlohmann::json resultsSummary(const CaptureResults& r) {
    const CaptureScript& s = *r.script;
    nlohmann::json j;
    j["script"] = s.file.string();
    j["identity"] = r.identity;
    j["scene"] = r.sceneName;
    j["context"] = r.context;
    j["frames"] = s.frames;
    j["resolutions"] = nlohmann::json::array();
    for (const auto& [w, h] : s.resolutions) j["resolutions"].push_back({w, h});
    j["shadowMap"] = {{"provider", s.shadowMapProvider}, {"size", s.shadowMapSize}};
    for (const TsmOption& t : tsmOptions()) j["shadowMap"][std::string(t.key)] = s.tsm.*t.field;
    j["jfaPasses"] = s.jfaPasses;
    j["reference"] = referenceSummary(s.reference);
    j["reference"]["medianFrameMs"] = fl::median(r.referenceFrameMs);
    j["definitions"] = summaryDefinitions();
    const std::vector<std::string> phases = allPhases(r);
    nlohmann::json methods = nlohmann::json::array();
    std::optional<double> hardMs;
    for (const MethodRun& m : r.runs)
        if (m.spec.method == cheapestMethod().name && !hardMs) hardMs = m.times.medianFrameMs();
    for (const MethodRun& m : r.runs) methods.push_back(methodSummary(m, phases, hardMs));
    j["methods"] = methods;
    const auto sample = [](const ResourceSample& at) {
        nlohmann::json gl = nlohmann::json::object();
        for (std::size_t k = 0; k < gl::kObjectKinds.size(); ++k)
            gl[std::string(gl::kObjectKinds[k].name)] = at.glObjects.live[k];
        return nlohmann::json{{"frame", at.frame},
                              {"residentKiB", at.residentKiB},
                              {"glObjects", at.glObjects.total()},
                              {"glObjectsByKind", gl}};
    };
    // After this run's first and last frame (a resumed run's first is its first of this sitting).
    if (r.firstFrame.frame >= 0)
        j["resources"] = {{"firstFrame", sample(r.firstFrame)}, {"lastFrame", sample(r.lastFrame)}};
    // Where this sitting's time went (seconds; CaptureResults.h, PhaseSplit).
    nlohmann::json split = {{"threads", r.split.threads}};
    for (const SplitPhase& p : kSplitPhases)
        split[std::string(p.name) + "Seconds"] = r.split.*p.seconds;
    split["outsideRenderingShare"] = outsideRendering(r.split);
    split["progressMedianMs"] = fl::median(r.progressMs);
    split["progressShareOfRendering"] = progressShare(r);
    j["phaseSplit"] = split;
    j["complete"] = true;
    return j;
}

// The summary's table: one line per method.
void printSummaryTable(const nlohmann::json& summary) {
    std::cout << std::left << std::setw(22) << "method" << std::right << std::setw(10) << "rmse"
              << std::setw(12) << "rmse pen." << std::setw(10) << "miscl.%" << std::setw(11)
              << "flicker" << std::setw(11) << "frame ms" << std::setw(8) << "acne%"
              << std::setw(10) << "p.-pan.%"
              << "\n"
              << std::fixed;
    for (const auto& m : summary["methods"])
        std::cout << std::left << std::setw(22) << m["label"].get<std::string>() << std::right
                  << std::setprecision(4) << std::setw(10) << m["rmse"].get<double>()
                  << std::setw(12) << m["rmsePenumbra"].get<double>() << std::setprecision(2)
                  << std::setw(10) << m["misclassifiedPercent"].get<double>()
                  << std::setprecision(5) << std::setw(11) << m["addedFlicker"].get<double>()
                  << std::setprecision(2) << std::setw(11) << m["medianFrameMs"].get<double>()
                  << std::setw(8) << 100.0 * m["acne"].get<double>() << std::setw(10)
                  << 100.0 * m["peterPanning"].get<double>() << "\n";
    std::cout << std::defaultfloat;
}

// Memory and GL objects after this sitting's first and last frame.
void printResources(const CaptureResults& r) {
    if (r.lastFrame.frame >= 0)
        std::cout << "resources: resident " << r.firstFrame.residentKiB << " KiB after frame "
                  << r.firstFrame.frame << ", " << r.lastFrame.residentKiB << " KiB after frame "
                  << r.lastFrame.frame << "; GL objects " << r.firstFrame.glObjects.total() << ", "
                  << r.lastFrame.glObjects.total() << "\n";
}

// The phase split (CaptureResults.h) and what keeping the progress cost against rendering.
void printPhaseSplit(const CaptureResults& r) {
    const PhaseSplit& s = r.split;
    std::cout << std::fixed << std::setprecision(2) << "phase split, s ("
              << (s.threads > 0 ? std::to_string(s.threads) + " worker threads" : "synchronous")
              << "):";
    for (const SplitPhase& p : kSplitPhases) std::cout << " " << p.name << " " << s.*p.seconds;
    std::cout << std::setprecision(0) << "; outside rendering " << 100.0 * outsideRendering(s)
              << "% of the wall\n";
    if (!r.progressMs.empty())
        std::cout << std::setprecision(1) << "progress for --resume: " << median(r.progressMs)
                  << " ms a frame (median) to keep, " << 100.0 * progressShare(r)
                  << "% of a frame's rendering\n";
    std::cout << std::defaultfloat;
}

} // namespace fl::app
