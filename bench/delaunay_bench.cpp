// Our Delaunay pipeline (geometry/Delaunay.h: G1-G6 + C1-C4, thesis ch. 6) against CGAL's
// Delaunay_triangulation_2 (exact predicates, inexact constructions; range insertion, which
// spatially sorts first: CGAL's fast path) on the standard point distributions. For every
// distribution and size it prints min/median times of both, ours per step, the ratios, peak
// memory per point, and whether both produced the same triangulation.
//
// Every measurement runs in a fresh child process (this binary re-executed with --child), so
// peak RSS (getrusage's ru_maxrss of the child) is the peak of one triangulator on one input and
// not the high-water mark of everything before it. The baseline child only generates the points;
// "bytes/point" is (peak - baseline peak) / n, i.e. what the triangulator itself holds at its peak
// (our pipeline's includes its N x N textures and every G-step stage it keeps). Both children
// read their peak once their sorted triangle list is written, before our exact check runs: the
// checker's arrays are the bench's, not the triangulator's (they were counted until 2026-11-29).
//
// Same triangulation: the triangle counts must agree. Where the input has no four co-circular
// points (uniform, gaussian, kuzmin: random doubles) the Delaunay triangulation is unique and the
// sorted canonical triangle lists must be identical; grids, circles and lines have many valid
// Delaunay triangulations, so there our result is checked exactly (checkTriangulation) instead.

#include <base/Stats.h>
#include <geometry/Delaunay.h>
#include <geometry_gl/GlDiscreteDelaunay.h>
#include <gpu/ShaderLibrary.h>
#include <jfa/Sites.h>
#include <renderer/context/EglContext.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/version.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <numbers>
#include <spawn.h>
#include <sstream>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace {

using fl::geom::DelaunayResult;
using Tri = std::array<std::uint32_t, 3>;

// --- distributions -----------------------------------------------------------------------------

const std::vector<std::string> kDistributions{"uniform",    "gaussian",  "grid",  "circle",
                                              "thincircle", "two-lines", "kuzmin"};

// Whether the Delaunay triangulation is unique (no four co-circular points, almost surely).
bool uniqueTriangulation(const std::string& d) {
    return d == "uniform" || d == "gaussian" || d == "kuzmin";
}

// `n` points of distribution `d`, the same for a given seed on every machine (SplitMix64 and
// IEEE arithmetic; libm's cos/sin/log are correctly rounded enough not to matter for timing).
std::vector<glm::dvec2> generate(const std::string& d, std::size_t n, std::uint64_t seed) {
    fl::jfa::SplitMix64 rng(seed * 0x9e3779b97f4a7c15ull + std::hash<std::string>{}(d));
    std::vector<glm::dvec2> p;
    p.reserve(n);
    const double twoPi = 2.0 * std::numbers::pi;
    if (d == "grid") { // side = round(sqrt(n)): 100^2, 316^2, 1000^2
        const auto side = std::size_t(std::llround(std::sqrt(double(n))));
        for (std::size_t y = 0; y < side; ++y)
            for (std::size_t x = 0; x < side; ++x) p.emplace_back(double(x), double(y));
        return p;
    }
    for (std::size_t i = 0; i < n; ++i) {
        const double u = rng.unit(), v = rng.unit();
        if (d == "uniform") {
            p.emplace_back(u, v);
        } else if (d == "gaussian") { // Box-Muller, sigma 1
            const double r = std::sqrt(-2.0 * std::log(1.0 - u));
            p.emplace_back(r * std::cos(twoPi * v), r * std::sin(twoPi * v));
        } else if (d == "circle") { // on the unit circle (rounded: nearly co-circular)
            p.emplace_back(std::cos(twoPi * u), std::sin(twoPi * u));
        } else if (d == "thincircle") { // annulus 0.99 <= r <= 1, uniform by area
            const double r = std::sqrt(0.99 * 0.99 + (1.0 - 0.99 * 0.99) * v);
            p.emplace_back(r * std::cos(twoPi * u), r * std::sin(twoPi * u));
        } else if (d == "two-lines") { // half on y = x, half on y = 1 - x (exactly collinear)
            p.emplace_back(u, i % 2 == 0 ? u : 1.0 - u);
        } else if (d == "kuzmin") { // Kuzmin disc: mass within r is 1 - 1/sqrt(1 + r^2)
            const double r = std::sqrt(1.0 / ((1.0 - u) * (1.0 - u)) - 1.0);
            p.emplace_back(r * std::cos(twoPi * v), r * std::sin(twoPi * v));
        } else {
            throw std::invalid_argument("unknown distribution " + d);
        }
    }
    return p;
}

// --- the two triangulators ---------------------------------------------------------------------

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb>;
using CgalDt = CGAL::Delaunay_triangulation_2<K, Tds>;

double msSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// Rotates each counterclockwise triangle to start at its smallest index, then sorts the list.
std::vector<Tri> canonical(std::vector<Tri> tris) {
    for (Tri& t : tris) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    std::sort(tris.begin(), tris.end());
    return tris;
}

std::vector<Tri> cgalTriangles(const CgalDt& dt) {
    std::vector<Tri> out;
    out.reserve(dt.number_of_faces());
    for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
        out.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
    return out;
}

std::vector<Tri> ourTriangles(const fl::geom::Triangulation& mesh) {
    std::vector<Tri> out(mesh.triangleCount());
    for (std::size_t t = 0; t < out.size(); ++t)
        out[t] = {mesh.triangles[3 * t], mesh.triangles[3 * t + 1], mesh.triangles[3 * t + 2]};
    return out;
}

void writeTriangles(const std::string& path, const std::vector<Tri>& tris) {
    std::ofstream f(path, std::ios::binary);
    f.write(reinterpret_cast<const char*>(tris.data()), std::streamsize(tris.size() * sizeof(Tri)));
    if (!f) throw std::runtime_error("cannot write " + path);
}

std::vector<Tri> readTriangles(const std::string& path) {
    std::ifstream f(path, std::ios::binary | std::ios::ate);
    std::vector<Tri> tris(std::size_t(f.tellg()) / sizeof(Tri));
    f.seekg(0);
    f.read(reinterpret_cast<char*>(tris.data()), std::streamsize(tris.size() * sizeof(Tri)));
    return tris;
}

// The GL lane's texture side for n points: the smallest power of two with N^2 >= n, in
// 256..8192.
int autoGlTexture(std::size_t n) {
    int size = 256;
    while (size < 8192 && double(size) * double(size) < double(n)) size *= 2;
    return size;
}

struct ChildOptions {
    std::string side, dist, trianglesOut, backend = "cpu";
    std::size_t n = 0;
    std::uint64_t seed = 1;
    int runs = 3, texture = 0, threads = 0;
    bool check = true;
};

// The process's peak resident set so far, in bytes (ru_maxrss is in KiB on Linux).
double peakRssBytes() {
    rusage ru{};
    getrusage(RUSAGE_SELF, &ru);
    return double(ru.ru_maxrss) * 1024.0;
}

// CGAL's side of one measurement: `runs` range insertions; the canonical triangle list to
// o.trianglesOut.
void runCgal(const ChildOptions& o, const std::vector<glm::dvec2>& points, std::ostream& res) {
    std::vector<std::pair<K::Point_2, std::uint32_t>> in;
    in.reserve(points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
        in.emplace_back(K::Point_2(points[i].x, points[i].y), std::uint32_t(i));
    std::vector<Tri> tris;
    for (int r = 0; r < o.runs; ++r) {
        const auto t0 = std::chrono::steady_clock::now();
        CgalDt dt(in.begin(), in.end());
        res << " total=" << msSince(t0);
        if (r + 1 == o.runs) tris = cgalTriangles(dt);
    }
    res << " triangles=" << tris.size();
    writeTriangles(o.trianglesOut, canonical(std::move(tris)));
}

// The GL backend's state, made once before the first run's clock starts (as `floodlight
// delaunay --backend gl` does): context, shaders and programs.
struct GlLane {
    std::unique_ptr<fl::EglContext> context = fl::EglContext::create();
    fl::gl::ShaderLibrary shaders;
    fl::geom::GlDiscreteDelaunay steps{shaders};
};

// Our side: `runs` runs of delaunay() with per-step times; the canonical triangle list to
// o.trianglesOut, then (unless --no-check) the exact check.
void runOurs(const ChildOptions& o, const std::vector<glm::dvec2>& points, std::ostream& res) {
    fl::geom::DelaunayOptions opt;
    opt.discrete.threads = o.threads;
    // The CPU backend's default is `floodlight delaunay`'s; the GL lane keeps N^2 >= n (1024 at
    // 1M), the size its numbers in docs/BENCHMARKS.md were measured at.
    opt.discrete.size = o.texture > 0       ? o.texture
                        : o.backend == "gl" ? autoGlTexture(points.size())
                                            : fl::geom::kCpuDefaultTexture;
    std::unique_ptr<GlLane> gl;
    if (o.backend == "gl") {
        gl = std::make_unique<GlLane>();
        opt.discreteBackend = [&gl](const std::vector<glm::dvec2>& s,
                                    const fl::geom::DiscreteDelaunayOptions& d) {
            return gl->steps.run(s, d);
        };
    }
    DelaunayResult r;
    for (int run = 0; run < o.runs; ++run) {
        r = {}; // or the peak RSS would hold the previous run's result next to this one
        const auto t0 = std::chrono::steady_clock::now();
        r = fl::geom::delaunay(points, opt);
        const double wall = msSince(t0);
        const auto& g = r.discrete.timings;
        const auto& c = r.cpu;
        res << " total=" << wall << " g1=" << g.g1 << " g2=" << g.g2 << " g3=" << g.g3
            << " g4=" << g.g4 << " g5=" << g.g5 << " g6=" << g.g6 << " c1=" << c.c1
            << " c2=" << c.c2 << " c3=" << c.c3 << " c4=" << c.c4;
        if (gl) {
            const fl::geom::GlDiscreteExtras& x = gl->steps.extras();
            res << " rb=" << x.readbackMs << " snap=" << x.snapMs << " up=" << x.uploads
                << " down=" << x.readbacks;
        }
    }
    res << " texture=" << opt.discrete.size << " missing=" << r.discrete.missing().size()
        << " flips=" << r.counts.flips + r.counts.insertFlips << " badshifts=" << r.counts.badShifts
        << " sequential=" << r.counts.sequentialInserts << " triangles=" << r.mesh.triangleCount();
    writeTriangles(o.trianglesOut, canonical(ourTriangles(r.mesh)));
    // The peak so far, as CGAL's child's at the same point (its triangle list written): the
    // checker's own arrays are the bench's, not the triangulator's.
    res << " peak=" << peakRssBytes();
    if (o.check) res << " checkok=" << (fl::geom::checkTriangulation(r.mesh).ok() ? 1 : 0);
}

// One measurement in this (fresh) process; prints one "RESULT ..." line for the parent.
int runChild(const ChildOptions& o) {
    const std::vector<glm::dvec2> points = generate(o.dist, o.n, o.seed);
    std::ostringstream res;
    res << std::setprecision(9) << "RESULT n=" << points.size();
    if (o.side == "cgal") {
        runCgal(o, points, res);
        res << " peak=" << peakRssBytes();
    } else if (o.side == "ours") {
        runOurs(o, points, res);
    }
    std::cout << res.str() << std::endl;
    return 0;
}

// --- the parent: children, parsing, tables -----------------------------------------------------

// key -> every value printed for it (one per run for times).
using Values = std::map<std::string, std::vector<double>>;

struct ChildRun {
    bool ok = false;
    std::string error;
    Values values;
    double maxRssBytes = 0.0;
};

ChildRun spawnChild(const std::vector<std::string>& args, int timeoutS) {
    ChildRun out;
    int fds[2];
    if (pipe(fds) != 0) throw std::runtime_error("pipe failed");
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_adddup2(&fa, fds[1], STDOUT_FILENO);
    posix_spawn_file_actions_addclose(&fa, fds[0]);
    std::vector<std::string> full{"/proc/self/exe"};
    full.insert(full.end(), args.begin(), args.end());
    full.push_back("--timeout=" + std::to_string(timeoutS));
    std::vector<char*> argv;
    for (std::string& a : full) argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_t pid = 0;
    const int err = posix_spawn(&pid, "/proc/self/exe", &fa, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&fa);
    close(fds[1]);
    if (err != 0) throw std::runtime_error("posix_spawn failed");
    std::string text;
    char buf[4096];
    for (ssize_t k; (k = read(fds[0], buf, sizeof buf)) > 0;) text.append(buf, std::size_t(k));
    close(fds[0]);
    int status = 0;
    rusage ru{};
    wait4(pid, &status, 0, &ru);
    out.maxRssBytes = double(ru.ru_maxrss) * 1024.0; // Linux reports KiB
    if (WIFSIGNALED(status)) {
        out.error = WTERMSIG(status) == SIGALRM ? "timeout (> " + std::to_string(timeoutS) + " s)"
                                                : "signal " + std::to_string(WTERMSIG(status));
        return out;
    }
    const auto at = text.find("RESULT ");
    if (WEXITSTATUS(status) != 0 || at == std::string::npos) {
        out.error = "failed";
        return out;
    }
    std::istringstream in(text.substr(at + 7));
    for (std::string kv; in >> kv;) {
        const auto eq = kv.find('=');
        out.values[kv.substr(0, eq)].push_back(std::stod(kv.substr(eq + 1)));
    }
    out.ok = true;
    return out;
}

double med(const Values& v, const std::string& key) {
    const auto it = v.find(key);
    return it == v.end() || it->second.empty() ? std::nan("") : fl::median(it->second);
}

std::string fmt(double v, int digits = 1) {
    if (std::isnan(v)) return "-";
    std::ostringstream s;
    s << std::fixed << std::setprecision(digits) << v;
    return s.str();
}

std::size_t parseCount(const std::string& s) {
    const char last = s.empty() ? '\0' : char(std::tolower(s.back()));
    const double scale = last == 'k' ? 1e3 : last == 'm' ? 1e6 : 1.0;
    return std::size_t(std::stod(scale == 1.0 ? s : s.substr(0, s.size() - 1)) * scale);
}

// One row of each table for a distribution/size/texture.
void writeRows(const std::string& d, int texture, const ChildRun& base, const ChildRun& cgal,
               const ChildRun& ours, const std::vector<Tri>& cgalTris, const std::string& ourFile,
               bool noCheck, std::ostream& table, std::ostream& steps) {
    const double points = base.ok ? base.values.at("n").front() : std::nan("");
    const Values& o = ours.values;
    // The side the child ran at (its backend's default without --texture).
    const double side = ours.ok && o.count("texture") ? o.at("texture").front()
                        : texture > 0                 ? texture
                                                      : fl::geom::kCpuDefaultTexture;
    // The child's peak before our exact check (older binaries: at exit) over the points' child.
    auto perPoint = [&](const ChildRun& r) {
        if (!r.ok) return std::nan("");
        const double peak = r.values.count("peak") ? r.values.at("peak").front() : r.maxRssBytes;
        return (peak - base.maxRssBytes) / points;
    };
    std::string same = "-";
    if (cgal.ok && ours.ok) {
        const std::vector<Tri> ourTris = readTriangles(ourFile);
        if (ourTris.size() != cgalTris.size())
            same = "NO: count";
        else if (uniqueTriangulation(d))
            same = ourTris == cgalTris ? "identical" : "NO: triangles differ";
        else if (noCheck)
            same = "count";
        else
            same = med(o, "checkok") == 1.0 ? "count + check" : "NO: check failed";
    }
    const double cg = cgal.ok ? fl::median(cgal.values.at("total")) : std::nan("");
    const double ot = ours.ok ? fl::median(o.at("total")) : std::nan("");
    double gsum = 0.0, csum = 0.0;
    for (const char* k : {"g1", "g2", "g3", "g4", "g5", "g6"}) gsum += med(o, k);
    for (const char* k : {"c1", "c2", "c3", "c4"}) csum += med(o, k);
    auto times = [&](const ChildRun& r) {
        return r.ok ? fmt(fl::minimum(r.values.at("total"))) + " / " +
                          fmt(fl::median(r.values.at("total")))
                    : r.error;
    };
    table << "| " << d << " | " << fmt(points, 0) << " | " << fmt(side, 0) << " | " << times(cgal)
          << " | " << times(ours) << " | " << fmt(gsum) << " | " << fmt(csum) << " | "
          << fmt(ot / cg, 2) << " | " << fmt(csum / cg, 2) << " | " << fmt(med(o, "missing"), 0)
          << " | " << fmt(med(o, "flips"), 0) << " | " << fmt(med(o, "triangles"), 0) << " | "
          << same << " | " << fmt(perPoint(cgal), 0) << " | " << fmt(perPoint(ours), 0) << " |\n";
    steps << "| " << d << " | " << fmt(points, 0) << " | " << fmt(side, 0);
    for (const char* k :
         {"g1", "snap", "g2", "g3", "g4", "g5", "g6", "rb", "up", "down", "c1", "c2", "c3", "c4"})
        steps << " | " << fmt(med(o, k));
    steps << " |\n";
}

// Everything the command line sets (the --child options only in the children).
struct BenchOptions {
    std::vector<std::string> dists = kDistributions, sizes{"10k", "100k", "1M"};
    std::vector<int> textures{0};
    std::string backend = "cpu";
    int runs = 3, threads = 0, timeoutS = 600;
    std::uint64_t seed = 1;
    bool noCheck = false;
    ChildOptions child;
};

void addOptions(CLI::App& app, BenchOptions& o) {
    app.add_option("--dist", o.dists, "Distributions")
        ->check(CLI::IsMember(kDistributions))
        ->capture_default_str();
    app.add_option("--sizes", o.sizes, "Point counts (10k, 100k, 1M, or plain numbers)")
        ->capture_default_str();
    app.add_option("--texture", o.textures, "Texture sides to run ours at (0: the CLI's rule)")
        ->capture_default_str();
    app.add_option("--runs", o.runs, "Runs per measurement (min/median)")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    app.add_option("--backend", o.backend, "G1-G6 on the CPU or through GL (headless EGL)")
        ->check(CLI::IsMember({"cpu", "gl"}))
        ->capture_default_str();
    app.add_option("--threads", o.threads, "Threads for G1-G6 and C1-C4 (0: all)")
        ->capture_default_str();
    app.add_option("--seed", o.seed)->capture_default_str();
    app.add_option("--timeout", o.timeoutS, "Seconds per child before it is killed")
        ->capture_default_str();
    app.add_flag("--no-check", o.noCheck, "Skip checkTriangulation on our results");
    app.add_option("--child", o.child.side)->group(""); // internal: points | cgal | ours
    app.add_option("--child-dist", o.child.dist)->group("");
    app.add_option("--child-n", o.child.n)->group("");
    app.add_option("--child-out", o.child.trianglesOut)->group("");
}

// A child's command line for one side (points | cgal | ours) of distribution d at n points.
std::vector<std::string> childArgs(const BenchOptions& o, const std::string& side,
                                   const std::string& d, const std::string& n, int texture,
                                   const std::string& out) {
    std::vector<std::string> a{"--child",      side,
                               "--child-out",  out,
                               "--texture",    std::to_string(texture),
                               "--child-dist", d,
                               "--child-n",    n,
                               "--seed",       std::to_string(o.seed),
                               "--runs",       std::to_string(o.runs),
                               "--threads",    std::to_string(o.threads),
                               "--backend",    o.backend};
    if (o.noCheck) a.push_back("--no-check");
    return a;
}

// Every size x distribution x texture: the points' child, CGAL's and ours; a row of each table.
void measureAll(const BenchOptions& o, std::ostream& table, std::ostream& steps) {
    const std::string tmp = "/tmp/delaunay_bench." + std::to_string(getpid());
    for (const std::string& size : o.sizes) {
        for (const std::string& d : o.dists) {
            const std::string n = std::to_string(parseCount(size));
            const auto child = [&](const std::string& side, int texture) {
                return spawnChild(childArgs(o, side, d, n, texture, tmp + "." + side), o.timeoutS);
            };
            const ChildRun base = child("points", 0);
            const ChildRun cgal = child("cgal", 0);
            const std::vector<Tri> cgalTris =
                cgal.ok ? readTriangles(tmp + ".cgal") : std::vector<Tri>{};
            for (const int texture : o.textures) {
                const ChildRun ours = child("ours", texture);
                std::ostringstream row, stepRow;
                writeRows(d, texture, base, cgal, ours, cgalTris, tmp + ".ours", o.noCheck, row,
                          stepRow);
                std::cerr << row.str() << std::flush; // progress
                table << row.str();
                steps << stepRow.str();
            }
        }
    }
    std::remove((tmp + ".cgal").c_str());
    std::remove((tmp + ".ours").c_str());
}

// The parent: the header, every measurement, both tables.
int runParent(const BenchOptions& o) {
    std::cout << "delaunay_bench: CGAL " << CGAL_VERSION_STR
              << " Delaunay_triangulation_2 (Epick, range insert) vs floodlight delaunay() ("
              << o.backend
              << " backend, threads: " << (o.threads ? std::to_string(o.threads) : "all") << ")\n"
              << "runs " << o.runs << ", seed " << o.seed << "; times in ms (min / median); "
              << "each measurement in a fresh process\n\n";
    std::ostringstream table, steps;
    table << "| distribution | n | N | CGAL ms | ours ms | G1-G6 ms | C1-C4 ms | ours/CGAL | "
             "C1-C4/CGAL | missing | flips | triangles | same | CGAL B/pt | ours B/pt |\n"
          << "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|---|--:|--:|\n";
    // GL backend only ("-" on the CPU backend): snap, the host's share of G1; rb, the read-back
    // outside G1-G6; up / down, its uploads and read-backs per run.
    steps << "| distribution | n | N | G1 | snap | G2 | G3 | G4 | G5 | G6 | rb | up | down | C1 | "
             "C2 | C3 | C4 |\n"
          << "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n";
    measureAll(o, table, steps);
    std::cout << table.str() << "\nper-step medians (ms):\n" << steps.str();
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"delaunay_bench: our G1-G6 + C1-C4 pipeline vs CGAL Delaunay_triangulation_2"};
    BenchOptions o;
    addOptions(app, o);
    CLI11_PARSE(app, argc, argv);
    if (o.child.side.empty()) return runParent(o);
    alarm(unsigned(o.timeoutS)); // SIGALRM ends a run that takes too long; the parent says so
    o.child.seed = o.seed;
    o.child.runs = o.runs;
    o.child.texture = o.textures.front();
    o.child.threads = o.threads;
    o.child.backend = o.backend;
    o.child.check = !o.noCheck;
    return runChild(o.child);
}
