// The exact Voronoi repair (jfa/ExactRepair.h, geometry/SiteGraph.h; issue 31 item 3) on the
// CPU: after JFA, after floods that leave most texels wrong or empty, and on clustered,
// collinear, co-circular and mask sites, the repaired grid has 0 error pixels against the exact
// reference (the same count `voronoi` prints) and every texel holds a real site.

#include "VoronoiCases.h"

#include <geometry/SiteGraph.h>

#include <jfa/CpuKernel.h>
#include <jfa/ExactRepair.h>
#include <jfa/Plan.h>
#include <jfa/Reference.h>
#include <jfa/Sites.h>

#include <gtest/gtest.h>

#include <set>
#include <tuple>

namespace fl::jfa {
namespace {

const NearestSite kCriterion{true};

// Repairs `flooded` on `graph` and checks it against the exact field of `seeds`, and the row
// interval shortcut against walks from every texel (the definition).
void expectExact(Grid flooded, const SiteGraph& graph, const Grid& seeds, const char* what) {
    Grid walked = flooded;
    repairNearest(walked, graph, 2, RepairMethod::Walks);
    repairNearest(flooded, graph, 2, RepairMethod::RowIntervals);
    EXPECT_EQ(flooded, walked) << what << ": row intervals differ from the walks";
    const ExactField exact = exactNearest(seeds, kCriterion);
    EXPECT_EQ(countErrors(flooded, exact, kCriterion), 0) << what;
    std::set<std::tuple<float, float, float>> sites;
    for (const Cell& c : siteCells(seeds)) sites.insert({c.x, c.y, c.z});
    std::int64_t unknown = 0;
    for (const Cell& c : flooded.cells) unknown += sites.count({c.x, c.y, c.z}) == 0;
    EXPECT_EQ(unknown, 0) << what << ": texels that hold no site";
}

TEST(ExactRepair, EveryCaseAfterJfaAndAfterBadFloods) {
    std::int64_t jfaErrors = 0;
    for (const test::VoronoiCase& c : test::voronoiCases(96)) {
        SCOPED_TRACE(c.name);
        Grid seeds = c.seeds;
        const SiteGraph graph = geom::buildSiteGraph(seeds);
        const Grid jfa = flood(Plan::jfa(seeds.width, seeds.height), seeds, kCriterion);
        jfaErrors += countErrors(jfa, exactNearest(seeds, kCriterion), kCriterion);
        expectExact(jfa, graph, seeds, "after JFA");
        // Floods that leave most texels empty, or every texel wrong: walks from vertex 0 and
        // from a far site must still end at a nearest site.
        expectExact(flood(Plan::flood(1, seeds.width, seeds.height), seeds, kCriterion), graph,
                    seeds, "after flood:1");
        Grid wrong = seeds;
        if (!graph.vertices.empty())
            for (Cell& cell : wrong.cells)
                if (kCriterion.empty(cell)) cell = graph.vertices.back();
        expectExact(wrong, graph, seeds, "every texel the last vertex");
    }
    // The cases are hard for JFA itself, or the test would prove little.
    EXPECT_GT(jfaErrors, 0);
}

// Many small random inputs, walks from an empty flood (vertex 0): the greedy property checked
// against brute force, which records NearestSite's tie winner; distances must match exactly.
TEST(ExactRepair, RandomSmallGridsAgainstBruteForce) {
    SplitMix64 rng(31);
    for (int trial = 0; trial < 300; ++trial) {
        const int w = 2 + int(rng.below(30)), h = 2 + int(rng.below(30));
        const int n = 1 + int(rng.below(std::uint64_t(std::min(w * h, 60))));
        Grid seeds = seedPoints(randomIntegerSites(n, w, h, rng.next()), w, h, true).grid;
        const SiteGraph graph = geom::buildSiteGraph(seeds);
        Grid repaired = flood(Plan::flood(1, w, h), seeds, kCriterion);
        repairNearest(repaired, graph, 1);
        const ExactField brute = bruteForceNearest(seeds, kCriterion);
        ASSERT_EQ(countErrors(repaired, brute, kCriterion), 0)
            << "trial " << trial << ": " << n << " sites on " << w << "x" << h;
    }
}

TEST(ExactRepair, ThreadCountsAgree) {
    Grid seeds = seedPoints(randomIntegerSites(500, 128, 96, 3), 128, 96, true).grid;
    const SiteGraph graph = geom::buildSiteGraph(seeds);
    const Grid jfa = flood(Plan::jfa(128, 96), seeds, kCriterion);
    Grid one = jfa, many = jfa;
    repairNearest(one, graph, 1);
    repairNearest(many, graph, 3);
    EXPECT_EQ(one, many);
}

TEST(ExactRepair, GraphKeepsOnlyBoundarySitesAndTagsTheSeeds) {
    // A 5x5 solid block: its 9 inner sites are never a non-site pixel's nearest.
    std::vector<std::uint8_t> mask(20 * 20, 0);
    for (int y = 4; y < 9; ++y)
        for (int x = 6; x < 11; ++x) mask[std::size_t(y) * 20 + std::size_t(x)] = 1;
    Grid seeds = seedMask(mask, 20, 20);
    const SiteGraph graph = geom::buildSiteGraph(seeds);
    EXPECT_EQ(graph.vertices.size(), 16u);
    ASSERT_EQ(graph.offsets.size(), 17u);
    for (std::size_t v = 0; v < graph.vertices.size(); ++v) {
        const Cell& c = graph.vertices[v];
        EXPECT_EQ(c.w, float(v));
        EXPECT_EQ(seeds.at(int(c.x), int(c.y)), c);
        EXPECT_GT(graph.offsets[v + 1], graph.offsets[v]) << "vertex " << v << " has no edge";
    }
    for (const Cell& c : seeds.cells) {
        if (!kCriterion.empty(c)) {
            EXPECT_LT(c.w, 16.0f);
        }
    }
}

TEST(ExactRepair, RefusesWhatItCannotRepair) {
    Grid sub = seedPoints({{1.25f, 2.5f}, {5.0f, 5.0f}}, 8, 8, false).grid;
    EXPECT_THROW((void)geom::buildSiteGraph(sub), std::invalid_argument);
    Grid seeds = seedPoints({{1, 2}, {5, 5}, {7, 1}}, 8, 8, true).grid;
    std::vector<Cell> sites = siteCells(seeds);
    std::swap(sites[0], sites[1]); // not row-major
    EXPECT_THROW((void)geom::buildSiteGraph(seeds, sites), std::invalid_argument);
    sites = siteCells(seeds);
    sites[1].x += 1.0f; // not where the seeds hold it
    EXPECT_THROW((void)geom::buildSiteGraph(seeds, sites), std::invalid_argument);
    const SiteGraph graph = geom::buildSiteGraph(seeds);
    Grid bad = flood(Plan::jfa(8, 8), seeds, kCriterion);
    bad.at(0, 7).w = 99.0f; // names a vertex the graph does not have
    EXPECT_THROW(repairNearest(bad, graph), std::invalid_argument);
}

} // namespace
} // namespace fl::jfa
