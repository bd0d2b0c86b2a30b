// The real-model benchmark (issue 41; bench/real_models.sh fetches the models): each glTF/GLB
// model as `floodlight render --scene X --camera auto` shows it (its ground added when it has
// none, the default light), with a disk light of radius --light-size x the model's bounding
// radius, rendered with every method chosen and scored against the ray-traced truth over its
// receivers: RMSE, penumbra RMSE (the truth in (0.02, 0.98)), leak (the truth's umbra, <= 0.05,
// lit by more than 0.3), dark (its fully lit receivers, >= 0.95, darkened by more than 0.3) and
// the frame time (median and min over timed frames, the methods interleaved frame by frame) with
// its ratio to hard. Writes DIR/real_models.csv (one row per model x method), DIR/real_models.md
// (the tables it prints), DIR/LABEL.grid.png (per method: its visibility | the rays' | method
// - rays) and DIR/LABEL.png (the truth's colour render), all committed together.

#include <renderer/Renderer.h>
#include <renderer/context/EglContext.h>
#include <renderer/metrics/BiasArtifacts.h>
#include <renderer/metrics/Metrics.h>
#include <renderer/metrics/ShadowStats.h>
#include <renderer/metrics/SoftStats.h>
#include <renderer/passes/HudPass.h>
#include <renderer/run/Capture.h>
#include <renderer/run/FrameRunner.h>
#include <renderer/soft/ShadowRayInputs.h>
#include <scene/Camera.h>
#include <scene/GltfLoader.h>
#include <scene/Ground.h>

#include <base/OutputFiles.h>
#include <base/Stats.h>
#include <base/Text.h>

#include <BenchSupport.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <functional>
#include <iostream>
#include <memory>
#include <sstream>

namespace {

using fl::bench::MethodEntry;

// The methods the benchmark renders unless --methods says otherwise (labels as sweptMethods
// makes them; "reference" is the shadow-map truth, scored like a method).
constexpr const char* kDefaultMethods =
    "hard,pcf 3x3,pcss 16/16,pcss 16/24,vsm,jfa-l,jfa-e,flood-l,flood-e,reference";

struct Options {
    std::vector<std::string> models; // [LABEL=]PATH
    int size = 256, shadowMap = 1024, frames = 5, referenceFrames = 1, referenceSamples = 256,
        referenceMap = 1024, raySamples = 256;
    float lightSize = 0.08f;
    std::string methods = kDefaultMethods;
    std::string out = "captures/real_models";
};

struct Model {
    std::string label, path;
    fl::Scene scene;
    float radius = 0.0f; // the model's bounding radius, before the ground
    bool ground = false; // a ground was added under it
};

// One measured column per model: a method at a setting, or the shadow-map truth.
struct Score {
    fl::FrameMetrics error;
    fl::ShadowLeaks leaks;
    double medianMs = 0.0, minMs = 0.0, xHard = NAN;
    std::size_t frames = 0;
    /// Where the squared error lies (ErrorPart): each part's root of its pixels' squared error
    /// over all receivers, so the parts' squares add up to the RMSE's.
    std::array<double, 3> parts{};
};

// The parts of a frame an error can come from: near a contact (within kContactReach pixels of
// one, where the map's bias meets the rays' exact contact), on a receiver whose triangle faces
// away from the light's centre (a body's own terminator: its smooth normal faces the light, its
// plane does not), and the rest (cast shadows and penumbrae on surfaces facing the light).
enum ErrorPart { kNearContact, kBackFacing, kElsewhere };

struct ModelResult {
    std::vector<Score> scores; // one per column
    double truthMs = 0.0;
};

// The columns on offer: every method of the table at each swept setting (flood-l and flood-e
// included), then the shadow-map truth labelled "maps N" (its method name is "reference").
std::vector<MethodEntry> offeredColumns(int referenceSamples) {
    std::vector<MethodEntry> all = fl::bench::sweptMethods(true);
    const fl::MethodDescriptor& maps = fl::groundTruth("maps");
    all.push_back({fl::cat(maps.truth, " ", referenceSamples), &maps, {}, {}});
    return all;
}

std::vector<std::string> splitList(const std::string& text) {
    std::vector<std::string> out;
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, ',');) {
        item.erase(0, item.find_first_not_of(' '));
        item.erase(item.find_last_not_of(' ') + 1);
        if (!item.empty()) out.push_back(item);
    }
    return out;
}

// The columns --methods names, in its order: an item is a label ("pcss 16/24"), a method name
// ("pcss": each of its settings) or the truth's kind ("maps"). Throws std::invalid_argument naming
// an unknown item.
std::vector<MethodEntry> chosenColumns(const std::string& list, int referenceSamples) {
    const std::vector<MethodEntry> offered = offeredColumns(referenceSamples);
    std::vector<MethodEntry> out;
    for (const std::string& item : splitList(list)) {
        bool found = false;
        for (const MethodEntry& e : offered) {
            if (e.label != item && e.method->name != item && e.method->truth != item) continue;
            found = true;
            if (std::none_of(out.begin(), out.end(),
                             [&](const MethodEntry& c) { return c.label == e.label; }))
                out.push_back(e);
        }
        if (!found) {
            std::string labels;
            for (const MethodEntry& e : offered) labels += (labels.empty() ? "" : ", ") + e.label;
            throw std::invalid_argument(fl::cat("'", item, "' is no method (valid: ", labels,
                                                ", or a method's name for all its settings)"));
        }
    }
    if (out.empty()) throw std::invalid_argument("no method chosen");
    return out;
}

void addOptions(CLI::App& app, Options& o) {
    app.add_option("models", o.models,
                   "glTF/GLB models, each PATH or LABEL=PATH (the label names its pictures and "
                   "rows; default: the file's stem)")
        ->required();
    fl::bench::addFrameSizeOptions(app, o.size, o.shadowMap);
    app.add_option("--light-size", o.lightSize,
                   "The disk light's radius as a share of the model's bounding radius (before "
                   "the ground is added)")
        ->check(CLI::Range(1e-4f, 10.0f))
        ->capture_default_str();
    app.add_option("--frames", o.frames, "Timed frames per method (after 2 warm-up frames)")
        ->check(CLI::Range(1, 10000))
        ->capture_default_str();
    app.add_option("--reference-frames", o.referenceFrames,
                   "Timed frames of the two truths (after 1 warm-up frame)")
        ->check(CLI::Range(1, 10000))
        ->capture_default_str();
    app.add_option("--reference-samples", o.referenceSamples, "Point lights of the maps truth")
        ->check(CLI::Range(1, 65536))
        ->capture_default_str();
    app.add_option("--reference-map-size", o.referenceMap, "Their shadow maps' side")
        ->check(CLI::Range(16, 8192))
        ->capture_default_str();
    app.add_option("--raytrace-samples", o.raySamples, "Shadow rays per pixel of the truth")
        ->check(CLI::Range(1, 16384))
        ->capture_default_str();
    app.add_option("--methods", o.methods,
                   "Comma-separated labels or method names (all their settings) to render, in "
                   "this order")
        ->check([&o](const std::string& v) {
            try {
                (void)chosenColumns(v, o.referenceSamples);
            } catch (const std::invalid_argument& e) {
                return std::string(e.what());
            }
            return std::string();
        })
        ->capture_default_str();
    app.add_option("--out", o.out, "Output folder")->capture_default_str();
}

// LABEL=PATH or PATH; the label is used in file names, so it is checked.
std::pair<std::string, std::string> labelAndPath(const std::string& arg) {
    const std::size_t eq = arg.find('=');
    std::string label =
        eq == std::string::npos ? std::filesystem::path(arg).stem().string() : arg.substr(0, eq);
    std::string path = eq == std::string::npos ? arg : arg.substr(eq + 1);
    if (label.empty() || std::any_of(label.begin(), label.end(), [](unsigned char c) {
            return !std::isalnum(c) && c != '-' && c != '_' && c != '.';
        }))
        throw std::invalid_argument(fl::cat("model '", arg, "': the label '", label,
                                            "' must be letters, digits, '-', '_' or '.'"));
    return {label, path};
}

// The model as `render --scene PATH --camera auto` sets it up (app/src/SceneSetup.cpp), with
// the light's radius from the model's own bounds.
Model loadModel(const std::string& arg, float lightSize) {
    auto [label, path] = labelAndPath(arg);
    fl::LoadOptions lo;
    lo.warn = [](const std::string& w) { std::cerr << "warning: " << w << "\n"; };
    Model m{label, path, fl::loadGltf(path, lo)};
    m.radius = m.scene.bounds.radius();
    if (!std::isfinite(m.radius) || !(m.radius > 0.0f))
        throw std::invalid_argument(
            fl::cat(path, ": its bounds are empty or degenerate (radius ", m.radius, ")"));
    m.ground = fl::applyGround(m.scene, fl::GroundMode::Auto);
    fl::Light light = fl::sceneLight(m.scene);
    light.radius = lightSize * m.radius;
    m.scene.light = light;
    return m;
}

fl::RenderSettings settingsOf(const Options& o, const fl::MethodDescriptor& m,
                              const std::string& flag, const std::string& value) {
    const fl::MethodDescriptor &maps = fl::groundTruth("maps"),
                               &rays = fl::groundTruth(fl::kExactTruth);
    fl::RenderSettings s;
    s.shadow.size = o.shadowMap;
    s.method = std::string(m.name);
    s.options.set(maps.option("samples")->flag, o.referenceSamples);
    s.options.set(maps.option("mapSize")->flag, o.referenceMap);
    s.options.set(rays.option("samples")->flag, o.raySamples);
    if (!flag.empty()) s.options.set(flag, value);
    return s;
}

// Method lanes (interleaved, 2 warm-up frames), then the truths' (the maps column and the rays,
// 1 warm-up frame): the frame loop of capture/compare (renderer/run/FrameRunner.h).
void timeLanes(const Options& o, const Model& model, const fl::CameraView& cam,
               std::vector<fl::Lane>& methods, std::vector<fl::Lane>& truths) {
    fl::FrameRunner runner(o.frames + o.referenceFrames);
    const auto plan = [&](int n, int warmup) {
        return fl::FramePlan{.scene = &model.scene,
                             .camera = cam,
                             .frames = n,
                             .width = o.size,
                             .height = o.size,
                             .warmup = warmup,
                             .readBack = false};
    };
    if (!methods.empty()) runner.run(plan(o.frames, 2), methods);
    runner.run(plan(o.referenceFrames, 1), truths);
    runner.finish();
}

// Grey visibility where the metrics count (the truth's receivers), slate blue elsewhere.
fl::ByteImage receiverGrey(const fl::FloatImage& visibility, const fl::FloatImage& mask) {
    fl::ByteImage out = fl::visibilityToGrey(visibility);
    for (std::size_t i = 0; i < mask.data.size(); ++i)
        if (!fl::isReceiver(mask, i)) {
            out.data[i * 4] = 70;
            out.data[i * 4 + 1] = 80;
            out.data[i * 4 + 2] = 100;
        }
    return out;
}

void label(fl::ByteImage& tile, const std::vector<std::string>& lines) {
    fl::HudStyle style;
    style.margin = 3;
    fl::rasterizeHud(fl::layoutHud(lines, style), tile);
}

std::string percent(double share) {
    return fl::fixed(100.0 * share, 1) + "%";
}

// Per column: its visibility | the rays' | method - rays (red: too bright, blue: too dark).
fl::ByteImage gridPicture(const std::vector<MethodEntry>& columns,
                          const std::vector<fl::FrameImages>& frames, const fl::FrameImages& truth,
                          const std::vector<Score>& scores, const std::string& truthName) {
    std::vector<fl::ByteImage> tiles;
    for (std::size_t c = 0; c < columns.size(); ++c) {
        const fl::FloatImage& mask = truth.receivers;
        tiles.push_back(receiverGrey(frames[c].visibility, mask));
        label(tiles.back(), {columns[c].label, "RMSE " + fl::fixed(scores[c].error.rmse, 4)});
        tiles.push_back(receiverGrey(truth.visibility, mask));
        label(tiles.back(), {truthName});
        tiles.push_back(
            fl::signedDifferencePicture(frames[c].visibility, truth.visibility, 0.5f, mask));
        label(tiles.back(),
              {columns[c].label + " - rays (+-0.5)",
               "leak " + percent(scores[c].leaks.leak) + " dark " + percent(scores[c].leaks.dark)});
    }
    return fl::tileGrid(tiles, 3);
}

// Each receiver's ErrorPart, from the truth's surfaces (row 0 at the top, as readFrame gives).
std::vector<ErrorPart> errorParts(const fl::BiasMasks& masks) {
    const int w = masks.contact.width, h = masks.contact.height;
    std::vector<ErrorPart> part(static_cast<std::size_t>(w) * h, kElsewhere);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * w + x;
            bool contact = false;
            for (int dy = -fl::kContactReach; dy <= fl::kContactReach && !contact; ++dy)
                for (int dx = -fl::kContactReach; dx <= fl::kContactReach && !contact; ++dx) {
                    const int qx = x + dx, qy = y + dy;
                    contact = qx >= 0 && qy >= 0 && qx < w && qy < h &&
                              masks.contact.data[static_cast<std::size_t>(qy) * w + qx] > 0.5f;
                }
            if (contact)
                part[i] = kNearContact;
            else if (masks.facingLight.data[i] < 0.5f)
                part[i] = kBackFacing;
        }
    return part;
}

std::array<double, 3> errorByPart(const fl::FloatImage& method, const fl::FloatImage& truth,
                                  const fl::FloatImage& receivers,
                                  const std::vector<ErrorPart>& part) {
    std::array<double, 3> sum{};
    std::size_t n = 0;
    for (std::size_t i = 0; i < part.size(); ++i) {
        if (!fl::isReceiver(receivers, i)) continue;
        const double d = double(method.data[i]) - double(truth.data[i]);
        sum[part[i]] += d * d;
        ++n;
    }
    for (double& v : sum) v = n ? std::sqrt(v / double(n)) : 0.0;
    return sum;
}

Score scoreOf(const fl::FrameImages& frame, const fl::FrameImages& truth, const fl::Lane& lane) {
    Score s;
    s.error = fl::compareWithReference(frame.visibility, truth.visibility, truth.receivers);
    s.leaks = fl::shadowLeaks(frame.visibility, truth.visibility, truth.receivers);
    s.medianMs = lane.times.medianFrameMs();
    s.minMs = fl::minimum(lane.times.frameMs());
    s.frames = lane.times.frames();
    return s;
}

// Renders, scores and pictures one model; the pictures are written into the open output set.
ModelResult runModel(const Options& o, const Model& model, const std::vector<MethodEntry>& columns,
                     const fl::gl::ShaderLibrary& shaders) {
    fl::CameraSpec spec;
    spec.kind = fl::CameraSpec::Kind::Auto;
    const fl::CameraView cam = fl::makeCameraView(model.scene, spec, 1.0f);
    std::vector<std::unique_ptr<fl::Renderer>> renderers;
    std::vector<fl::Lane> methods, truths;
    for (const MethodEntry& c : columns) {
        renderers.push_back(std::make_unique<fl::Renderer>(
            shaders, model.scene, settingsOf(o, *c.method, c.flag, c.value)));
        renderers.back()->resize(o.size, o.size);
        (c.method->truth.empty() ? methods : truths)
            .push_back({c.label, renderers.back().get(), {}});
    }
    const fl::MethodDescriptor& rays = fl::groundTruth(fl::kExactTruth);
    fl::Renderer truthRenderer(shaders, model.scene, settingsOf(o, rays, {}, {}));
    truthRenderer.resize(o.size, o.size);
    truths.push_back({std::string(rays.name), &truthRenderer, {}});
    timeLanes(o, model, cam, methods, truths);

    const fl::FrameImages truth = fl::readFrame(truthRenderer);
    const std::vector<ErrorPart> parts = errorParts(fl::biasMasks(
        fl::surfaceGeometry(truthRenderer.surfaces(), cam), truthRenderer.disk().center));
    std::vector<fl::FrameImages> frames;
    ModelResult r;
    std::size_t m = 0, t = 0;
    for (std::size_t c = 0; c < columns.size(); ++c) {
        frames.push_back(fl::readFrame(*renderers[c]));
        const fl::Lane& lane = columns[c].method->truth.empty() ? methods[m++] : truths[t++];
        r.scores.push_back(scoreOf(frames.back(), truth, lane));
        r.scores.back().parts =
            errorByPart(frames.back().visibility, truth.visibility, truth.receivers, parts);
    }
    r.truthMs = truths.back().times.medianFrameMs();
    for (std::size_t c = 0; c < columns.size(); ++c)
        if (columns[c].method->cheapest && columns[c].flag.empty())
            for (Score& s : r.scores) s.xHard = s.medianMs / r.scores[c].medianMs;
    const std::filesystem::path dir(o.out);
    fl::writePng(dir / (model.label + ".grid.png"),
                 gridPicture(columns, frames, truth, r.scores,
                             fl::cat("raytrace ", o.raySamples, " (truth)")));
    fl::writePng(dir / (model.label + ".png"), fl::toSrgb8(truth.color));
    return r;
}

std::string csvOf(const std::vector<Model>& models, const std::vector<ModelResult>& results,
                  const std::vector<MethodEntry>& columns, const Options& o) {
    fl::CsvTable csv({"model",
                      "path",
                      "triangles",
                      "ground_added",
                      "model_radius",
                      "light_radius",
                      "label",
                      "method",
                      "receivers",
                      "penumbra_pixels",
                      "umbra_pixels",
                      "lit_pixels",
                      "rmse",
                      "penumbra_rmse",
                      "leak",
                      "dark",
                      "median_ms",
                      "min_ms",
                      "x_hard",
                      "frames",
                      "raytrace_ms",
                      "rmse_near_contact",
                      "rmse_back_facing",
                      "rmse_elsewhere"});
    for (std::size_t i = 0; i < models.size(); ++i)
        for (std::size_t c = 0; c < columns.size(); ++c) {
            const Model& m = models[i];
            const Score& s = results[i].scores[c];
            csv << m.label << m.path << m.scene.triangleCount() << m.ground << m.radius
                << m.radius * o.lightSize << fl::csvName(columns[c].label)
                << columns[c].method->name << s.error.pixels << s.error.penumbraPixels
                << s.leaks.umbra << s.leaks.lit << s.error.rmse << s.error.rmsePenumbra
                << s.leaks.leak << s.leaks.dark << s.medianMs << s.minMs;
            if (std::isfinite(s.xHard))
                csv << s.xHard;
            else
                csv.blank();
            csv << s.frames << results[i].truthMs << s.parts[kNearContact] << s.parts[kBackFacing]
                << s.parts[kElsewhere];
            csv.endRow();
        }
    return csv.text();
}

// One Markdown table: a row per model, a column per method, each cell from `cell`.
std::string markdownTable(const std::vector<Model>& models, const std::vector<ModelResult>& results,
                          const std::vector<MethodEntry>& columns,
                          const std::function<std::string(const Score&)>& cell) {
    std::ostringstream out;
    out << "| model |";
    for (const MethodEntry& c : columns) out << " " << c.label << " |";
    out << "\n|---|";
    for (std::size_t c = 0; c < columns.size(); ++c) out << "---|";
    out << "\n";
    for (std::size_t i = 0; i < models.size(); ++i) {
        out << "| " << models[i].label << " |";
        for (const Score& s : results[i].scores) out << " " << cell(s) << " |";
        out << "\n";
    }
    return out.str();
}

std::string markdownOf(const std::vector<Model>& models, const std::vector<ModelResult>& results,
                       const std::vector<MethodEntry>& columns, const Options& o) {
    std::ostringstream out;
    out << "Against `raytrace` (" << o.raySamples << " rays) over its receivers; " << o.size << "x"
        << o.size << ", uniform " << o.shadowMap << "^2 map, light radius " << o.lightSize
        << " x the model's bounding radius, `--camera auto`; maps truth " << o.referenceSamples
        << " maps of " << o.referenceMap << "^2.\n\n"
        << "RMSE / leak (share of the truth's umbra, <= 0.05, lit by more than 0.3):\n\n"
        << markdownTable(models, results, columns,
                         [](const Score& s) {
                             return fl::fixed(s.error.rmse, 4) + " / " + percent(s.leaks.leak);
                         })
        << "\nPenumbra RMSE (truth in (0.02, 0.98)) / dark (share of the truth's lit "
           "receivers, >= 0.95, darkened by more than 0.3) / median frame ms:\n\n"
        << markdownTable(models, results, columns,
                         [](const Score& s) {
                             return fl::fixed(s.error.rmsePenumbra, 4) + " / " +
                                    percent(s.leaks.dark) + " / " + fl::fixed(s.medianMs, 1);
                         })
        << "\nWhere the error lies: RMSE parts near a contact / on back-facing triangles / "
           "elsewhere (each the root of its pixels' squared error over all receivers: the "
           "squares add up to the RMSE's square):\n\n"
        << markdownTable(models, results, columns,
                         [](const Score& s) {
                             return fl::fixed(s.parts[kNearContact], 4) + " / " +
                                    fl::fixed(s.parts[kBackFacing], 4) + " / " +
                                    fl::fixed(s.parts[kElsewhere], 4);
                         })
        << "\n| model | file | triangles | ground added | bounding radius | raytrace ms |\n"
        << "|---|---|---|---|---|---|\n";
    for (std::size_t i = 0; i < models.size(); ++i)
        out << "| " << models[i].label << " | " << models[i].path << " | "
            << models[i].scene.triangleCount() << " | " << (models[i].ground ? "yes" : "no")
            << " | " << models[i].radius << " | " << fl::fixed(results[i].truthMs, 0) << " |\n";
    return out.str();
}

int runBench(const Options& o) {
    const std::vector<MethodEntry> columns = chosenColumns(o.methods, o.referenceSamples);
    std::vector<Model> models; // every model is loaded before anything renders or is written
    for (const std::string& arg : o.models) {
        models.push_back(loadModel(arg, o.lightSize));
        for (std::size_t i = 0; i + 1 < models.size(); ++i)
            if (models[i].label == models.back().label)
                throw std::invalid_argument("two models labelled '" + models[i].label + "'");
    }
    auto ctx = fl::EglContext::create(false);
    std::cout << "context: " << ctx->description() << "\n";
    const fl::gl::ShaderLibrary shaders;
    fl::makeOutputFolder(o.out, "--out");
    fl::OutputSet outputs;
    std::vector<ModelResult> results;
    for (const Model& m : models) {
        std::cout << "model " << m.label << ": " << m.path << ", " << m.scene.triangleCount()
                  << " triangles, bounding radius " << m.radius << ", light radius "
                  << m.radius * o.lightSize << (m.ground ? ", ground added" : "") << "\n"
                  << std::flush;
        results.push_back(runModel(o, m, columns, shaders));
    }
    const std::filesystem::path dir(o.out);
    const std::string md = markdownOf(models, results, columns, o);
    fl::writeFileAtomically(dir / "real_models.csv", csvOf(models, results, columns, o));
    fl::writeFileAtomically(dir / "real_models.md", md);
    outputs.commit();
    std::cout << "\n"
              << md << "\nwrote " << (dir / "real_models.csv").string() << ", "
              << (dir / "real_models.md").string() << " and per model LABEL.grid.png, LABEL.png\n";
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"real_models_bench: every method against the ray-traced truth on real glTF "
                 "models (issue 41; bench/real_models.sh fetches them)"};
    Options o;
    addOptions(app, o);
    return fl::bench::parseAndRun(app, argc, argv, [&] { return runBench(o); });
}
