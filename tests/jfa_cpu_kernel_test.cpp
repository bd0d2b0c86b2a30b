// The CPU flood kernel (jfa/CpuKernel.h): the exact semantics the GL kernels replicate, checked on
// hand-checkable grids, plus Property 3.1, accuracy against brute force, thread determinism,
// half resolution, until-unchanged and the per-pass callback.
#include <jfa/CpuKernel.h>
#include <jfa/NearestSite.h>
#include <jfa/Reference.h>
#include <jfa/Sites.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <iostream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace fl::jfa {
namespace {

Cell site(int x, int y, int id) {
    return Cell{float(x), float(y), float(id), 0.0f};
}

Grid randomSeeds(int w, int h, int count, std::uint64_t seed, bool integer) {
    const std::vector<Site> sites =
        integer ? randomIntegerSites(count, w, h, seed) : randomFloatSites(count, w, h, seed);
    return seedPoints(sites, w, h, integer).grid;
}

// A plan of explicit stages (the last one full resolution).
Plan custom(std::vector<Stage> stages) {
    return Plan("custom", std::move(stages));
}

// ---- Property 3.1: one seed fills any grid
// -------------------------------------------------------

TEST(CpuKernel, OneSeedFillsAnyGrid) {
    const std::vector<std::pair<int, int>> sizes{{1, 1}, {2, 1},     {1, 2},   {3, 3},
                                                 {7, 3}, {300, 200}, {513, 7}, {7, 513}};
    for (auto [w, h] : sizes) {
        const std::vector<std::pair<int, int>> positions{
            {0, 0}, {w - 1, h - 1}, {w - 1, 0}, {0, h - 1}, {w / 2, h / 3}};
        for (auto [sx, sy] : positions) {
            for (const char* spec : {"jfa", "1+jfa", "jfa+2", "jfa2", "doubling", "half:jfa"}) {
                Grid seeds(w, h);
                seeds.at(sx, sy) = site(sx, sy, 5);
                const Grid out = flood(parsePlan(spec, w, h), seeds, NearestSite{}, {2, {}});
                ASSERT_EQ(out.width, w);
                ASSERT_EQ(out.height, h);
                for (const Cell& c : out.cells) {
                    ASSERT_EQ(c, seeds.at(sx, sy))
                        << spec << " on " << w << "x" << h << " from (" << sx << ", " << sy << ")";
                }
            }
        }
    }
}

TEST(CpuKernel, PlanWithoutPassesReturnsTheSeeds) {
    Grid seeds(1, 1);
    seeds.at(0, 0) = site(0, 0, 3);
    const FloodResult result = floodWithStats(Plan::jfa(1, 1), seeds, NearestSite{});
    EXPECT_EQ(result.passesRun(), 0);
    EXPECT_EQ(result.grid, seeds);
}

// ---- one pass, by hand
// ---------------------------------------------------------------------------

TEST(CpuKernel, PassReadsThePreviousGridNotItsOwnOutput) {
    // 5x1, sites at both ends. Pass 1 (step 1): x = 1 and x = 3 pick up their neighbour's site;
    // x = 2 reads only empty cells (an in-place left-to-right sweep would have given it site 0).
    Grid seeds(5, 1);
    seeds.at(0, 0) = site(0, 0, 0);
    seeds.at(4, 0) = site(4, 0, 1);
    std::vector<Grid> after;
    FloodOptions options;
    options.onPass = [&](int, const Pass&, const Grid& g) { after.push_back(g); };
    const FloodResult result =
        floodWithStats(custom({Stage{5, 1, {1, 1}}}), seeds, NearestSite{}, options);
    ASSERT_EQ(after.size(), 2u);
    EXPECT_EQ(after[0].at(0, 0), site(0, 0, 0));
    EXPECT_EQ(after[0].at(1, 0), site(0, 0, 0));
    EXPECT_EQ(after[0].at(2, 0), kEmptyCell);
    EXPECT_EQ(after[0].at(3, 0), site(4, 0, 1));
    EXPECT_EQ(after[0].at(4, 0), site(4, 0, 1));
    EXPECT_EQ(result.passes[0].changed, 2);
    // Pass 2: x = 2 is 2 from both sites; the tie goes to the smaller id.
    EXPECT_EQ(after[1].at(2, 0), site(0, 0, 0));
    EXPECT_EQ(result.passes[1].changed, 1);
    EXPECT_EQ(result.grid, after[1]);
}

TEST(CpuKernel, CandidatesOutsideTheGridAreSkipped) {
    // 4x1, seed at x = 0. Step 2 reaches x = 2 only; step 3 reaches x = 3 only (no wrapping,
    // no clamping to the border).
    Grid seeds(4, 1);
    seeds.at(0, 0) = site(0, 0, 7);
    const Grid two = flood(custom({Stage{4, 1, {2}}}), seeds, NearestSite{});
    EXPECT_EQ(two.at(1, 0), kEmptyCell);
    EXPECT_EQ(two.at(2, 0), site(0, 0, 7));
    EXPECT_EQ(two.at(3, 0), kEmptyCell);
    const Grid three = flood(custom({Stage{4, 1, {3}}}), seeds, NearestSite{});
    EXPECT_EQ(three.at(1, 0), kEmptyCell);
    EXPECT_EQ(three.at(2, 0), kEmptyCell);
    EXPECT_EQ(three.at(3, 0), site(0, 0, 7));
    // A step larger than the grid reads only the texel itself: the pass changes nothing.
    const FloodResult big = floodWithStats(custom({Stage{4, 1, {1000}}}), seeds, NearestSite{});
    EXPECT_EQ(big.grid, seeds);
    EXPECT_EQ(big.passes[0].changed, 0);
}

TEST(CpuKernel, StepKReachesTheNineOffsets) {
    Grid seeds(5, 5);
    seeds.at(2, 2) = site(2, 2, 0);
    const Grid out = flood(custom({Stage{5, 5, {2}}}), seeds, NearestSite{});
    for (int y = 0; y < 5; ++y) {
        for (int x = 0; x < 5; ++x) {
            const bool reached = x % 2 == 0 && y % 2 == 0;
            EXPECT_EQ(out.at(x, y), reached ? site(2, 2, 0) : kEmptyCell) << x << ", " << y;
        }
    }
}

TEST(CpuKernel, AllEmptyCandidatesGiveTheCanonicalEmptyCell) {
    // Empty cells may carry anything; a texel that reads only empty cells writes kEmptyCell, and
    // that counts as a change (the GL kernels behave the same).
    Grid seeds(3, 1, Cell{9.0f, 9.0f, -3.0f, 1.0f});
    const FloodResult result = floodWithStats(custom({Stage{3, 1, {1}}}), seeds, NearestSite{});
    for (const Cell& c : result.grid.cells) EXPECT_EQ(c, kEmptyCell);
    EXPECT_EQ(result.passes[0].changed, 3);
}

// ---- accuracy against brute force
// ----------------------------------------------------------------

TEST(CpuKernel, StandardFloodingMatchesBruteForceOnRandomIntegerSites) {
    // Observed on these inputs (not a theorem: see the float counterexample below): standard
    // flooding until unchanged finds NearestSite's winner everywhere, ties included.
    for (std::uint64_t seed = 0; seed < 60; ++seed) {
        const int w = 24 + int(seed % 9), h = 17 + int(seed % 5), count = 2 + int(seed % 40);
        const Grid seeds = randomSeeds(w, h, count, seed, true);
        const Grid out = flood(Plan::floodUntilUnchanged(w, h), seeds, NearestSite{true});
        EXPECT_EQ(out, bruteForceNearest(seeds, NearestSite{true}).nearest) << "seed " << seed;
    }
}

TEST(CpuKernel, JfaSquaredIsExactOnTheseInputs) {
    // Observed on these inputs; JFA^2 is not exact in general (see below).
    for (bool integer : {true, false}) {
        const NearestSite crit{integer};
        for (std::uint64_t seed = 0; seed < 40; ++seed) {
            const Grid seeds = randomSeeds(40, 30, 5 + int(seed % 30), seed, integer);
            const ExactField exact = bruteForceNearest(seeds, crit);
            EXPECT_EQ(countErrors(flood(Plan::jfaSquared(40, 30), seeds, crit), exact, crit), 0)
                << "seed " << seed << (integer ? " integer" : " float");
        }
    }
}

TEST(CpuKernel, ErrorsOfJfaAndItsVariants) {
    // JFA misses nearest sites (thesis Fig. 3.3), extra passes remove most of those misses, 1+JFA
    // more than JFA+1 (§4.5.2), and doubling (Fig. 3.2a) makes many more; totals over the same
    // 100 inputs.
    std::int64_t jfa = 0, jfaPlus1 = 0, jfaPlus2 = 0, onePlusJfa = 0, doubling = 0;
    const NearestSite crit{true};
    for (std::uint64_t seed = 0; seed < 100; ++seed) {
        const Grid seeds = randomSeeds(64, 48, 30, seed, true);
        const ExactField exact = exactNearest(seeds, crit);
        auto errors = [&](const char* spec) {
            return countErrors(flood(parsePlan(spec, 64, 48), seeds, crit), exact, crit);
        };
        jfa += errors("jfa");
        jfaPlus1 += errors("jfa+1");
        jfaPlus2 += errors("jfa+2");
        onePlusJfa += errors("1+jfa");
        doubling += errors("doubling");
    }
    EXPECT_GT(jfa, 0);
    EXPECT_LT(jfaPlus1, jfa);
    EXPECT_LT(jfaPlus2, jfaPlus1);
    EXPECT_LT(onePlusJfa, jfaPlus1);
    EXPECT_GT(doubling, 5 * jfa);
    std::cout << "errors over 100 inputs (64x48, 30 sites): JFA " << jfa << ", JFA+1 " << jfaPlus1
              << ", JFA+2 " << jfaPlus2 << ", 1+JFA " << onePlusJfa << ", doubling " << doubling
              << "\n";
}

TEST(CpuKernel, NeitherJfaSquaredNorStandardFloodingIsAlwaysExact) {
    // Inputs found by search. Integer sites, 24x24, 6 sites: JFA^2 misses one grid point.
    {
        const NearestSite crit{true};
        const Grid seeds = randomSeeds(24, 24, 6, 3388 * 131 + 6, true);
        const ExactField exact = bruteForceNearest(seeds, crit);
        EXPECT_EQ(countErrors(flood(Plan::jfaSquared(24, 24), seeds, crit), exact, crit), 1);
        EXPECT_EQ(countErrors(flood(Plan::floodUntilUnchanged(24, 24), seeds, crit), exact, crit),
                  0);
    }
    // Sub-pixel sites, 16x16, 12 sites: standard flooding until unchanged misses one grid point,
    // whose nearest site never passes through any of its 8 neighbours (thesis Fig. 4.2).
    {
        const NearestSite crit{false};
        const Grid seeds = randomSeeds(16, 16, 12, 402, false);
        const ExactField exact = bruteForceNearest(seeds, crit);
        EXPECT_EQ(countErrors(flood(Plan::floodUntilUnchanged(16, 16), seeds, crit), exact, crit),
                  1);
    }
}

// ---- threads
// --------------------------------------------------------------------------------------

TEST(CpuKernel, ThreadCountDoesNotChangeTheResult) {
    for (bool integer : {true, false}) {
        const Grid seeds = randomSeeds(300, 200, 500, 9, integer);
        for (const char* spec : {"jfa", "half:jfa+2", "flood:20", "flood"}) {
            const Plan plan = parsePlan(spec, 300, 200);
            const FloodResult one = floodWithStats(plan, seeds, NearestSite{integer}, {1, {}});
            for (int threads : {2, 7, 0}) {
                const FloodResult many =
                    floodWithStats(plan, seeds, NearestSite{integer}, {threads, {}});
                EXPECT_EQ(many.grid, one.grid) << spec << ", " << threads << " threads";
                ASSERT_EQ(many.passesRun(), one.passesRun());
                for (int i = 0; i < one.passesRun(); ++i)
                    EXPECT_EQ(many.passes[std::size_t(i)].changed,
                              one.passes[std::size_t(i)].changed);
            }
        }
    }
}

TEST(CpuKernel, MoreThreadsThanRows) {
    Grid seeds(9, 2);
    seeds.at(8, 1) = site(8, 1, 0);
    const Grid out = flood(Plan::jfa(9, 2), seeds, NearestSite{}, {16, {}});
    for (const Cell& c : out.cells) EXPECT_EQ(c, site(8, 1, 0));
    EXPECT_EQ(bandCount(2, 16), 2);
    EXPECT_EQ(bandCount(100, 3), 3);
}

// A criterion that throws, to check that worker exceptions reach the caller.
struct Throwing {
    static constexpr const char* glslFile = "none.glsl";
    bool empty(const Cell& c) const { return c.z < 0.0f; }
    bool better(int, int py, const Cell&, const Cell&) const {
        if (py > 50) throw std::runtime_error("criterion failed");
        return false;
    }
};

TEST(CpuKernel, ExceptionsInWorkersReachTheCaller) {
    Grid seeds(4, 100, site(0, 0, 0));
    EXPECT_THROW(flood(Plan::jfa(4, 100), seeds, Throwing{}, {4, {}}), std::runtime_error);
}

// ---- half resolution
// ------------------------------------------------------------------------------

TEST(CpuKernel, DownsampleKeepsTheBestSiteOfEachBlockAtItsGridPoint) {
    // 5x3 -> 3x2. Block (0,0) = cells (0..1, 0..1) judged at grid point (0,0): (0,1) id 2
    // (d2 = 1) beats (1,1) id 5 (d2 = 2). Block (1,0) at (2,0): (3,0) id 1 and (2,1) id 0 are
    // both at d2 = 1; the smaller id wins. Block (2,0) is the partial column x = 4. Row 1 of the
    // half grid covers only y = 2.
    Grid full(5, 3);
    full.at(1, 1) = site(1, 1, 5);
    full.at(0, 1) = site(0, 1, 2);
    full.at(3, 0) = site(3, 0, 1);
    full.at(2, 1) = site(2, 1, 0);
    full.at(4, 1) = site(4, 1, 7);
    full.at(3, 2) = site(3, 2, 9);
    const Grid half = downsample(full, 2, NearestSite{});
    ASSERT_EQ(half.width, 3);
    ASSERT_EQ(half.height, 2);
    EXPECT_EQ(half.at(0, 0), site(0, 1, 2));
    EXPECT_EQ(half.at(1, 0), site(2, 1, 0));
    EXPECT_EQ(half.at(2, 0), site(4, 1, 7));
    EXPECT_EQ(half.at(0, 1), kEmptyCell);
    EXPECT_EQ(half.at(1, 1), site(3, 2, 9));
    EXPECT_EQ(half.at(2, 1), kEmptyCell);

    // Through a plan: no half-resolution pass, expansion, then a pass that reads only itself.
    // Expansion refines each texel among the sites of its representative's block (thesis
    // §4.3.2): block (0,0) holds ids 2 and 5, block (1,0) ids 0 and 1, so every site gets back
    // its own pixel; (2,0) and (3,1) are ties between ids 0 and 1 (d2 = 1), won by id 0.
    const Grid out =
        flood(custom({Stage{3, 2, {}}, Stage{5, 3, {1000}}}), full, NearestSite{}, {1, {}});
    ASSERT_EQ(out.width, 5);
    const int expectedIds[3][5] = {{2, 5, 0, 1, 7}, {2, 5, 0, 0, 7}, {-1, -1, 9, 9, -1}};
    for (int y = 0; y < 3; ++y) {
        for (int x = 0; x < 5; ++x)
            EXPECT_EQ(out.at(x, y).z, float(expectedIds[y][x])) << x << ", " << y;
    }
    EXPECT_EQ(expandStage(half, 5, 3, 2, full, NearestSite{}), out);
    // The plain 2x copy underneath, and its size check.
    EXPECT_EQ(expand(half, 5, 3).at(1, 1), half.at(0, 0));
    EXPECT_THROW(expand(half, 7, 3), std::invalid_argument);
}

TEST(CpuKernel, HalfResolutionPassesMeasureAtFullResolutionGridPoints) {
    // 8x1 -> 4x1. A (id 5) at x = 0 lies in half texel 0, B (id 1) at x = 4 in half texel 2.
    // Half texel 1 stands for grid point x = 2, equidistant from both: B wins on its id. (Texel
    // 1 judged as grid point x = 1 would pick A.)
    Grid full(8, 1);
    full.at(0, 0) = site(0, 0, 5);
    full.at(4, 0) = site(4, 0, 1);
    const Grid out = flood(custom({Stage{4, 1, {1}}, Stage{8, 1, {1000}}}), full, NearestSite{});
    const std::vector<int> expected{5, 5, 1, 1, 1, 1, 1, 1};
    for (int x = 0; x < 8; ++x) EXPECT_EQ(out.at(x, 0).z, float(expected[std::size_t(x)])) << x;
    EXPECT_EQ(stageScale(Plan::halfResolution(8, 1), 0), 2);
    EXPECT_EQ(stageScale(Plan::halfResolution(8, 1), 1), 1);
}

TEST(CpuKernel, HalfResolutionExpandsBeforeItsFullResolutionPass) {
    // half:jfa on 6x4: stage 3x2 (steps 2 1), then expand + one step-1 pass at 6x4.
    const Grid seeds = randomSeeds(6, 4, 3, 4, true);
    const Plan plan = Plan::halfResolution(6, 4);
    Grid lastHalf;
    std::vector<Pass> seen;
    FloodOptions options;
    options.onPass = [&](int, const Pass& pass, const Grid& g) {
        seen.push_back(pass);
        if (!pass.expandBefore) lastHalf = g;
    };
    const Grid out = flood(plan, seeds, NearestSite{}, options);
    EXPECT_EQ(seen, plan.passes());
    ASSERT_TRUE(seen.back().expandBefore);
    Grid expected;
    runPass(expandStage(lastHalf, 6, 4, 2, seeds, NearestSite{}), expected, 1, 1, NearestSite{}, 1);
    EXPECT_EQ(out, expected);
}

// ---- until unchanged and the callback
// -------------------------------------------------------------

TEST(CpuKernel, UntilUnchangedStopsAfterTheFirstPassWithoutChanges) {
    // From a corner of 10x10 the front moves one ring per pass: pass k changes the 2k + 1 texels
    // at Chebyshev distance k; pass 10 changes nothing and ends the stage (cap: 20 passes).
    Grid seeds(10, 10);
    seeds.at(0, 0) = site(0, 0, 0);
    const Plan plan = Plan::floodUntilUnchanged(10, 10);
    ASSERT_EQ(plan.passCount(), 20);
    std::vector<int> indices;
    FloodOptions options;
    options.onPass = [&](int i, const Pass& pass, const Grid&) {
        indices.push_back(i);
        EXPECT_TRUE(pass.untilUnchanged);
    };
    const FloodResult result = floodWithStats(plan, seeds, NearestSite{}, options);
    ASSERT_EQ(result.passesRun(), 10);
    for (int k = 1; k <= 9; ++k) EXPECT_EQ(result.passes[std::size_t(k - 1)].changed, 2 * k + 1);
    EXPECT_EQ(result.passes[9].changed, 0);
    EXPECT_EQ(indices, (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9}));
    for (const Cell& c : result.grid.cells) EXPECT_EQ(c, site(0, 0, 0));
}

TEST(CpuKernel, UntilUnchangedSkipsOnlyTheRestOfItsStage) {
    // half:flood on 10x10: the 5x5 stage (cap 10) stops after 5 passes; the full-resolution pass
    // still runs and keeps its index in plan.passes() (10).
    Grid seeds(10, 10);
    seeds.at(1, 1) = site(1, 1, 0);
    const Plan plan = parsePlan("half:flood", 10, 10);
    std::vector<int> indices;
    FloodOptions options;
    options.onPass = [&](int i, const Pass&, const Grid&) { indices.push_back(i); };
    const FloodResult result = floodWithStats(plan, seeds, NearestSite{}, options);
    EXPECT_EQ(indices, (std::vector<int>{0, 1, 2, 3, 4, 10}));
    EXPECT_EQ(result.passes.back().passIndex, 10);
    EXPECT_TRUE(result.passes.back().pass.expandBefore);
    for (const Cell& c : result.grid.cells) EXPECT_EQ(c, site(1, 1, 0));
}

TEST(CpuKernel, CallbackSeesEveryPassInOrder) {
    const Grid seeds = randomSeeds(64, 48, 20, 3, true);
    const Plan plan = Plan::jfaPlus(2, 64, 48);
    const std::vector<Pass> passes = plan.passes();
    int calls = 0;
    Grid last;
    FloodOptions options;
    options.threads = 3;
    options.onPass = [&](int i, const Pass& pass, const Grid& after) {
        EXPECT_EQ(i, calls);
        EXPECT_EQ(pass, passes[std::size_t(i)]);
        EXPECT_EQ(after.width, pass.width);
        ++calls;
        last = after;
    };
    const FloodResult result = floodWithStats(plan, seeds, NearestSite{}, options);
    EXPECT_EQ(calls, plan.passCount());
    EXPECT_EQ(result.passesRun(), plan.passCount());
    EXPECT_EQ(result.grid, last);
}

TEST(CpuKernel, RejectsMismatchedSeedsAndThreadCounts) {
    EXPECT_THROW(flood(Plan::jfa(8, 8), Grid(8, 7), NearestSite{}), std::invalid_argument);
    EXPECT_THROW(flood(Plan::jfa(8, 8), Grid(8, 8), NearestSite{}, {-1, {}}),
                 std::invalid_argument);
}

// Any criterion: the largest value (cell x) wins, ties by id.
struct Brightest {
    static constexpr const char* glslFile = "none.glsl";
    bool empty(const Cell& c) const { return c.z < 0.0f; }
    bool better(int, int, const Cell& a, const Cell& b) const {
        return a.x != b.x ? a.x > b.x : a.z < b.z;
    }
};
static_assert(Criterion<Brightest>);

TEST(CpuKernel, RunsAnyCriterion) {
    Grid seeds(33, 20);
    seeds.at(3, 4) = Cell{2.0f, 0.0f, 0.0f, 0.0f};
    seeds.at(30, 17) = Cell{9.0f, 0.0f, 1.0f, 0.0f};
    seeds.at(12, 0) = Cell{5.0f, 0.0f, 2.0f, 0.0f};
    const Grid out = flood(Plan::jfa(33, 20), seeds, Brightest{});
    for (const Cell& c : out.cells) EXPECT_EQ(c, seeds.at(30, 17));
}

} // namespace
} // namespace fl::jfa
