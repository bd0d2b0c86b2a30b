// `floodlight delaunay`: the Delaunay triangulation of a point file by the thesis' pipeline
// (ch. 6: discrete Voronoi diagram by 1+JFA, G1-G6, completed exactly on the CPU, C1-C4), with
// the time and counts of every step, an optional exact check, Triangle/OBJ/SVG output and one
// picture per step.

#include <app/Commands.h>
#include <app/DelaunaySteps.h>

#include <base/InputFile.h>
#include <base/OutputFiles.h>
#include <geometry/Delaunay.h>
#include <geometry/MeshIO.h>
#include <geometry/MeshSvg.h>
#include <geometry/PointIO.h>
#include <geometry/Predicates.h>
#include <jfa/CpuKernel.h>
#include <jfa/Plan.h>

// The GL backend arrives separately from this command; without it --backend gl says so.
#if __has_include(<geometry_gl/GlDiscreteDelaunay.h>)
#include <geometry_gl/GlDiscreteDelaunay.h>
#include <gpu/ShaderLibrary.h>
#include <renderer/context/EglContext.h>
#define FLOODLIGHT_HAVE_GL_DELAUNAY 1
#endif

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <utility>

namespace fl::app {

namespace {

struct DelaunayCliOptions {
    std::string input;
    int texture = 0; // 0: defaultTextureSize(points)
    std::string backend = "cpu";
    std::string plan = "1+jfa";
    bool check = false;
    std::string out; // output prefix; empty: no mesh files
    std::string format = "all";
    std::string steps; // picture folder; empty: no pictures
    int threads = 0;
};

std::vector<glm::dvec2> readInput(const std::string& file) {
    try {
        return geom::readPoints(file);
    } catch (const geom::PointFileError& e) {
        throw InputError(e.what()); // already "FILE:LINE: problem"
    }
}

// The pipeline's own checks would catch these too, but only with point indices; here the
// message names the file and says why there is no triangulation.
void requireTriangulable(const std::vector<glm::dvec2>& points, const std::string& file) {
    const glm::dvec2 a = points.front();
    const auto b = std::find_if(points.begin(), points.end(), [&](glm::dvec2 p) { return p != a; });
    const auto c = b == points.end() ? b : std::find_if(b, points.end(), [&](glm::dvec2 p) {
        return p != a && p != *b;
    });
    if (c == points.end()) {
        const int distinct = b == points.end() ? 1 : 2;
        throw InputError(file + ": " + std::to_string(points.size()) + " point(s), " +
                         std::to_string(distinct) +
                         " distinct; a triangulation needs at least 3 distinct points");
    }
    const bool flat = std::all_of(points.begin(), points.end(),
                                  [&](glm::dvec2 p) { return geom::orient2dSign(a, *b, p) == 0; });
    if (flat)
        throw InputError(file + ": all " + std::to_string(points.size()) +
                         " points are collinear; they have no triangulation");
}

// Runs G1-G6 through the GL backend when it is built in; the context lives as long as the
// returned function.
std::function<geom::DiscreteDelaunay(const std::vector<glm::dvec2>&,
                                     const geom::DiscreteDelaunayOptions&)>
glBackend() {
#ifdef FLOODLIGHT_HAVE_GL_DELAUNAY
    // Context, shaders and programs are made once, before the pipeline's clock starts.
    struct Gl {
        std::unique_ptr<EglContext> context = EglContext::create();
        gl::ShaderLibrary shaders;
        geom::GlDiscreteDelaunay steps{shaders};
    };
    auto gl = std::make_shared<Gl>();
    return
        [gl](const std::vector<glm::dvec2>& sites, const geom::DiscreteDelaunayOptions& options) {
            return gl->steps.run(sites, options);
        };
#else
    throw InputError("--backend gl: this build has no GL Delaunay backend; use --backend cpu");
#endif
}

void printTimes(const geom::DelaunayResult& r, double checkMs, std::ostream& out) {
    const geom::DiscreteTimings& g = r.discrete.timings;
    const geom::CpuTimings& c = r.cpu;
    const std::pair<const char*, double> rows[] = {
        {"G1 sites into texture", g.g1},
        {"G2 flood (discrete Voronoi)", g.g2},
        {"G3 island removal", g.g3},
        {"G4 Voronoi vertices", g.g4},
        {"G5 row chains", g.g5},
        {"G6 triangles T'", g.g6},
        {"G1-G6", g.total()},
        {"C1 convex hull", c.c1},
        {"C2 shift sites", c.c2},
        {"C3 insert missing sites", c.c3},
        {"C4 edge flips", c.c4},
        {"C1-C4", c.total()},
        {"total", g.total() + c.total()},
    };
    out << "steps (ms):\n" << std::fixed << std::setprecision(3);
    for (const auto& [name, ms] : rows)
        out << "  " << std::left << std::setw(28) << name << ms << "\n";
    if (checkMs >= 0) out << "  " << std::setw(28) << "check" << checkMs << "\n";
    out << std::defaultfloat << std::right;
}

void printCounts(const geom::DelaunayResult& r, std::ostream& out) {
    const geom::DiscreteDelaunay& d = r.discrete;
    const geom::CpuCounts& c = r.counts;
    out << "counts:\n"
        << "  points: " << r.mesh.points.size() << "\n"
        << "  duplicates: " << c.duplicates << "\n"
        << "  missing sites: " << d.missing().size() << " (lost their pixel in G1)\n"
        << "  islands removed: ";
    if (d.islandsBefore >= 0) out << d.islandsBefore << " components, ";
    out << d.islands.reassigned << " pixels in " << d.islands.passes << " pass(es)\n"
        << "  Voronoi vertices: " << d.mesh.vertices.size() << " (" << d.mesh.stats.threeColour
        << " three-colour, " << d.mesh.stats.fourColour << " four-colour)\n"
        << "  triangles T': " << d.mesh.triangleCount() << "\n"
        << "  hull triangles added: " << c.hullTriangles << "\n"
        << "  shifts: " << c.goodShifts << " good, " << c.badShifts << " bad\n"
        << "  missing inserted: " << c.missingInserted << " (" << c.insertFlips << " flips, "
        << c.walkSteps << " walk steps)\n"
        << "  flips: " << c.flips << "\n"
        << "  triangles: " << r.mesh.triangleCount() << "\n";
}

// "wrote ..." lines go to `log`, printed once the command's OutputSet has committed.
void writeMeshFiles(const DelaunayCliOptions& o, const geom::Triangulation& mesh,
                    std::ostream& log) {
    const std::filesystem::path prefix = o.out;
    if (prefix.has_parent_path()) makeOutputFolder(prefix.parent_path(), "--out");
    auto named = [&](const char* ext) { return std::filesystem::path(prefix.string() + ext); };
    const bool all = o.format == "all";
    if (all || o.format == "node") {
        geom::writeNodeFile(named(".node"), mesh.points);
        geom::writeEleFile(named(".ele"), mesh.points, mesh.triangles);
        log << "wrote " << named(".node").string() << " and " << named(".ele").string()
            << " (Triangle format, 0-based)\n";
    }
    if (all || o.format == "obj") {
        geom::writeObjFile(named(".obj"), mesh.points, mesh.triangles);
        log << "wrote " << named(".obj").string() << "\n";
    }
    if (o.format == "svg" || (all && mesh.points.size() <= kMaxPicturePoints)) {
        try {
            geom::writeSvg(named(".svg"), geom::triangulationPicture(mesh.points, mesh.triangles));
        } catch (const std::invalid_argument& e) { // e.g. an extent beyond a double
            throw InputError(o.input + ": cannot draw " + named(".svg").string() + " (" + e.what() +
                             "); --format node or obj writes the mesh without it");
        }
        log << "wrote " << named(".svg").string() << "\n";
    } else if (all) {
        log << "skipped " << named(".svg").string() << ": more than " << kMaxPicturePoints
            << " points (ask for it with --format svg)\n";
    }
}

void checkPlan(const std::string& plan, int size) {
    try {
        (void)jfa::parsePlan(plan, size, size);
    } catch (const std::invalid_argument& e) {
        throw InputError(std::string("--plan: ") + e.what());
    }
}

int runDelaunay(const DelaunayCliOptions& o) {
    // Usage problems first: a bad plan is reported whatever the input holds (the real texture
    // size is checked again below).
    checkPlan(o.plan, o.texture > 0 ? o.texture : kMinAutoTexture);
    const std::vector<glm::dvec2> points = readInput(o.input);
    if (points.empty()) throw InputError(o.input + ": no points");
    requireTriangulable(points, o.input);

    geom::DelaunayOptions options;
    options.discrete.size =
        o.texture > 0 ? o.texture : defaultTextureSize(points.size(), o.backend == "gl");
    options.discrete.plan = o.plan;
    options.discrete.threads = o.threads;
    options.discrete.countIslands = true;
    checkPlan(o.plan, options.discrete.size);
    const bool pictures = !o.steps.empty() && points.size() <= kMaxPicturePoints;
    options.keepStages = pictures;
    if (o.backend == "gl") options.discreteBackend = glBackend();

    std::cout << "input: " << o.input << ", " << points.size() << " points\n"
              << "texture: " << options.discrete.size << "x" << options.discrete.size
              << (o.texture > 0 ? " (--texture)" : " (default for the point count and backend)")
              << ", plan " << o.plan << ", backend " << o.backend;
    if (o.backend == "cpu") std::cout << ", " << jfa::resolveThreads(o.threads) << " thread(s)";
    std::cout << "\n";

    const geom::DelaunayResult r = [&] {
        try {
            return geom::delaunay(points, options);
        } catch (const std::invalid_argument& e) {
            throw InputError(o.input + ": " + e.what());
        }
    }();

    double checkMs = -1.0;
    geom::TriangulationReport report;
    if (o.check) {
        const auto t0 = std::chrono::steady_clock::now();
        report = geom::checkTriangulation(r.mesh);
        checkMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                      .count();
    }
    printTimes(r, checkMs, std::cout);
    printCounts(r, std::cout);
    if (o.check) {
        std::cout << "check: " << (report.ok() ? "ok" : "FAILED") << "\n"
                  << report.summary() << (report.summary().ends_with('\n') ? "" : "\n");
    }

    // Every file appears, or none (base/OutputFiles.h): a failing SVG or --steps folder used to
    // leave the .node/.ele/.obj behind.
    OutputSet outputs;
    std::ostringstream wrote;
    if (!o.out.empty()) writeMeshFiles(o, r.mesh, wrote);
    if (!o.steps.empty()) {
        if (pictures) {
            try {
                writeStepPictures(o.steps, points, r, wrote);
            } catch (const std::invalid_argument& e) {
                throw InputError(o.input + ": cannot draw the --steps pictures (" + e.what() + ")");
            }
        } else
            std::cout << "steps: " << points.size() << " points (more than " << kMaxPicturePoints
                      << "): step pictures skipped, they would be unreadable; use a subset\n";
    }
    outputs.commit();
    std::cout << wrote.str();
    if (o.check && !report.ok()) {
        std::cerr << "error: " << o.input << ": the triangulation failed --check ("
                  << report.problemCount << " problem(s), listed above)\n";
        return 1;
    }
    return 0;
}

} // namespace

int defaultTextureSize(std::size_t points, bool glBackend) {
    if (!glBackend) return geom::kCpuDefaultTexture;
    const double texels = kTexelsPerSiteGl * double(points);
    int n = kMinAutoTexture;
    while (n < kMaxAutoTexture && double(n) * double(n) < texels) n *= 2;
    return n;
}

Runner addDelaunayCommand(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand(
        "delaunay",
        "Delaunay triangulation of a point file by 1+JFA + exact repair (thesis ch. 6)");
    auto o = std::make_shared<DelaunayCliOptions>();
    cmd->add_option("IN", o->input,
                    "Points: .node (Triangle), .txt/.xy ('x y') (at most " +
                        std::to_string(kTextInputLimitMiB) + " MiB), .bin/.f64 (at most " +
                        std::to_string(kBinaryInputLimitMiB) + " MiB)")
        ->required();
    cmd->add_option("--texture", o->texture,
                    "Texture side N for G1-G6 (default, gl: the smallest power of two with N^2 "
                    ">= " +
                        std::to_string(int(kTexelsPerSiteGl)) + " x points, in " +
                        std::to_string(kMinAutoTexture) + ".." + std::to_string(kMaxAutoTexture) +
                        " (thesis 6.5); cpu: " + std::to_string(geom::kCpuDefaultTexture) +
                        " (measured))")
        ->check(integer(2, geom::kMaxDiscreteSize));
    cmd->add_option("--backend", o->backend, "G1-G6 on cpu or gl (needs a GL 4.5 context)")
        ->check(CLI::IsMember({"cpu", "gl"}))
        ->capture_default_str();
    cmd->add_option("--plan", o->plan, "G2's flood plan (1+jfa, jfa, jfa+1, ...)")
        ->capture_default_str();
    cmd->add_flag("--check", o->check,
                  "Verify the result exactly (structure, convex hull, empty circles); exit 1 if "
                  "it fails");
    cmd->add_option("--out", o->out, "Output prefix: PREFIX.node + PREFIX.ele, .obj, .svg")
        ->check(outputFile());
    cmd->add_option("--format", o->format, "Which outputs --out writes")
        ->check(CLI::IsMember({"node", "obj", "svg", "all"}))
        ->capture_default_str();
    cmd->add_option("--steps", o->steps, "Folder for one SVG per step (01_sites ... 09_flipped)")
        ->check(outputFolder());
    cmd->add_option("--threads", o->threads, "Worker threads for G1-G6 (0: all)")
        ->check(integer(0, 1024))
        ->capture_default_str();
    return [o] { return runDelaunay(*o); };
}

} // namespace fl::app
