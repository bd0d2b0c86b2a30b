// Average erroneous pixels of every flood variant over many random inputs (thesis Fig. 4.14):
// 1,000 random integer sites on 512² by default, --runs inputs, CPU kernel (identical to the GL
// kernels texel for texel, see tests/jfa_gl_kernel_gltest.cpp), errors against the exact EDT.

#include <jfa/CpuKernel.h>
#include <jfa/ErrorAnalysis.h>
#include <jfa/Reference.h>
#include <jfa/Sites.h>

#include <CLI/CLI.hpp>

#include <iomanip>
#include <iostream>

int main(int argc, char** argv) {
    using namespace fl::jfa;
    CLI::App app{"jfa_variants_bench: mean error pixels per variant over random inputs"};
    int size = 512, sites = 1000, runs = 100;
    app.add_option("--size", size)->check(CLI::Range(8, 4096))->capture_default_str();
    app.add_option("--sites", sites)->check(CLI::Range(3, 1 << 20))->capture_default_str();
    app.add_option("--runs", runs, "Random inputs (seeds 1..runs)")
        ->check(CLI::Range(1, 100000))
        ->capture_default_str();
    CLI11_PARSE(app, argc, argv);
    const std::vector<std::string> specs{"jfa",     "jfa+1",    "jfa+2",    "jfa2",       "1+jfa",
                                         "1+jfa+1", "doubling", "half:jfa", "half:jfa+2", "flood"};
    std::vector<double> sum(specs.size(), 0.0), maxErr(specs.size(), 0.0),
        singles(specs.size(), 0.0), atVertices(specs.size(), 0.0);
    double estimate = 0.0;
    for (int run = 1; run <= runs; ++run) {
        const Grid seeds =
            seedPoints(randomIntegerSites(sites, size, size, std::uint64_t(run)), size, size, true)
                .grid;
        const NearestSite crit{true};
        const ExactField exact = exactNearest(seeds, crit);
        const std::vector<Cell> siteList = siteCells(seeds);
        const ExactDiagramView view{size, size, siteList, exact.distSq, true};
        for (size_t v = 0; v < specs.size(); ++v) {
            const Plan plan = parsePlan(specs[v], size, size);
            const ErrorReport rep = analyzeErrors(flood(plan, seeds, crit), view, plan.name());
            sum[v] += double(rep.errorPixels);
            maxErr[v] = std::max(maxErr[v], double(rep.errorPixels));
            singles[v] += double(rep.singles);
            atVertices[v] += double(rep.singlesAtVertices);
            if (v == 0) estimate += rep.estimate.e;
        }
        if (run % 10 == 0) std::cerr << "  " << run << "/" << runs << " inputs\r" << std::flush;
    }
    std::cout << "\n"
              << size << "x" << size << ", " << sites << " random integer sites, " << runs
              << " inputs (seeds 1.." << runs << "), CPU kernel, errors vs exact EDT\n"
              << std::fixed << std::setprecision(2);
    for (size_t v = 0; v < specs.size(); ++v)
        std::cout << "  " << std::left << std::setw(14) << parsePlan(specs[v], size, size).name()
                  << std::right << " mean " << std::setw(9) << sum[v] / runs
                  << " error pixels, max " << std::setw(6) << maxErr[v]
                  << ", singles at Voronoi vertices "
                  << (singles[v] > 0 ? 100.0 * atVertices[v] / singles[v] : 0.0) << "%\n";
    std::cout << "  estimate E (JFA), mean " << estimate / runs << "\n";
    return 0;
}
