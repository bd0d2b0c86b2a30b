// `voronoi --exact` against JFA and JFA^2 (issue 31 item 3): per backend, grid size and site
// count, the three run side by side in one process, interleaved, --runs rounds (min / median,
// after one warm-up). Exact = the site graph from the site list (CPU, geometry/SiteGraph.h; on
// GL its upload too) + JFA + the repair (jfa/ExactRepair.h). The input of all three is the seed
// grid and the list of its sites, built (and on GL uploaded) outside every timing; the graph
// tags the seeds in place. Each exact result is then checked: 0 error pixels against
// jfa::exactNearest, and GL equal to CPU texel for texel. On the CPU the repair alone is also
// timed with walks at every texel against the row-interval shortcut, and the two compared.

#include <base/Stats.h>
#include <base/Text.h>
#include <renderer/context/EglContext.h>

#include <geometry/SiteGraph.h>

#include <jfa/CpuKernel.h>
#include <jfa/ExactRepair.h>
#include <jfa/Plan.h>
#include <jfa/Reference.h>
#include <jfa/Sites.h>
#include <jfa_gl/GlExactRepair.h>
#include <jfa_gl/GlKernel.h>

#include <BenchSupport.h>
#include <CLI/CLI.hpp>

#include <chrono>
#include <ctime>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>

namespace {

using namespace fl;
using Clock = std::chrono::steady_clock;

// Wall time, and the process's CPU time (all its threads, llvmpipe's included): on a machine
// shared with other builds the wall time of a run varies with their load, its CPU time much less.
struct Timing {
    double min = 0, median = 0, cpuMedian = 0;
};

double since(Clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

double processCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

// "1.10x JFA (min 1.02x, CPU time 1.05x)": the ratios of medians, of minima, of CPU medians.
std::string ratioText(const Timing& t, const Timing& base, const char* what) {
    return cat(fixed(t.median / base.median, 2), "x ", what, " (min ", fixed(t.min / base.min, 2),
               "x, CPU time ", fixed(t.cpuMedian / base.cpuMedian, 2), "x)");
}

// Each of `fs` once to warm up, then `runs` rounds that time each once, interleaved so that
// load from other processes falls on all of them alike; `gl` waits for the GPU around each.
std::vector<Timing> timeRuns(int runs, bool gl, const std::vector<std::function<void()>>& fs) {
    std::vector<std::vector<double>> ms(fs.size()), cpu(fs.size());
    for (const auto& f : fs) f();
    for (int i = 0; i < runs; ++i)
        for (std::size_t k = 0; k < fs.size(); ++k) {
            if (gl) glFinish();
            const auto t0 = Clock::now();
            const double c0 = processCpuMs();
            fs[k]();
            if (gl) glFinish();
            ms[k].push_back(since(t0));
            cpu[k].push_back(processCpuMs() - c0);
        }
    std::vector<Timing> out;
    for (std::size_t k = 0; k < fs.size(); ++k)
        out.push_back({fl::minimum(ms[k]), fl::median(ms[k]), fl::median(cpu[k])});
    return out;
}

void row(const std::string& what, const Timing& t, const std::string& note) {
    std::cout << "  " << std::left << std::setw(30) << what << std::right << std::fixed
              << std::setprecision(2) << " min " << std::setw(9) << t.min << " ms  median "
              << std::setw(9) << t.median << " ms  CPU " << std::setw(9) << t.cpuMedian << " ms  "
              << note << "\n"
              << std::defaultfloat;
}

struct Config {
    int runs = 3;
    std::vector<int> sizes{512, 1024, 2048};
    std::vector<int> sites{100, 1000, 10000};
    std::vector<std::string> backends{"cpu", "gl"};
};

// The repair alone on the CPU, walks at every texel against the row-interval shortcut
// (jfa/ExactRepair.h), from the same JFA result: the optimisation before and after, and equal.
void compareRepairMethods(const Config& c, const jfa::Grid& seeds) {
    jfa::Grid tagged = seeds;
    const jfa::SiteGraph graph = geom::buildSiteGraph(tagged);
    const jfa::Grid flooded =
        jfa::flood(jfa::Plan::jfa(seeds.width, seeds.height), tagged, jfa::NearestSite{true});
    jfa::Grid walks, intervals;
    const std::vector<Timing> t =
        timeRuns(c.runs, false,
                 {[&] {
                      walks = flooded;
                      jfa::repairNearest(walks, graph, 0, jfa::RepairMethod::Walks);
                  },
                  [&] {
                      intervals = flooded;
                      jfa::repairNearest(intervals, graph);
                  }});
    row("repair alone: walks", t[0], "(every texel walks)");
    row("repair alone: row intervals", t[1],
        cat(ratioText(t[1], t[0], "the walks"),
            "; same grid: ", walks == intervals ? "yes" : "NO"));
    if (walks != intervals) throw std::runtime_error("the row intervals changed the repair");
}

// The exact pipeline once: the graph (CPU; on GL uploaded too), JFA, the repair, each stage's
// time appended to `stageMs`. GL floods `taggedIn`, the seeds as the graph tags them.
struct ExactPipeline {
    jfa::Grid seeds;              // tagged in place by every run (the same tags each time)
    std::vector<jfa::Cell> sites; // jfa::siteCells(seeds), the input as a list
    const gl::Texture* taggedIn = nullptr;
    jfa::GlFloodKernel<jfa::NearestSite>* kernel = nullptr;
    jfa::GlExactRepair* repair = nullptr;
    std::vector<double> stageMs[3];
    jfa::Grid result; // the CPU's

    void operator()() {
        const jfa::Plan plan = jfa::Plan::jfa(seeds.width, seeds.height);
        const jfa::NearestSite crit{true};
        const bool gl = kernel != nullptr;
        auto t0 = Clock::now();
        auto stage = [&](int i) {
            if (gl) glFinish();
            stageMs[i].push_back(since(t0));
            t0 = Clock::now();
        };
        const jfa::SiteGraph graph = geom::buildSiteGraph(seeds, sites);
        if (gl) repair->setGraph(graph);
        stage(0);
        if (gl) {
            const gl::Texture& flooded = kernel->run(plan, *taggedIn, crit);
            stage(1);
            repair->run(flooded);
            stage(2);
            return;
        }
        result = jfa::flood(plan, seeds, crit);
        stage(1);
        jfa::repairNearest(result, graph);
        stage(2);
    }
    std::string stages() {
        for (auto& v : stageMs) v.erase(v.begin()); // the warm-up
        return cat("medians: graph ", fixed(fl::median(stageMs[0]), 2), ", JFA ",
                   fixed(fl::median(stageMs[1]), 2), ", repair ", fixed(fl::median(stageMs[2]), 2),
                   " ms");
    }
};

// One size and site count on one backend: JFA, JFA^2, exact; returns the exact grid.
jfa::Grid measure(const Config& c, bool gl, int n, int sites, const gl::ShaderLibrary* shaders) {
    const jfa::NearestSite crit{true};
    const jfa::Grid seeds =
        jfa::seedPoints(jfa::randomIntegerSites(sites, n, n, 1), n, n, true).grid;
    const jfa::Plan jfa = jfa::Plan::jfa(n, n), jfa2 = jfa::Plan::jfaSquared(n, n);
    std::unique_ptr<jfa::GlFloodKernel<jfa::NearestSite>> kernel;
    std::unique_ptr<jfa::GlExactRepair> repair;
    gl::Texture in, taggedIn;
    jfa::Grid tagged = seeds;
    const std::size_t vertices = geom::buildSiteGraph(tagged).vertices.size(); // the tags
    if (gl) {
        kernel = std::make_unique<jfa::GlFloodKernel<jfa::NearestSite>>(
            *shaders, jfa::GlKernelKind::Fragment);
        repair = std::make_unique<jfa::GlExactRepair>(*shaders);
        in = jfa::uploadGrid(seeds);
        taggedIn = jfa::uploadGrid(tagged);
    }
    auto run = [&](const jfa::Plan& plan) -> jfa::Grid {
        if (gl) return jfa::readGrid(kernel->run(plan, in, crit));
        return jfa::flood(plan, seeds, crit);
    };
    auto timed = [&](const jfa::Plan& plan) {
        if (gl)
            kernel->run(plan, in, crit);
        else
            (void)jfa::flood(plan, seeds, crit);
    };
    ExactPipeline exactRun{seeds, jfa::siteCells(seeds), &taggedIn, kernel.get(), repair.get(), {},
                           {}};
    const std::vector<Timing> t =
        timeRuns(c.runs, gl, {[&] { timed(jfa); }, [&] { timed(jfa2); }, [&] { exactRun(); }});
    const jfa::Grid result =
        gl ? jfa::readGrid(repair->run(kernel->run(jfa, taggedIn, crit))) : exactRun.result;
    const jfa::ExactField exact = jfa::exactNearest(seeds, crit);
    const std::int64_t exactErrors = jfa::countErrors(result, exact, crit);
    const std::string tag = cat(gl ? "GL " : "CPU ", n, "^2, ", sites, " sites");
    std::cout << tag << " (graph: " << vertices << " vertices)\n";
    row("JFA", t[0], cat(jfa::countErrors(run(jfa), exact, crit), " error pixels"));
    row("JFA^2", t[1],
        cat(jfa::countErrors(run(jfa2), exact, crit), " error pixels, ",
            ratioText(t[1], t[0], "JFA")));
    row("exact (graph + JFA + repair)", t[2],
        cat(exactErrors, " error pixels, ", ratioText(t[2], t[0], "JFA"), "; ", exactRun.stages()));
    if (exactErrors != 0) throw std::runtime_error(tag + ": the exact result has errors");
    if (!gl) compareRepairMethods(c, seeds);
    return result;
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"exact_voronoi_bench: voronoi --exact against JFA and JFA^2 (CPU and GL)"};
    Config c;
    app.add_option("--runs", c.runs, "Timed runs per configuration")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    app.add_option("--sizes", c.sizes, "Grid sides")->delimiter(',')->check(CLI::Range(8, 4096));
    app.add_option("--sites", c.sites, "Site counts")
        ->delimiter(',')
        ->check(CLI::Range(1, 1 << 20));
    app.add_option("--backends", c.backends, "cpu, gl")
        ->delimiter(',')
        ->check(CLI::IsMember({"cpu", "gl"}));
    return fl::bench::parseAndRun(app, argc, argv, [&] {
        auto ctx = EglContext::create(false);
        const gl::ShaderLibrary shaders;
        std::cout << "context: " << ctx->description() << "\n"
                  << c.runs << " runs each after a warm-up (min / median), uniform random "
                  << "integer sites (seed 1); CPU: all threads; GL: fragment JFA kernel, compute "
                     "repair, glFinish wall time\n";
        for (int n : c.sizes)
            for (int sites : c.sites) {
                if (sites > n * n) continue;
                std::map<std::string, jfa::Grid> results;
                for (const std::string& b : c.backends)
                    results[b] = measure(c, b == "gl", n, sites, &shaders);
                if (results.size() == 2)
                    std::cout << "  GL exact == CPU exact texel for texel: "
                              << (results["gl"] == results["cpu"] ? "yes" : "NO") << "\n";
                if (results.size() == 2 && results["gl"] != results["cpu"]) return 1;
            }
        return 0;
    });
}
