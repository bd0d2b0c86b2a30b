// GL jump flooding: fragment vs compute kernels, JFA vs standard flooding, few vs many sites.
// Every configuration runs --runs times in one process and context; min and median reported,
// with ratios taken between medians measured side by side in this same run.

#include <base/Stats.h>
#include <base/Text.h>
#include <renderer/context/EglContext.h>

#include <jfa/CpuKernel.h>
#include <jfa/Sites.h>
#include <jfa_gl/GlKernel.h>

#include <BenchSupport.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <iostream>

namespace {

using namespace fl;
using Clock = std::chrono::steady_clock;

struct Timing {
    double min = 0, median = 0;
};

Timing timeRuns(int runs, const std::function<void()>& f) {
    std::vector<double> ms;
    f(); // warm-up: shader compilation, texture allocation
    for (int i = 0; i < runs; ++i) {
        glFinish();
        const auto t0 = Clock::now();
        f();
        glFinish();
        ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t0).count());
    }
    return {fl::minimum(ms), fl::median(ms)};
}

void row(const std::string& what, const Timing& t, int passes) {
    std::cout << "  " << std::left << std::setw(44) << what << std::right << std::fixed
              << std::setprecision(2) << " min " << std::setw(9) << t.min << " ms  median "
              << std::setw(9) << t.median << " ms  (" << passes << " passes, "
              << t.median / std::max(passes, 1) << " ms/pass)\n";
}

// Random integer sites on an n x n grid (seed 1), as a texture.
gl::Texture seedTexture(int sites, int n) {
    return jfa::uploadGrid(
        jfa::seedPoints(jfa::randomIntegerSites(sites, n, n, 1), n, n, true).grid);
}

// The configurations, each timed and kept by name for the ratios.
struct Bench {
    int size, runs, floodRuns;
    const gl::ShaderLibrary& shaders;
    const jfa::NearestSite crit{true};
    std::map<std::string, double> median;

    void time(const std::string& name, int timedRuns, const std::function<void()>& f,
              const std::function<int()>& passes) {
        const Timing t = timeRuns(timedRuns, f);
        row(name, t, passes());
        median[name] = t.median;
    }

    // JFA's variants with few and many sites, and standard flooding as many passes as JFA
    // reaches (n - 1, all step 1), on each kernel kind.
    void kernels() {
        for (jfa::GlKernelKind kind : {jfa::GlKernelKind::Fragment, jfa::GlKernelKind::Compute}) {
            jfa::GlFloodKernel<jfa::NearestSite> kernel(shaders, kind);
            const std::string k = jfa::kernelName(kind);
            for (int sites : {100, 10000}) {
                const gl::Texture in = seedTexture(sites, size);
                for (const char* spec : {"jfa", "1+jfa", "jfa+2", "half:jfa+2"}) {
                    const jfa::Plan plan = jfa::parsePlan(spec, size, size);
                    time(
                        k + " " + plan.name() + ", " + std::to_string(sites) + " sites", runs,
                        [&] { kernel.run(plan, in, crit); }, [&] { return plan.passCount(); });
                }
            }
            const gl::Texture in = seedTexture(100, size);
            const jfa::Plan flood = jfa::Plan::flood(size - 1, size, size);
            time(
                k + " " + flood.name() + ", 100 sites", floodRuns,
                [&] { kernel.run(flood, in, crit); }, [&] { return flood.passCount(); });
        }
    }

    // Band-limited flooding (jfa/Band.h) against the full grid on plans of limited reach (few
    // sites: a small band), with each kernel kind (band passes are compute for both kinds:
    // instanced tile quads through the fragment kernel measured twice as slow).
    void bands() {
        for (jfa::GlKernelKind kind : {jfa::GlKernelKind::Fragment, jfa::GlKernelKind::Compute}) {
            jfa::GlFloodKernel<jfa::NearestSite> kernel(shaders, kind);
            const gl::Texture in = seedTexture(20, size);
            for (const char* spec : {"flood:15", "flood:63"}) {
                const jfa::Plan plan = jfa::parsePlan(spec, size, size);
                for (jfa::FloodRegion region : {jfa::FloodRegion::Full, jfa::FloodRegion::Band}) {
                    kernel.setRegion(region);
                    const Timing t = timeRuns(floodRuns, [&] { kernel.run(plan, in, crit); });
                    const std::string name = cat(jfa::kernelName(kind), " ", spec, ", 20 sites, ",
                                                 jfa::floodRegionName(region), " (",
                                                 fixed(100.0 * kernel.activeShare(), 1), "%)");
                    row(name, t, kernel.passesRun());
                    median[name] = t.median;
                }
            }
        }
    }

    // Standard flooding run to completion (it stops when nothing changes).
    void untilUnchanged() {
        jfa::GlFloodKernel<jfa::NearestSite> kernel(shaders, jfa::GlKernelKind::Fragment);
        for (int sites : {100, 1000}) {
            const gl::Texture in = seedTexture(sites, size);
            const jfa::Plan plan = jfa::parsePlan("flood", size, size);
            time(
                std::string(jfa::kernelName(jfa::GlKernelKind::Fragment)) +
                    " flood until unchanged, " + std::to_string(sites) + " sites",
                floodRuns, [&] { kernel.run(plan, in, crit); }, [&] { return kernel.passesRun(); });
        }
    }

    // The whole JFA plan on the GL fragment kernel and the CPU kernel (all threads) by grid
    // size, and JFA's defining property, cost independent of the number of sites.
    void sizeSweep(const std::vector<int>& scaling) {
        std::cout << "JFA plan time by grid size (GL fragment kernel; CPU kernel, all threads):\n";
        jfa::GlFloodKernel<jfa::NearestSite> fragment(shaders, jfa::GlKernelKind::Fragment);
        for (int n : scaling) {
            const jfa::Plan plan = jfa::parsePlan("jfa", n, n);
            for (int sites : {100, 10000}) {
                const jfa::Grid seeds =
                    jfa::seedPoints(jfa::randomIntegerSites(sites, n, n, 1), n, n, true).grid;
                const gl::Texture in = jfa::uploadGrid(seeds);
                const std::string tag =
                    std::to_string(n) + "^2 JFA, " + std::to_string(sites) + " sites";
                const Timing g = timeRuns(runs, [&] { fragment.run(plan, in, crit); });
                row("GL fragment " + tag, g, plan.passCount());
                median["GL " + tag] = g.median;
                const Timing c = timeRuns(runs, [&] { (void)jfa::flood(plan, seeds, crit); });
                row("CPU " + tag, c, plan.passCount());
                median["CPU " + tag] = c.median;
            }
        }
    }

    void ratio(const std::string& a, const std::string& b) const {
        std::cout << "  " << a << " / " << b << " = " << std::setprecision(3)
                  << median.at(a) / median.at(b) << "\n";
    }

    void ratios(const std::vector<int>& scaling) const {
        std::cout << "ratios of medians:\n";
        const std::string floodName = jfa::Plan::flood(size - 1, size, size).name();
        for (const char* k : {"fragment", "compute"}) {
            ratio(std::string(k) + " " + floodName + ", 100 sites",
                  std::string(k) + " JFA, 100 sites");
            ratio(std::string(k) + " JFA, 10000 sites", std::string(k) + " JFA, 100 sites");
        }
        ratio("compute JFA, 100 sites", "fragment JFA, 100 sites");
        ratio("fragment flood until unchanged, 100 sites", "fragment JFA, 100 sites");
        ratio("fragment flood until unchanged, 1000 sites", "fragment JFA, 100 sites");
        for (int n : scaling) {
            const std::string base = std::to_string(n) + "^2 JFA, ";
            ratio("GL " + base + "10000 sites", "GL " + base + "100 sites");
            ratio("CPU " + base + "10000 sites", "CPU " + base + "100 sites");
            ratio("CPU " + base + "100 sites", "GL " + base + "100 sites");
        }
        ratio("compute JFA, 10000 sites", "fragment JFA, 10000 sites");
    }
};

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"jfa_bench: GL flooding kernels (fragment vs compute, JFA vs standard flooding)"};
    int size = 512, runs = 5, floodRuns = 3;
    std::vector<int> scaling{512, 1024, 2048};
    app.add_option("--size", size, "Grid side")->check(CLI::Range(8, 4096))->capture_default_str();
    app.add_option("--runs", runs, "Timed runs per configuration")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    app.add_option("--flood-runs", floodRuns, "Timed runs of the (slow) standard flooding")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    app.add_option("--scaling-sizes", scaling, "Grid sides for the JFA size sweep (GL and CPU)")
        ->delimiter(',');
    return fl::bench::parseAndRun(app, argc, argv, [&] {
        auto ctx = EglContext::create(false);
        std::cout << "context: " << ctx->description() << "\n"
                  << "grid " << size << "x" << size << ", " << runs
                  << " runs each (min / median), glFinish wall time\n";
        const gl::ShaderLibrary shaders;
        Bench bench{size, runs, floodRuns, shaders}; // crit and median: their defaults
        bench.kernels();
        bench.bands();
        bench.untilUnchanged();
        bench.sizeSweep(scaling);
        bench.ratios(scaling);
        return 0;
    });
}
