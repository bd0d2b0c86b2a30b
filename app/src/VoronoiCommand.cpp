// `floodlight voronoi`: Voronoi diagrams and distance transforms by jump flooding (thesis ch. 4),
// on the GPU or the CPU, with errors counted against the exact diagram; with --exact the flood
// is then repaired to that exact diagram (jfa/ExactRepair.h).

#include <app/Commands.h>

#include <io/ImageIO.h>
#include <io/MaskImage.h>
#include <renderer/context/EglContext.h>

#include <base/InputFile.h>
#include <base/OutputFiles.h>

#include <geometry/SiteGraph.h>

#include <jfa/CpuKernel.h>
#include <jfa/DistanceTransform.h>
#include <jfa/ErrorAnalysis.h>
#include <jfa/ExactRepair.h>
#include <jfa/Plan.h>
#include <jfa/Reference.h>
#include <jfa/Sites.h>
#include <jfa_gl/GlExactRepair.h>
#include <jfa_gl/GlKernel.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

namespace fl::app {

namespace {

struct VoronoiOptions {
    int width = 512, height = 512;
    int sites = 100;
    std::uint64_t seed = 1;
    bool floatSites = false;
    std::string points, mask, labels;
    std::string plan = "jfa";
    std::string backend = "gl";
    std::string kernel = "fragment";
    std::string floodRegion = "band";
    bool compare = false;
    bool exact = false;
    std::string out = "captures";
    std::string name = "voronoi";
    std::string shaderDir;
};

// Reads "x y" per line (blank lines and # comments skipped); names file and line on errors.
// Regular files within kTextInputLimitMiB only (base/InputFile.h): a FIFO would be read forever.
std::vector<jfa::Site> readPoints(const std::string& file) {
    std::istringstream in(readInputFile(file, "--points", kTextInputLimitMiB));
    std::vector<jfa::Site> out;
    std::map<std::pair<float, float>, int> seen; // position -> line, to name duplicates
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
        if (line.find_first_not_of(" \t\r") == std::string::npos || line[0] == '#') continue;
        std::istringstream s(line);
        double x = 0, y = 0;
        if (!(s >> x >> y) || !std::isfinite(x) || !std::isfinite(y))
            throw InputError("--points " + file + ":" + std::to_string(n) +
                             ": expected two finite numbers 'x y'");
        const auto [it, added] = seen.try_emplace({float(x), float(y)}, n);
        if (!added)
            throw InputError("--points " + file + ":" + std::to_string(n) +
                             ": duplicate of the site on line " + std::to_string(it->second));
        out.push_back({float(x), float(y)});
    }
    if (out.empty()) throw InputError("--points " + file + ": no sites");
    return out;
}

struct Input {
    jfa::Grid seeds;
    bool integer = true;
    std::vector<std::uint8_t> mask; // for masks: the binary image (distance transforms)
    std::string what;
};

Input makeInput(const VoronoiOptions& o) {
    Input in;
    if (!o.mask.empty()) {
        const ByteImage img = [&] {
            try {
                return readPng(o.mask, "--mask");
            } catch (const std::exception& e) {
                throw InputError(e.what());
            }
        }();
        in.mask = maskGrid(img);
        std::vector<std::int32_t> labels;
        if (!o.labels.empty()) {
            const ByteImage lab = readPng(o.labels, "--labels");
            if (lab.width != img.width || lab.height != img.height)
                throw InputError(o.labels + ": label image size differs from the mask's");
            labels = labelGrid(lab);
        }
        in.seeds =
            jfa::seedMask(in.mask, img.width, img.height, labels.empty() ? nullptr : &labels);
        in.what =
            o.mask + " (" + std::to_string(img.width) + "x" + std::to_string(img.height) + ")";
        return in;
    }
    std::vector<jfa::Site> sites;
    if (!o.points.empty())
        sites = readPoints(o.points);
    else if (o.floatSites)
        sites = jfa::randomFloatSites(o.sites, o.width, o.height, o.seed);
    else if (std::int64_t(o.sites) > std::int64_t(o.width) * o.height)
        throw InputError("--sites: " + std::to_string(o.sites) + " distinct sites do not fit a " +
                         std::to_string(o.width) + "x" + std::to_string(o.height) +
                         " grid (use --float-sites, or a larger grid)");
    else
        sites = jfa::randomIntegerSites(o.sites, o.width, o.height, o.seed);
    in.integer = !o.floatSites;
    try {
        const jfa::SeedResult r = jfa::seedPoints(sites, o.width, o.height, in.integer);
        in.seeds = r.grid;
        if (!r.missing.empty())
            std::cerr << "note: " << r.missing.size()
                      << " site(s) share a pixel with a nearer site "
                      << "and are not flooded (first: site " << r.missing.front() << ")\n";
    } catch (const std::invalid_argument& e) {
        throw InputError((o.points.empty() ? std::string("sites") : o.points) + ": " + e.what());
    }
    in.what = std::to_string(sites.size()) + (in.integer ? " integer" : " sub-pixel") + " sites";
    return in;
}

// --exact: the site graph, built before the flood (it tags the seeds with start vertices), and
// the repair's GL twin on the GL backend.
struct Repair {
    jfa::SiteGraph graph;
    double graphMs = 0;
    std::unique_ptr<jfa::GlExactRepair> gl;
};

struct Run {
    jfa::Grid grid;
    double ms = 0;
    jfa::Grid repaired; // with a Repair: the flood repaired to the exact diagram
    double repairMs = 0;
    bool banded = false;      // ran over a band, not the whole grid
    double activeShare = 1.0; // of the full-resolution texels
};

double msSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// Floods with the GL kernel (timed after a warm-up run) or the CPU one, over `region`, then with
// `repair` repairs the result (timed on its own).
Run flood(const jfa::Plan& plan, const jfa::Grid& seeds, const jfa::NearestSite& crit,
          jfa::GlFloodKernel<jfa::NearestSite>* gl, jfa::FloodRegion region, const Repair* repair) {
    Run r;
    if (gl) {
        gl->setRegion(region);
        const gl::Texture in = jfa::uploadGrid(seeds);
        // Warm-up: shader compilation and allocation are not the flood (nor the repair).
        const gl::Texture& warm = gl->run(plan, in, crit);
        if (repair) repair->gl->run(warm);
        glFinish();
        auto t0 = std::chrono::steady_clock::now();
        const gl::Texture& out = gl->run(plan, in, crit);
        glFinish();
        r.ms = msSince(t0);
        if (repair) {
            t0 = std::chrono::steady_clock::now();
            const gl::Texture& fixed = repair->gl->run(out);
            glFinish();
            r.repairMs = msSince(t0);
            r.repaired = jfa::readGrid(fixed);
        }
        r.grid = jfa::readGrid(out);
        r.banded = gl->lastRunBanded();
        r.activeShare = gl->activeShare();
    } else {
        jfa::FloodOptions options;
        options.region = region;
        const auto t0 = std::chrono::steady_clock::now();
        jfa::FloodResult f = jfa::floodWithStats(plan, seeds, crit, options);
        r.ms = msSince(t0);
        r.grid = std::move(f.grid);
        r.activeShare = f.activeShare;
        r.banded = f.activeShare < 1.0;
        if (repair) {
            r.repaired = r.grid;
            const auto t1 = std::chrono::steady_clock::now();
            jfa::repairNearest(r.repaired, repair->graph);
            r.repairMs = msSince(t1);
        }
    }
    return r;
}

// "wrote ..." lines go to `log`, printed once the command's OutputSet has committed.
void writeOutputs(const VoronoiOptions& o, const jfa::Grid& g, const jfa::ExactField& exact,
                  const std::vector<std::uint8_t>& errors, const jfa::NearestSite& crit,
                  std::ostream& log) {
    const int w = g.width, h = g.height;
    ByteImage pic{w, h, 4, std::vector<std::uint8_t>(size_t(w) * size_t(h) * 4)};
    std::vector<ExrChannel> ch{{"site.x", {}},   {"site.y", {}},         {"site.id", {}},
                               {"distance", {}}, {"exact_distance", {}}, {"error", {}}};
    for (auto& c : ch) c.values.resize(size_t(w) * size_t(h));
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const size_t src = size_t(y) * size_t(w) + size_t(x);
            const size_t dst = size_t(h - 1 - y) * size_t(w) + size_t(x); // files: top row first
            const jfa::Cell& c = g.cells[src];
            auto rgb = regionColour(std::int64_t(std::max(c.z, 0.0f)));
            if (errors[src]) rgb = {255, 0, 0};
            if (!crit.empty(c) && jfa::pixelOf(c.x) == x && jfa::pixelOf(c.y) == y) rgb = {0, 0, 0};
            for (int k = 0; k < 3; ++k) pic.data[dst * 4 + size_t(k)] = rgb[size_t(k)];
            pic.data[dst * 4 + 3] = 255;
            ch[0].values[dst] = c.x;
            ch[1].values[dst] = c.y;
            ch[2].values[dst] = c.z;
            ch[3].values[dst] =
                crit.empty(c) ? 0.0f : float(std::sqrt(jfa::squaredDistance(crit, x, y, c)));
            ch[4].values[dst] = float(std::sqrt(exact.at(x, y)));
            ch[5].values[dst] = errors[src] ? 1.0f : 0.0f;
        }
    }
    const std::filesystem::path dir = o.out;
    writePng(dir / (o.name + ".png"), pic);
    std::vector<ExrChannel> exr;
    for (auto& c : ch) exr.push_back({c.name, std::move(c.values)});
    writeExr(dir / (o.name + ".exr"), w, h, exr);
    log << "wrote " << (dir / (o.name + ".png")).string() << " (regions by site, sites black, "
        << "errors red)\nwrote " << (dir / (o.name + ".exr")).string()
        << " (site.x, site.y, site.id, distance, exact_distance, error)\n";
}

// Grid sizes the kernels can take: 1 .. 16384 (integer distances in 32 bits on the GPU), and
// with the GL backend no more than the implementation's largest texture.
constexpr int kMaxGridSide = 16384;

void checkGridSize(int w, int h, const std::string& what, bool gl) {
    const int glMax = gl ? gl::maxTextureSize() : kMaxGridSide;
    const int limit = std::min(kMaxGridSide, glMax);
    if (w < 1 || h < 1 || w > limit || h > limit)
        throw InputError(what + ": grid " + std::to_string(w) + "x" + std::to_string(h) +
                         " is outside 1.." + std::to_string(limit) + " per side" +
                         (gl ? " (GL maximum texture size here: " + std::to_string(glMax) + ")"
                             : std::string()));
}

// --exact refuses what it cannot repair (usage errors, exit 2): sub-pixel sites, whose float
// distances the proof does not cover, and --compare, which runs every plan.
void checkExactOptions(const VoronoiOptions& o) {
    if (!o.exact) return;
    if (o.floatSites)
        throw UsageError("--exact: sub-pixel sites (--float-sites) cannot be repaired exactly; "
                         "the repair is proven for integer sites (--sites, --points, --mask)");
    if (o.compare)
        throw UsageError("--exact repairs one plan's flood and --compare runs every plan: use one "
                         "of them");
}

// The repair starts each walk from the flood's answer; a plan that cannot reach every texel
// (flood:N with small N) leaves texels whose walks would start from an arbitrary site.
void checkRepairablePlan(const jfa::Plan& plan) {
    const long long need = std::max(plan.width(), plan.height()) - 1;
    if (plan.maxReach() < need)
        throw UsageError("--exact: plan " + plan.name() + " reaches " +
                         std::to_string(plan.maxReach()) + " texels, fewer than the " +
                         std::to_string(need) +
                         " of this grid; the repair needs a plan that "
                         "floods every texel (jfa, jfa+1, 1+jfa, jfa2, half:jfa, ...)");
}

// Builds the site graph of `seeds` from their `sites` (tagging the seeds) and, on GL, uploads it.
std::unique_ptr<Repair> prepareRepair(jfa::Grid& seeds, const std::vector<jfa::Cell>& sites,
                                      const gl::ShaderLibrary* shaders) {
    auto repair = std::make_unique<Repair>();
    const auto t0 = std::chrono::steady_clock::now();
    repair->graph = geom::buildSiteGraph(seeds, sites);
    if (shaders) {
        repair->gl = std::make_unique<jfa::GlExactRepair>(*shaders);
        repair->gl->setGraph(repair->graph);
    }
    repair->graphMs = msSince(t0);
    return repair;
}

// The lines --exact adds under a plan's: the repair's cost and its errors, counted as the
// plan's are.
void reportRepair(const Repair& repair, const Run& r, const jfa::ExactDiagramView& view) {
    std::int64_t changed = 0;
    for (std::size_t i = 0; i < r.grid.cells.size(); ++i)
        changed += !(r.grid.cells[i] == r.repaired.cells[i]);
    const jfa::ErrorReport rep = jfa::analyzeErrors(r.repaired, view, "exact");
    std::cout << std::fixed << std::setprecision(2) << "exact repair: site graph of "
              << repair.graph.vertices.size() << " boundary sites, greedy walks; " << changed
              << " texels changed\n  " << repair.graphMs << " ms graph + " << r.ms << " ms flood + "
              << r.repairMs << " ms repair = " << repair.graphMs + r.ms + r.repairMs << " ms; "
              << rep.describe() << "\n"
              << std::defaultfloat;
}

// The mask's signed distance transform, as the plan floods it on the CPU, or with --exact from
// the repaired diagram and the repaired flood of the outside pixels.
jfa::DistanceField maskDistances(const std::vector<std::uint8_t>& mask, int w, int h,
                                 const jfa::Plan& plan, const jfa::Grid* repairedInside) {
    if (!repairedInside) return jfa::signedDistanceTransform(mask, w, h, plan);
    jfa::Grid outside = jfa::seedMask(jfa::invertedMask(mask), w, h);
    const jfa::SiteGraph graph = geom::buildSiteGraph(outside);
    jfa::Grid nearestOutside = jfa::flood(plan, outside, jfa::NearestSite{true});
    jfa::repairNearest(nearestOutside, graph);
    return jfa::signedDistanceFromNearest(mask, *repairedInside, nearestOutside);
}

// The mask's signed distance transform on the CPU kernel (with --exact, repaired), against the
// exact one, written as NAME.sdf.exr.
void writeMaskDistances(const VoronoiOptions& o, const std::vector<std::uint8_t>& mask, int w,
                        int h, const jfa::Grid* repairedInside, std::ostream& wrote) {
    const jfa::Plan plan = jfa::parsePlan(o.plan, w, h);
    const jfa::DistanceField sd = maskDistances(mask, w, h, plan, repairedInside);
    const jfa::DistanceField ex = jfa::exactSignedDistanceTransform(mask, w, h);
    std::cout << "signed distance transform (" << plan.name()
              << (repairedInside ? " + exact repair" : "")
              << ", CPU): " << jfa::countDifferences(sd, ex)
              << " pixels differ from the exact one\n";
    std::vector<float> flipped(sd.values.size());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            flipped[size_t(h - 1 - y) * size_t(w) + size_t(x)] = sd.at(x, y);
    // Every value is finite: where the mask has no outside (every pixel a site) or no inside
    // pixel, the nearest pixel of the other kind lies beyond the grid and the field holds
    // -/+ hypot(W, H) (jfa/DistanceTransform.h); an inf here became NaN in renderers.
    const auto all = std::count(mask.begin(), mask.end(), std::uint8_t{1});
    if (all == 0 || std::size_t(all) == mask.size())
        std::cout << "note: the mask has no " << (all == 0 ? "inside" : "outside")
                  << " pixel: signed_distance is " << (all == 0 ? "+" : "-")
                  << jfa::noFeatureDistance(w, h) << " (hypot(width, height)) everywhere\n";
    const auto path = std::filesystem::path(o.out) / (o.name + ".sdf.exr");
    writeExr(path, w, h, {{"signed_distance", flipped}});
    wrote << "wrote " << path.string() << " (negative inside the mask)\n";
}

int runVoronoi(const VoronoiOptions& o) {
    checkExactOptions(o);
    std::unique_ptr<EglContext> ctx;
    if (o.backend == "gl") ctx = EglContext::create();
    if (o.mask.empty()) checkGridSize(o.width, o.height, "--width/--height", bool(ctx));
    const Input in = makeInput(o);
    const int w = in.seeds.width, h = in.seeds.height;
    checkGridSize(w, h, in.what, bool(ctx));
    if (jfa::siteCells(in.seeds).empty()) throw InputError(in.what + ": no sites to flood");
    const jfa::NearestSite crit{in.integer};
    const jfa::ExactField exact = jfa::exactNearest(in.seeds, crit);
    const std::vector<jfa::Cell> siteList = jfa::siteCells(in.seeds);
    const jfa::ExactDiagramView view{w, h, siteList, exact.distSq, in.integer};
    jfa::Grid seeds = in.seeds; // with --exact, tagged with the walks' start vertices

    std::unique_ptr<gl::ShaderLibrary> shaders;
    std::unique_ptr<jfa::GlFloodKernel<jfa::NearestSite>> kernel;
    if (o.backend == "gl") {
        shaders = std::make_unique<gl::ShaderLibrary>(
            o.shaderDir.empty() ? gl::ShaderLibrary() : gl::ShaderLibrary(o.shaderDir));
        kernel = std::make_unique<jfa::GlFloodKernel<jfa::NearestSite>>(
            *shaders,
            o.kernel == "compute" ? jfa::GlKernelKind::Compute : jfa::GlKernelKind::Fragment);
    }
    std::unique_ptr<Repair> repair;
    if (o.exact) repair = prepareRepair(seeds, siteList, shaders.get());
    jfa::Grid repairedInside; // --exact with --mask: the repaired diagram, for the SDF
    const std::string backend = o.backend == "gl" ? "GL " + o.kernel : std::string("CPU");
    std::cout << "input: " << in.what << " on " << w << "x" << h << ", backend " << backend << "\n";

    // The .png, .exr and .sdf.exr appear together or not at all (base/OutputFiles.h).
    OutputSet outputs;
    std::ostringstream wrote;
    std::vector<std::string> specs{o.plan};
    if (o.compare)
        specs = {"jfa",     "jfa+1",    "jfa+2",    "jfa2",       "1+jfa",
                 "1+jfa+1", "doubling", "half:jfa", "half:jfa+2", "flood"};
    for (const std::string& spec : specs) {
        jfa::Plan plan = [&] {
            try {
                return jfa::parsePlan(spec, w, h);
            } catch (const std::invalid_argument& e) {
                throw InputError(std::string("--plan: ") + e.what());
            }
        }();
        if (o.exact) checkRepairablePlan(plan);
        const jfa::FloodRegion region = *jfa::parseFloodRegion(o.floodRegion);
        Run r = flood(plan, seeds, crit, kernel.get(), region, repair.get());
        const jfa::ErrorReport rep = jfa::analyzeErrors(r.grid, view, plan.name());
        std::cout << std::fixed << std::setprecision(2) << plan.describe() << "\n  " << r.ms
                  << " ms; " << rep.describe() << "\n"
                  << std::defaultfloat;
        // The band (jfa/Band.h) bounds a plan by its reach: said once per plan when it could not.
        if (region == jfa::FloodRegion::Band && r.banded)
            std::cout << "  flood region: band, " << std::setprecision(3) << 100.0 * r.activeShare
                      << "% of the texels\n"
                      << std::defaultfloat;
        else if (region == jfa::FloodRegion::Band)
            std::cout << "  flood region: full (every tile lies within the plan's reach of "
                      << jfa::planBandReach(plan) << " texels from a site)\n";
        if (repair) reportRepair(*repair, r, view);
        const jfa::Grid& result = repair ? r.repaired : r.grid;
        if (!o.compare)
            writeOutputs(o, result, exact, jfa::errorPixelMask(result, view), crit, wrote);
        if (repair && !in.mask.empty()) repairedInside = std::move(r.repaired);
    }
    if (!in.mask.empty() && !o.compare)
        writeMaskDistances(o, in.mask, w, h, repair ? &repairedInside : nullptr, wrote);
    outputs.commit();
    std::cout << wrote.str();
    return 0;
}

} // namespace

Runner addVoronoiCommand(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand(
        "voronoi", "Voronoi diagram / distance transform by jump flooding, errors vs exact");
    auto o = std::make_shared<VoronoiOptions>();
    cmd->add_option("--width", o->width,
                    "Grid width (1.." + std::to_string(kMaxGridSide) + ", at most the GL maximum)")
        ->check(integer(1, kMaxGridSide))
        ->capture_default_str();
    cmd->add_option("--height", o->height,
                    "Grid height (1.." + std::to_string(kMaxGridSide) + ", at most the GL maximum)")
        ->check(integer(1, kMaxGridSide))
        ->capture_default_str();
    cmd->add_option("--sites", o->sites, "Random sites")
        ->check(integer(1, 1 << 24))
        ->capture_default_str();
    cmd->add_option("--seed", o->seed, "Random seed")->capture_default_str();
    cmd->add_flag("--float-sites", o->floatSites, "Sub-pixel random sites (float distances)");
    const std::string pngLimit = " (at most " + std::to_string(kImageInputLimitMiB) + " MiB and " +
                                 std::to_string(kMaxPngSide) + " pixels per side)";
    cmd->add_option("--points", o->points,
                    "Text file of sites, 'x y' per line (grid coordinates; at most " +
                        std::to_string(kTextInputLimitMiB) + " MiB)");
    cmd->add_option("--mask", o->mask,
                    "PNG whose bright pixels are generalized sites (sets the size)" + pngLimit);
    cmd->add_option("--labels", o->labels,
                    "PNG giving each mask pixel a region id by colour" + pngLimit);
    cmd->add_option("--flood-region", o->floodRegion,
                    "band: compute only the tiles within the plan's reach of a site (the same "
                    "result, texel for texel; a plan that reaches every texel runs full); full: "
                    "every texel")
        ->check(CLI::IsMember({"band", "full"}))
        ->capture_default_str();
    cmd->add_option("--plan", o->plan,
                    "Flood plan: jfa, jfa+1, jfa+2, jfa2, 1+jfa, 1+jfa+1, doubling, flood, "
                    "flood:N (N <= " +
                        std::to_string(jfa::kMaxFloodPasses) + "), half:jfa, half:jfa+2, ...")
        ->capture_default_str();
    cmd->add_option("--backend", o->backend, "gl or cpu")
        ->check(CLI::IsMember({"gl", "cpu"}))
        ->capture_default_str();
    cmd->add_option("--kernel", o->kernel, "GL kernel: fragment or compute")
        ->check(CLI::IsMember({"fragment", "compute"}))
        ->capture_default_str();
    cmd->add_flag("--compare", o->compare, "Run every variant and print times and errors");
    cmd->add_flag("--exact", o->exact,
                  "Repair the plan's flood to the exact diagram (0 error pixels): integer sites "
                  "only (--sites, --points, --mask), a plan that floods every texel, not with "
                  "--compare");
    addOutOption(*cmd, o->out, "Output folder");
    addNameOption(*cmd, o->name, "Output name stem: NAME.png, NAME.exr (and NAME.sdf.exr)");
    cmd->add_option("--shader-dir", o->shaderDir, "Load shaders from this folder");
    return [o] { return runVoronoi(*o); };
}

} // namespace fl::app
