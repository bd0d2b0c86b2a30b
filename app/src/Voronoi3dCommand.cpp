// `floodlight voronoi3d`: 3D Voronoi diagrams by jump flooding (thesis §4.6): 3D JFA and its
// variants or the slice-by-slice variant, on the CPU (jfa/Jfa3d.h) or the GPU (jfa_gl/GlJfa3d.h,
// its twin voxel for voxel), with the error voxels counted against the exact diagram, times,
// slice pictures and an EXR volume of distances.

#include <app/Commands.h>
#include <app/Voronoi3dInput.h>
#include <app/Voronoi3dOutput.h>

#include <renderer/context/EglContext.h>

#include <base/InputFile.h>
#include <base/OutputFiles.h>
#include <base/Parallel.h>
#include <base/Stats.h>

#include <jfa/Jfa3d.h>
#include <jfa_gl/GlJfa3d.h>

#include <chrono>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace fl::app {

namespace {

// Largest side of the cube: 512^3 = 2^27 voxels, the thesis' grid. Peak memory measured at 128^3
// (2M voxels, 1000 sites, with the outputs): 28 bytes a voxel on the CPU (site indices, exact
// squared distances, the error count's recorded ones, the EXR's float channels), 47 with
// --backend both on llvmpipe, whose textures (seeds and the ping-pong pair) live in RAM.
constexpr int kMaxSide3d = 512;
constexpr int kCpuBytesPerVoxel3d = 28;
constexpr int kGlBytesPerVoxel3d = 47;
constexpr int kMaxRuns3d = 100;
constexpr int kDefaultPictureSlices = 4;

struct Voronoi3dOptions {
    int size = 64;
    int sites = 100;
    std::uint64_t seed = 1;
    std::string points;
    std::string backend = "gl";
    std::string variant = "jfa";
    bool compare = false;
    int runs = 1;
    int threads = 0;
    std::vector<int> slices;
    std::string out = "captures";
    std::string name = "voronoi3d";
    std::string shaderDir;
};

double elapsedMs(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

std::string msText(double ms) {
    std::ostringstream s;
    s << std::fixed << std::setprecision(2) << ms << " ms";
    return s.str();
}

// "min X ms of R runs, median Y ms", or "X ms" for one run.
std::string timesText(const std::vector<double>& ms) {
    if (ms.size() == 1) return msText(ms.front());
    return "min " + msText(minimum(ms)) + " of " + std::to_string(ms.size()) + " runs, median " +
           msText(median(ms));
}

// One backend's flood of one variant, run `runs` times.
struct Flooded {
    jfa::SiteGrid3 grid;
    std::vector<double> ms;               // the flood (GL: the passes, after a warm-up run)
    std::vector<double> uploadMs, readMs; // GL only: start grid and upload, read-back
};

Flooded floodCpu(const jfa::Flood3dVariant& v, const std::vector<jfa::Site3>& sites, jfa::Extent3 e,
                 const Voronoi3dOptions& o) {
    Flooded f;
    for (int r = 0; r < o.runs; ++r) {
        const auto t0 = std::chrono::steady_clock::now();
        f.grid = jfa::floodVariant3d(v, sites, e, o.threads);
        f.ms.push_back(elapsedMs(t0));
    }
    return f;
}

// Times the start grid and its upload, the passes and the read-back apart, after one untimed
// warm-up run (the shader's compilation and the textures' allocation are not the flood).
Flooded floodGl(jfa::GlJfa3d& kernel, const jfa::Flood3dVariant& v,
                const std::vector<jfa::Site3>& sites, jfa::Extent3 e, const Voronoi3dOptions& o) {
    const jfa::Plan plan = jfa::variantPlan(v, e);
    Flooded f;
    f.grid = jfa::glFloodVariant3d(kernel, v, sites, e); // warm-up
    glFinish();
    for (int r = 0; r < o.runs; ++r) {
        auto t0 = std::chrono::steady_clock::now();
        kernel.upload(sites, jfa::startGrid3d(sites, e, v.shape, o.threads));
        glFinish();
        f.uploadMs.push_back(elapsedMs(t0));
        t0 = std::chrono::steady_clock::now();
        kernel.run(plan, v.shape);
        glFinish();
        f.ms.push_back(elapsedMs(t0));
        t0 = std::chrono::steady_clock::now();
        f.grid = kernel.read();
        f.readMs.push_back(elapsedMs(t0));
    }
    return f;
}

std::size_t differingVoxels(const jfa::SiteGrid3& a, const jfa::SiteGrid3& b) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < a.cells.size(); ++i) n += a.cells[i] != b.cells[i];
    return n;
}

// The sites of --points or --sites; file problems are bad input (exit 1), a count that does not
// fit the grid a usage error (exit 2).
std::vector<jfa::Site3> makeSites(const Voronoi3dOptions& o, jfa::Extent3 e, std::string& what) {
    if (!o.points.empty()) {
        try {
            const std::string text = readInputFile(o.points, "--points", kTextInputLimitMiB);
            std::vector<jfa::Site3> sites = parseSites3d(text, "--points " + o.points, o.size);
            what = std::to_string(sites.size()) + " sites from " + o.points;
            return sites;
        } catch (const std::invalid_argument& ex) {
            throw InputError(ex.what());
        }
    }
    if (std::size_t(o.sites) > e.voxels())
        throw UsageError("--sites: " + std::to_string(o.sites) + " distinct sites do not fit a " +
                         std::to_string(o.size) + "^3 grid of " + std::to_string(e.voxels()) +
                         " voxels");
    what = std::to_string(o.sites) + " random sites (seed " + std::to_string(o.seed) + ")";
    return jfa::randomSites3d(o.sites, e, o.seed);
}

std::vector<int> pictureSlices(const Voronoi3dOptions& o) {
    if (o.slices.empty()) return evenlySpacedSlices(o.size, kDefaultPictureSlices);
    for (int z : o.slices)
        if (z < 0 || z >= o.size)
            throw UsageError("--slices: slice " + std::to_string(z) + " is outside the " +
                             std::to_string(o.size) + "^3 grid (0.." + std::to_string(o.size - 1) +
                             ")");
    return o.slices;
}

// The GL context, its kernel and the grid check against the driver's 3D texture limit.
struct GlSide {
    std::unique_ptr<EglContext> context;
    std::unique_ptr<gl::ShaderLibrary> shaders;
    std::unique_ptr<jfa::GlJfa3d> kernel;
};

GlSide makeGl(const Voronoi3dOptions& o, jfa::Extent3 e) {
    GlSide gl;
    gl.context = EglContext::create();
    try {
        jfa::checkGlExtent3d(e);
    } catch (const std::invalid_argument& ex) {
        throw UsageError(std::string("--size: ") + ex.what());
    }
    gl.shaders = std::make_unique<gl::ShaderLibrary>(
        o.shaderDir.empty() ? gl::ShaderLibrary() : gl::ShaderLibrary(o.shaderDir));
    gl.kernel = std::make_unique<jfa::GlJfa3d>(*gl.shaders);
    return gl;
}

// Floods one variant on the backends asked for, prints times and errors; returns the result to
// picture (GL's where GL ran) and whether GL and CPU disagreed.
jfa::SiteGrid3 runVariant(const jfa::Flood3dVariant& v, const std::vector<jfa::Site3>& sites,
                          const std::vector<std::int64_t>& exact, jfa::Extent3 e,
                          const Voronoi3dOptions& o, jfa::GlJfa3d* gl, bool& disagreed) {
    const bool cpu = o.backend != "gl";
    const jfa::Plan plan = jfa::variantPlan(v, e);
    const std::vector<int>& steps = plan.stages().front().steps;
    std::cout << v.label << ": steps";
    for (int k : steps) std::cout << " " << k;
    std::cout << " (" << steps.size() << " passes, "
              << (v.shape == jfa::Flood3dShape::Volume ? "27 reads a voxel"
                                                       : "each z slice apart, 9 reads a voxel")
              << ")\n";
    Flooded c, g;
    if (cpu) {
        c = floodCpu(v, sites, e, o);
        std::cout << "  CPU: " << timesText(c.ms) << "\n";
    }
    if (gl) {
        g = floodGl(*gl, v, sites, e, o);
        std::cout << "  GL: " << timesText(g.ms) << " passes; + " << msText(median(g.uploadMs))
                  << " start grid and upload, + " << msText(median(g.readMs))
                  << " read-back (medians)\n";
    }
    std::size_t differ = 0;
    if (cpu && gl) {
        differ = differingVoxels(c.grid, g.grid);
        disagreed = disagreed || differ > 0;
        std::cout << "  GL == CPU: "
                  << (differ == 0 ? std::string("identical, voxel for voxel")
                                  : "NO, " + std::to_string(differ) + " voxels differ")
                  << "\n";
    }
    // One error line per distinct result: both backends' only where they differ.
    for (const Flooded* f : {&c, &g}) {
        if (f->ms.empty() || (f == &g && cpu && differ == 0)) continue;
        const std::string who = differ > 0 ? (f == &c ? "CPU " : "GL ") : "";
        std::cout << "  " << who << jfa::countErrors3d(f->grid, sites, exact, v.label).describe()
                  << "\n";
    }
    return gl ? std::move(g.grid) : std::move(c.grid);
}

int runVoronoi3d(const Voronoi3dOptions& o) {
    const jfa::Extent3 e{o.size, o.size, o.size};
    GlSide gl;
    if (o.backend != "cpu") gl = makeGl(o, e);
    std::string what;
    const std::vector<jfa::Site3> sites = makeSites(o, e, what);
    const std::vector<int> slices = pictureSlices(o);
    const std::string glName = gl.context ? "GL (" + gl::rendererName() + ")" : "";
    std::cout << "input: " << what << " on " << o.size << "x" << o.size << "x" << o.size
              << ", backend "
              << (o.backend == "both" ? "CPU and " + glName
                  : o.backend == "gl" ? glName
                                      : "CPU")
              << ", CPU threads " << resolveThreads(o.threads) << "\n";
    const auto t0 = std::chrono::steady_clock::now();
    const std::vector<std::int64_t> exact = jfa::exactSquaredDistances3d(sites, e, o.threads);
    std::cout << "exact reference (separable EDT, CPU): " << msText(elapsedMs(t0)) << "\n";

    std::vector<const jfa::Flood3dVariant*> variants;
    if (o.compare)
        for (const jfa::Flood3dVariant& v : jfa::flood3dVariants()) variants.push_back(&v);
    else
        variants.push_back(jfa::findFlood3dVariant(o.variant));
    OutputSet outputs; // the PNGs and the EXR appear together or not at all
    std::ostringstream wrote;
    bool disagreed = false;
    for (const jfa::Flood3dVariant* v : variants) {
        const jfa::SiteGrid3 grid = runVariant(*v, sites, exact, e, o, gl.kernel.get(), disagreed);
        if (!o.compare) writeVoronoi3d(o.out, o.name, {grid, sites, exact}, slices, wrote);
    }
    outputs.commit();
    std::cout << wrote.str();
    if (disagreed) std::cerr << "error: the GL and CPU kernels disagree (a bug; please report)\n";
    return disagreed ? 1 : 0;
}

std::string variantHelp() {
    std::string text = "Variant:";
    for (const jfa::Flood3dVariant& v : jfa::flood3dVariants())
        text += std::string(" ") + v.name + " (" + v.label + ")";
    return text + "; slices floods every z slice from the sites projected onto it (thesis §4.6.2)";
}

std::vector<std::string> variantNames() {
    std::vector<std::string> names;
    for (const jfa::Flood3dVariant& v : jfa::flood3dVariants()) names.emplace_back(v.name);
    return names;
}

} // namespace

Runner addVoronoi3dCommand(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand(
        "voronoi3d", "3D Voronoi diagram by jump flooding (3D JFA or slice by slice), errors vs "
                     "exact, CPU or GL");
    auto o = std::make_shared<Voronoi3dOptions>();
    cmd->add_option("--size", o->size,
                    "Grid side S: an S^3 grid, S in 1.." + std::to_string(kMaxSide3d) +
                        " (memory: about " + std::to_string(kCpuBytesPerVoxel3d) +
                        " bytes a voxel on the CPU, " + std::to_string(kGlBytesPerVoxel3d) +
                        " with GL on a software rasteriser: 3.8 / 6.3 GB at 512^3; with GL also "
                        "at most GL_MAX_3D_TEXTURE_SIZE)")
        ->check(integer(1, kMaxSide3d))
        ->capture_default_str();
    cmd->add_option("--sites", o->sites,
                    "Random sites at distinct voxels (1.." + std::to_string(kMaxSites3d) +
                        ", at most S^3)")
        ->check(integer(1, kMaxSites3d))
        ->capture_default_str();
    cmd->add_option("--seed", o->seed, "Random seed")->capture_default_str();
    cmd->add_option("--points", o->points,
                    "Text file of sites instead, 'x y z' per line: integers in 0..S-1, no "
                    "duplicates, # comments (at most " +
                        std::to_string(kTextInputLimitMiB) + " MiB and " +
                        std::to_string(kMaxSites3d) + " sites; a site's id is its line order)");
    cmd->add_option("--backend", o->backend,
                    "gl, cpu, or both (both also checks GL == CPU voxel for voxel)")
        ->check(CLI::IsMember({"gl", "cpu", "both"}))
        ->capture_default_str();
    cmd->add_option("--variant", o->variant, variantHelp())
        ->check(CLI::IsMember(variantNames()))
        ->capture_default_str();
    cmd->add_flag("--compare", o->compare, "Run every variant; print times and errors, no files");
    cmd->add_option("--runs", o->runs,
                    "Time each flood this many times (1.." + std::to_string(kMaxRuns3d) +
                        "): min and median")
        ->check(integer(1, kMaxRuns3d))
        ->capture_default_str();
    cmd->add_option("--threads", o->threads, "CPU threads (0: one per hardware thread)")
        ->check(integer(0, 256))
        ->capture_default_str();
    cmd->add_option("--slices", o->slices,
                    "z slices to picture, e.g. 8,32 (at most " +
                        std::to_string(kMaxPictureSlices3d) + "; default " +
                        std::to_string(kDefaultPictureSlices) + " evenly spaced)")
        ->delimiter(',')
        ->expected(1, kMaxPictureSlices3d)
        ->check(integer(0, kMaxSide3d - 1));
    addOutOption(*cmd, o->out, "Output folder");
    addNameOption(*cmd, o->name,
                  "Output name stem: NAME.zZ.png per slice, NAME.montage.png, and NAME.exr: one "
                  "S x S*S float image, the z slices stacked top to bottom (z = 0 on top, each "
                  "slice y up), channels site.id, distance, exact_distance, error");
    cmd->add_option("--shader-dir", o->shaderDir, "Load shaders from this folder");
    return [o] { return runVoronoi3d(*o); };
}

} // namespace fl::app
