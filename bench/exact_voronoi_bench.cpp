// `voronoi --exact` against JFA and JFA^2 (issue 31 item 3): per backend, grid size and site
// count, the three run side by side in one process, each --runs times (min / median, after one
// warm-up). Exact = the site graph (CPU, geometry/SiteGraph.h) + JFA + the repair walk
// (jfa/ExactRepair.h); on GL the graph's upload counts too. The seed grid is built and uploaded
// outside every timing (the same for all three). Each exact result is then checked: 0 error
// pixels against jfa::exactNearest, and GL equal to CPU texel for texel.

#include <base/Stats.h>
#include <base/Text.h>
#include <renderer/context/EglContext.h>

#include <geometry/SiteGraph.h>

#include <jfa/CpuKernel.h>
#include <jfa/ExactRepair.h>
#include <jfa/GlKernel.h>
#include <jfa/Plan.h>
#include <jfa/Reference.h>
#include <jfa/Sites.h>

#include <CLI/CLI.hpp>

#include <chrono>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>

namespace {

using namespace fl;
using Clock = std::chrono::steady_clock;

struct Timing {
    double min = 0, median = 0;
};

double since(Clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// Each of `fs` once to warm up, then `runs` rounds that time each once, interleaved so that
// load from other processes falls on all of them alike; `gl` waits for the GPU around each.
std::vector<Timing> timeRuns(int runs, bool gl, const std::vector<std::function<void()>>& fs) {
    std::vector<std::vector<double>> ms(fs.size());
    for (const auto& f : fs) f();
    for (int i = 0; i < runs; ++i)
        for (std::size_t k = 0; k < fs.size(); ++k) {
            if (gl) glFinish();
            const auto t0 = Clock::now();
            fs[k]();
            if (gl) glFinish();
            ms[k].push_back(since(t0));
        }
    std::vector<Timing> out;
    for (const auto& series : ms) out.push_back({fl::minimum(series), fl::median(series)});
    return out;
}

void row(const std::string& what, const Timing& t, const std::string& note) {
    std::cout << "  " << std::left << std::setw(30) << what << std::right << std::fixed
              << std::setprecision(2) << " min " << std::setw(9) << t.min << " ms  median "
              << std::setw(9) << t.median << " ms  " << note << "\n"
              << std::defaultfloat;
}

struct Config {
    int runs = 3;
    std::vector<int> sizes{512, 1024, 2048};
    std::vector<int> sites{100, 1000, 10000};
    std::vector<std::string> backends{"cpu", "gl"};
};

// One size and site count on one backend: JFA, JFA^2, exact; returns the exact grid.
jfa::Grid measure(const Config& c, bool gl, int n, int sites, const gl::ShaderLibrary* shaders) {
    const jfa::NearestSite crit{true};
    const jfa::Grid seeds =
        jfa::seedPoints(jfa::randomIntegerSites(sites, n, n, 1), n, n, true).grid;
    const jfa::Plan jfa = jfa::Plan::jfa(n, n), jfa2 = jfa::Plan::jfaSquared(n, n);
    const jfa::ExactField exact = jfa::exactNearest(seeds, crit);
    std::unique_ptr<jfa::GlFloodKernel<jfa::NearestSite>> kernel;
    std::unique_ptr<jfa::GlExactRepair> repair;
    gl::Texture in, taggedIn;
    jfa::Grid tagged = seeds, result;
    const jfa::SiteGraph graph0 = geom::buildSiteGraph(tagged); // the tags, for the upload
    if (gl) {
        kernel = std::make_unique<jfa::GlFloodKernel<jfa::NearestSite>>(
            *shaders, jfa::GlKernelKind::Fragment);
        repair = std::make_unique<jfa::GlExactRepair>(*shaders);
        in = jfa::uploadGrid(seeds);
        taggedIn = jfa::uploadGrid(tagged);
    }
    auto run = [&](const jfa::Plan& plan) -> jfa::Grid {
        if (gl) {
            kernel->run(plan, in, crit);
            return {};
        }
        return jfa::flood(plan, seeds, crit);
    };
    std::int64_t jfaErrors = 0, jfa2Errors = 0;
    std::vector<double> graphMs, floodMs, repairMs;
    auto exactRun = [&] {
        auto t0 = Clock::now();
        jfa::Grid work = seeds;
        const jfa::SiteGraph graph = geom::buildSiteGraph(work);
        if (gl) repair->setGraph(graph);
        graphMs.push_back(since(t0));
        t0 = Clock::now();
        if (gl) {
            const gl::Texture& flooded = kernel->run(jfa, taggedIn, crit);
            glFinish();
            floodMs.push_back(since(t0));
            t0 = Clock::now();
            repair->run(flooded);
            glFinish();
            repairMs.push_back(since(t0));
            return;
        }
        result = jfa::flood(jfa, work, crit);
        floodMs.push_back(since(t0));
        t0 = Clock::now();
        jfa::repairNearest(result, graph);
        repairMs.push_back(since(t0));
    };
    const std::vector<Timing> t =
        timeRuns(c.runs, gl, {[&] { (void)run(jfa); }, [&] { (void)run(jfa2); }, exactRun});
    const Timing tJfa = t[0], tJfa2 = t[1], tExact = t[2];
    for (auto* v : {&graphMs, &floodMs, &repairMs}) v->erase(v->begin()); // the warm-up
    if (gl) {
        result = jfa::readGrid(repair->run(kernel->run(jfa, taggedIn, crit)));
        jfaErrors = jfa::countErrors(jfa::readGrid(kernel->run(jfa, in, crit)), exact, crit);
        jfa2Errors = jfa::countErrors(jfa::readGrid(kernel->run(jfa2, in, crit)), exact, crit);
    } else {
        jfaErrors = jfa::countErrors(run(jfa), exact, crit);
        jfa2Errors = jfa::countErrors(run(jfa2), exact, crit);
    }
    const std::int64_t exactErrors = jfa::countErrors(result, exact, crit);
    const std::string tag = cat(gl ? "GL " : "CPU ", n, "^2, ", sites, " sites");
    std::cout << tag << " (graph: " << graph0.vertices.size() << " vertices)\n";
    row("JFA", tJfa, cat(jfaErrors, " error pixels"));
    row("JFA^2", tJfa2,
        cat(jfa2Errors, " error pixels, ", fixed(tJfa2.median / tJfa.median, 2), "x JFA"));
    row("exact (graph + JFA + repair)", tExact,
        cat(exactErrors, " error pixels, ", fixed(tExact.median / tJfa.median, 2),
            "x JFA; medians: graph ", fixed(fl::median(graphMs), 2), ", JFA ",
            fixed(fl::median(floodMs), 2), ", repair ", fixed(fl::median(repairMs), 2), " ms"));
    if (exactErrors != 0) throw std::runtime_error(tag + ": the exact result has errors");
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
    CLI11_PARSE(app, argc, argv);
    try {
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
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
