// 3D jump flooding (thesis §4.6): Property 3.1 in 3D, thread-count independence, the exact
// separable EDT against brute force, the slice-by-slice variant, error counts and a small run of
// the Fig. 4.16 / 4.17 experiment. Pure CPU.
#include <jfa/Jfa3d.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <iostream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace fl::jfa {
namespace {

std::vector<int> concat(std::vector<int> a, const std::vector<int>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

// Comparison key of site c for voxel (x, y, z): distance, then id, then index.
std::tuple<std::int64_t, int, std::int32_t> key(const std::vector<Site3>& sites, std::int32_t c,
                                                int x, int y, int z) {
    const Site3& s = sites[std::size_t(c)];
    const std::int64_t dx = s.x - x, dy = s.y - y, dz = s.z - z;
    return {dx * dx + dy * dy + dz * dz, s.id, c};
}

// A direct transcription of 3D JFA (27 reads per voxel with bounds checks) to check the kernel's
// row pointers and shortcuts against.
SiteGrid3 naiveFlood3d(const std::vector<Site3>& sites, Extent3 e, const std::vector<int>& steps) {
    SiteGrid3 grid(e);
    for (std::size_t i = 0; i < sites.size(); ++i) {
        const Site3& s = sites[i];
        std::int32_t& cell = grid.cells[grid.index(s.x, s.y, s.z)];
        if (cell == kNoSite || key(sites, std::int32_t(i), 0, 0, 0) < key(sites, cell, 0, 0, 0)) {
            cell = std::int32_t(i);
        }
    }
    for (int k : steps) {
        SiteGrid3 next(e);
        for (int z = 0; z < e.depth; ++z)
            for (int y = 0; y < e.height; ++y)
                for (int x = 0; x < e.width; ++x) {
                    std::int32_t best = kNoSite;
                    for (int l = -1; l <= 1; ++l)
                        for (int j = -1; j <= 1; ++j)
                            for (int i = -1; i <= 1; ++i) {
                                const int nx = x + i * k, ny = y + j * k, nz = z + l * k;
                                if (nx < 0 || ny < 0 || nz < 0 || nx >= e.width || ny >= e.height ||
                                    nz >= e.depth)
                                    continue;
                                const std::int32_t c = grid.at(nx, ny, nz);
                                if (c != kNoSite &&
                                    (best == kNoSite ||
                                     key(sites, c, x, y, z) < key(sites, best, x, y, z)))
                                    best = c;
                            }
                    next.cells[next.index(x, y, z)] = best;
                }
        grid = next;
    }
    return grid;
}

// The same for slice-by-slice: project by brute force, then 2D passes with 9 reads per pixel.
SiteGrid3 naiveSliceBySlice(const std::vector<Site3>& sites, Extent3 e,
                            const std::vector<int>& steps) {
    SiteGrid3 result(e);
    for (int c = 0; c < e.depth; ++c) {
        SiteGrid3 slice(Extent3{e.width, e.height, 1});
        for (std::size_t i = 0; i < sites.size(); ++i) {
            const Site3& s = sites[i];
            std::int32_t& cell = slice.cells[slice.index(s.x, s.y, 0)];
            const auto nearness = [&](std::int32_t j) {
                return std::tuple{std::abs(sites[std::size_t(j)].z - c), sites[std::size_t(j)].id,
                                  j};
            };
            if (cell == kNoSite || nearness(std::int32_t(i)) < nearness(cell))
                cell = std::int32_t(i);
        }
        for (int k : steps) {
            SiteGrid3 next = slice;
            for (int y = 0; y < e.height; ++y)
                for (int x = 0; x < e.width; ++x) {
                    std::int32_t best = kNoSite;
                    for (int j = -1; j <= 1; ++j)
                        for (int i = -1; i <= 1; ++i) {
                            const int nx = x + i * k, ny = y + j * k;
                            if (nx < 0 || ny < 0 || nx >= e.width || ny >= e.height) continue;
                            const std::int32_t cand = slice.at(nx, ny, 0);
                            if (cand != kNoSite &&
                                (best == kNoSite ||
                                 key(sites, cand, x, y, c) < key(sites, best, x, y, c)))
                                best = cand;
                        }
                    next.cells[next.index(x, y, 0)] = best;
                }
            slice = next;
        }
        for (int y = 0; y < e.height; ++y)
            for (int x = 0; x < e.width; ++x)
                result.cells[result.index(x, y, c)] = slice.at(x, y, 0);
    }
    return result;
}

// ---- plans -------------------------------------------------------------------------------------

TEST(Jfa3dPlan, StepsComeFromThe2dPlansForTheLargestSide) {
    const Extent3 e{100, 30, 7};
    EXPECT_EQ(plan3d("jfa", e).steps(), jfaSteps(100));
    EXPECT_EQ(plan3d("jfa", Extent3{7, 30, 100}).steps(), jfaSteps(100));
    EXPECT_EQ(plan3d("jfa+1", e).steps(), concat(jfaSteps(100), {1}));
    EXPECT_EQ(plan3d("jfa+2", e).steps(), concat(jfaSteps(100), {2, 1}));
    EXPECT_EQ(plan3d("jfa2", e).steps(), concat(jfaSteps(100), jfaSteps(100)));
    EXPECT_EQ(plan3d("1+jfa", e).steps(), concat({1}, jfaSteps(100)));
    EXPECT_EQ(plan3d("jfa", Extent3{1, 1, 1}).steps(), std::vector<int>{});
    EXPECT_THROW(plan3d("half:jfa", e), std::invalid_argument);
    EXPECT_THROW(plan3d("nonsense", e), std::invalid_argument);
}

TEST(Jfa3dPlan, RejectsBadInput) {
    const Extent3 e{8, 8, 8};
    const std::vector<Site3> outside{{0, 0, 8, 0}};
    EXPECT_THROW(flood3d(outside, e, plan3d("jfa", e)), std::invalid_argument);
    EXPECT_THROW(exactSquaredDistances3d(outside, e), std::invalid_argument);
    EXPECT_THROW(flood3d({}, e, parsePlan("half:jfa", 8, 8)), std::invalid_argument);
    EXPECT_THROW(flood3d({}, Extent3{0, 8, 8}, plan3d("jfa", e)), std::invalid_argument);
    EXPECT_THROW(floodSliceBySlice({}, e, parsePlan("jfa", 8, 7)), std::invalid_argument);
    EXPECT_THROW(floodSlice({}, e, 8, parsePlan("jfa", 8, 8)), std::invalid_argument);
    EXPECT_THROW(randomSites3d(9, Extent3{2, 2, 2}, 1), std::invalid_argument);
}

// ---- Property 3.1 in 3D ------------------------------------------------------------------------

TEST(Jfa3dFill, SingleSiteFillsTheGridWhereverItIs) {
    const std::vector<Extent3> extents{{1, 1, 1},  {2, 2, 2},    {3, 3, 3},    {5, 5, 5},
                                       {7, 3, 9},  {16, 16, 16}, {17, 17, 17}, {33, 20, 9},
                                       {1, 1, 40}, {40, 1, 2},   {31, 32, 33}};
    for (const Extent3& e : extents) {
        const int w = e.width - 1, h = e.height - 1, d = e.depth - 1;
        const std::vector<Site3> positions{
            {0, 0, 0, 7}, {w, h, d, 7}, {w / 2, h / 2, d / 2, 7}, {w, 0, d / 3, 7}, {0, h, d, 7}};
        for (const Site3& site : positions) {
            for (const char* spec : {"jfa", "1+jfa", "doubling"}) {
                const SiteGrid3 grid = flood3d({site}, e, plan3d(spec, e), 2);
                EXPECT_EQ(grid.cells, std::vector<std::int32_t>(e.voxels(), 0))
                    << spec << " on " << e.width << "x" << e.height << "x" << e.depth
                    << ", site at (" << site.x << ", " << site.y << ", " << site.z << ")";
            }
            // Each slice floods its projection in 2D (Property 3.1 per slice).
            const SiteGrid3 slices =
                floodSliceBySlice({site}, e, parsePlan("jfa", e.width, e.height), 2);
            EXPECT_EQ(slices.cells, std::vector<std::int32_t>(e.voxels(), 0));
        }
    }
}

// ---- kernels against their direct transcription -------------------------------------------------

TEST(Jfa3dKernel, EqualsADirectTranscriptionOfTheAlgorithm) {
    for (const Extent3& e : {Extent3{23, 17, 19}, Extent3{9, 30, 4}, Extent3{16, 16, 16}}) {
        std::vector<Site3> sites = randomSites3d(60, e, 7);
        sites.push_back({sites[0].x, sites[0].y, sites[0].z, -5});    // shares a voxel
        sites.push_back({sites[1].x, sites[1].y, e.depth - 1, 1000}); // shares a column
        for (const char* spec : {"jfa", "1+jfa", "jfa+2", "jfa2", "doubling"}) {
            const Plan plan = plan3d(spec, e);
            EXPECT_EQ(flood3d(sites, e, plan, 2), naiveFlood3d(sites, e, plan.steps())) << spec;
            const Plan slicePlan = parsePlan(spec, e.width, e.height);
            EXPECT_EQ(floodSliceBySlice(sites, e, slicePlan, 2),
                      naiveSliceBySlice(sites, e, slicePlan.steps()))
                << spec;
        }
    }
}

// ---- determinism -------------------------------------------------------------------------------

TEST(Jfa3dThreads, ResultsAreIdenticalForOneTwoAndFiveThreads) {
    const Extent3 e{37, 29, 23};
    std::vector<Site3> sites = randomSites3d(150, e, 11);
    sites.push_back({sites[3].x, sites[3].y, sites[3].z, 200}); // same voxel, larger id
    sites.push_back({sites[5].x, sites[5].y, sites[5].z, -1});  // same voxel, smaller id
    for (const char* spec : {"jfa", "1+jfa", "jfa2", "flood"}) {
        const Plan plan = plan3d(spec, e);
        const SiteGrid3 one = flood3d(sites, e, plan, 1);
        EXPECT_EQ(flood3d(sites, e, plan, 2), one) << spec;
        EXPECT_EQ(flood3d(sites, e, plan, 5), one) << spec;
    }
    for (const char* spec : {"jfa", "1+jfa", "half:jfa+1"}) {
        const Plan plan = parsePlan(spec, e.width, e.height);
        const SiteGrid3 one = floodSliceBySlice(sites, e, plan, 1);
        EXPECT_EQ(floodSliceBySlice(sites, e, plan, 2), one) << spec;
        EXPECT_EQ(floodSliceBySlice(sites, e, plan, 5), one) << spec;
    }
    const auto exact = exactSquaredDistances3d(sites, e, 1);
    EXPECT_EQ(exactSquaredDistances3d(sites, e, 2), exact);
    EXPECT_EQ(exactSquaredDistances3d(sites, e, 5), exact);
}

// ---- exact reference ---------------------------------------------------------------------------

TEST(Jfa3dExact, SeparableTransformEqualsBruteForceOnRandomSmallInputs) {
    std::uint64_t state = 12345;
    const auto next = [&state](int n) { // small LCG, enough to vary shapes
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return int((state >> 33) % std::uint64_t(n));
    };
    for (int run = 0; run < 200; ++run) {
        const Extent3 e{1 + next(13), 1 + next(11), 1 + next(12)};
        const int count = 1 + next(std::min<int>(40, int(e.voxels())));
        std::vector<Site3> sites = randomSites3d(count, e, std::uint64_t(run));
        if (run % 3 == 0) sites.push_back({sites[0].x, sites[0].y, sites[0].z, 99}); // duplicate
        const SiteGrid3 brute = bruteForceNearest3d(sites, e);
        ASSERT_EQ(exactSquaredDistances3d(sites, e, 2), recordedSquaredDistances(brute, sites))
            << "run " << run << ": " << count << " sites in " << e.width << "x" << e.height << "x"
            << e.depth;
        EXPECT_EQ(countErrors3d(brute, sites, exactSquaredDistances3d(sites, e), "brute").erroneous,
                  0);
    }
    // Far-apart sites in a long thin grid and a single site in a corner.
    const Extent3 line{200, 1, 3};
    const std::vector<Site3> sparse{{0, 0, 0, 0}, {199, 0, 2, 1}, {120, 0, 1, 2}};
    EXPECT_EQ(exactSquaredDistances3d(sparse, line),
              recordedSquaredDistances(bruteForceNearest3d(sparse, line), sparse));
    EXPECT_EQ(exactSquaredDistances3d({}, line),
              std::vector<std::int64_t>(line.voxels(), kNoDistance));
}

TEST(Jfa3dExact, TiesGoToTheSmallerId) {
    const Extent3 e{5, 1, 1};
    const std::vector<Site3> sites{{0, 0, 0, 5}, {4, 0, 0, 2}};
    const SiteGrid3 brute = bruteForceNearest3d(sites, e);
    EXPECT_EQ(brute.at(2, 0, 0), 1); // equidistant: id 2 (index 1) wins
    EXPECT_EQ(flood3d(sites, e, plan3d("jfa", e)), brute);
    EXPECT_EQ(brute.at(1, 0, 0), 0);
}

// ---- slice by slice ----------------------------------------------------------------------------

TEST(Jfa3dSlice, ProjectionKeepsTheSiteNearestToTheSlice) {
    const Extent3 e{4, 3, 10};
    const std::vector<Site3> sites{
        {1, 2, 0, 0}, {1, 2, 9, 1}, {1, 2, 6, 4}, {1, 2, 2, 3}, {3, 0, 5, 8}};
    const auto at = [&](int slice, int x, int y) {
        return projectSites(sites, e, slice)[std::size_t(y * e.width + x)];
    };
    EXPECT_EQ(at(0, 1, 2), 0);
    EXPECT_EQ(at(1, 1, 2), 0); // |0 - 1| < |2 - 1|
    EXPECT_EQ(at(4, 1, 2), 3); // z = 2 and z = 6 tie: id 3 beats id 4
    EXPECT_EQ(at(5, 1, 2), 2); // z = 6
    EXPECT_EQ(at(8, 1, 2), 1); // z = 9
    EXPECT_EQ(at(0, 3, 0), 4); // the only site of its column, whatever its z
    EXPECT_EQ(at(0, 0, 0), kNoSite);
}

TEST(Jfa3dSlice, PlanarSitesGiveThe2dDiagramOnEverySlice) {
    // All sites on slice c: on slice c the problem is the 2D one, and on any other slice every
    // distance grows by the same dz^2, so every slice records the same sites. With these 12 sites
    // 1+JFA finds the exact 2D diagram (checked: it has no errors; JFA is not exact in general).
    const Extent3 e{61, 47, 9};
    const int c = 4;
    std::vector<Site3> planar = randomSites3d(12, Extent3{61, 47, 1}, 3);
    for (Site3& s : planar) s.z = c;
    const Plan plan = parsePlan("1+jfa", e.width, e.height);
    const SiteGrid3 slices = floodSliceBySlice(planar, e, plan, 2);
    const std::size_t sliceSize = std::size_t(e.width) * std::size_t(e.height);
    const std::vector<std::int32_t> onSlice(slices.cells.begin() + std::ptrdiff_t(c * sliceSize),
                                            slices.cells.begin() +
                                                std::ptrdiff_t((c + 1) * sliceSize));
    EXPECT_EQ(onSlice, floodSlice(planar, e, c, plan));
    for (int z = 0; z < e.depth; ++z) {
        EXPECT_EQ(
            std::vector<std::int32_t>(slices.cells.begin() + std::ptrdiff_t(z * sliceSize),
                                      slices.cells.begin() + std::ptrdiff_t((z + 1) * sliceSize)),
            onSlice)
            << "slice " << z;
    }
    // The same sites on a one-slice grid: exact 2D distances, and the 3D kernel (9 neighbours
    // when D = 1, the same steps) agrees with the slice flood.
    const Extent3 flat{61, 47, 1};
    std::vector<Site3> flatSites = planar;
    for (Site3& s : flatSites) s.z = 0;
    SiteGrid3 flatGrid(flat);
    flatGrid.cells = onSlice;
    EXPECT_EQ(recordedSquaredDistances(flatGrid, flatSites),
              exactSquaredDistances3d(flatSites, flat));
    EXPECT_EQ(flood3d(flatSites, flat, plan3d("1+jfa", flat)).cells, onSlice);
    EXPECT_EQ(flood3d(flatSites, flat, plan3d("jfa", flat)).cells,
              floodSlice(planar, e, c, parsePlan("jfa", e.width, e.height)));
}

TEST(Jfa3dSlice, HalfResolutionPlansFillEverySlice) {
    const Extent3 e{33, 20, 7};
    const std::vector<Site3> sites = randomSites3d(40, e, 5);
    for (const char* spec : {"half:jfa", "half:jfa+2"}) {
        const SiteGrid3 grid = floodSliceBySlice(sites, e, parsePlan(spec, e.width, e.height), 2);
        const ErrorCount3d count =
            countErrors3d(grid, sites, exactSquaredDistances3d(sites, e), spec);
        EXPECT_EQ(count.empty, 0) << count.describe();
        EXPECT_LT(count.erroneous, count.voxels / 20) << count.describe();
    }
}

// ---- errors ------------------------------------------------------------------------------------

TEST(Jfa3dErrors, DescribeSaysWhatWasCounted) {
    const Extent3 e{4, 4, 4};
    const std::vector<Site3> sites{{0, 0, 0, 0}, {3, 3, 3, 1}};
    const auto exact = exactSquaredDistances3d(sites, e);
    SiteGrid3 wrong(e);
    wrong.cells.assign(e.voxels(), 0); // everything to site 0: the far half is wrong
    wrong.cells[wrong.index(3, 3, 3)] = kNoSite;
    const ErrorCount3d count = countErrors3d(wrong, sites, exact, "test");
    EXPECT_EQ(count.erroneous, 32);
    EXPECT_EQ(count.empty, 1);
    EXPECT_EQ(count.describe(),
              "test on 4x4x4, 2 sites: 32 error voxels of 64 (50.0000%), 1 without a site");
    EXPECT_THROW(countErrors3d(wrong, sites, exactSquaredDistances3d({{1, 1, 1, 0}}, e), "x"),
                 std::invalid_argument);
}

TEST(Jfa3dErrors, MoreAndEarlierPassesDoNotAddErrors) {
    // Verified for exactly these inputs (48^3; 300 and 1500 sites; seeds 1..3), not theorems:
    // JFA^2 <= JFA in 3D on each input (JFA^2 had 0 errors on all six), and slice-by-slice
    // 1+JFA <= slice-by-slice JFA with 300 sites (45/41/56 vs 147/122/110 errors). With 1500
    // sites (1.4% of the voxels are sites) the slice ordering does NOT hold for seeds 2 and 3
    // (225 vs 210, 263 vs 229), so it is only printed there.
    const Extent3 e{48, 48, 48};
    const Plan jfa = plan3d("jfa", e), jfa2 = plan3d("jfa2", e);
    const Plan sliceJfa = parsePlan("jfa", 48, 48), slice1Jfa = parsePlan("1+jfa", 48, 48);
    for (int count : {300, 1500}) {
        for (std::uint64_t seed : {1, 2, 3}) {
            const std::vector<Site3> sites = randomSites3d(count, e, seed);
            const auto exact = exactSquaredDistances3d(sites, e);
            const auto errors = [&](const SiteGrid3& grid, const char* name) {
                const ErrorCount3d c = countErrors3d(grid, sites, exact, name);
                std::cout << c.describe() << "\n";
                EXPECT_EQ(c.empty, 0);
                return c.erroneous;
            };
            const std::int64_t e3 = errors(flood3d(sites, e, jfa), "3D JFA");
            const std::int64_t e3sq = errors(flood3d(sites, e, jfa2), "3D JFA^2");
            const std::int64_t es = errors(floodSliceBySlice(sites, e, sliceJfa), "slice JFA");
            const std::int64_t es1 = errors(floodSliceBySlice(sites, e, slice1Jfa), "slice 1+JFA");
            EXPECT_LE(e3sq, e3) << count << " sites, seed " << seed;
            if (count == 300) {
                EXPECT_LE(es1, es) << count << " sites, seed " << seed;
            }
        }
    }
}

// ---- the experiment ----------------------------------------------------------------------------

TEST(Jfa3dExperiment, SmallRunHasOneRowPerMethodAndFewErrors) {
    Experiment3dConfig config;
    config.sizes = {32};
    config.siteCounts = {100, 500};
    config.seeds = {1, 2};
    const std::vector<Experiment3dRow> rows = runExperiment3d(config);
    ASSERT_EQ(rows.size(), 2u * 6u);
    EXPECT_EQ(rows[0].method, "3D JFA");
    EXPECT_EQ(rows[3].method, "3D JFA^2");
    EXPECT_EQ(rows[5].method, "slice 1+JFA");
    for (const Experiment3dRow& row : rows) {
        std::cout << row.describe() << "\n";
        ASSERT_EQ(row.errorsPerSeed.size(), 2u);
        // Robust: JFA and its variants get all but a small fraction right (thesis: "close to
        // zero"); here under 1% of the 32^3 voxels for every method and seed.
        for (std::int64_t errors : row.errorsPerSeed) EXPECT_LT(errors, 32 * 32 * 32 / 100);
    }
    // Verified for these two seeds at 32^3 (not theorems), per seed: JFA+1, JFA+2 and JFA^2 have
    // no more errors than JFA (they had none; JFA had 4 / 14 and 19 / 49); slice 1+JFA has no
    // more than slice JFA (14 / 7 vs 28 / 39; 53 / 61 vs 85 / 73); and slice JFA has more than
    // 3D JFA (Fig. 4.17: fewer paths in 2D).
    for (std::size_t block = 0; block < rows.size(); block += 6) {
        for (std::size_t seed = 0; seed < 2; ++seed) {
            const auto errors = [&](std::size_t method) {
                return rows[block + method].errorsPerSeed[seed];
            };
            EXPECT_LE(errors(1), errors(0)) << rows[block].sites << " sites, seed " << seed;
            EXPECT_LE(errors(2), errors(0)) << rows[block].sites << " sites, seed " << seed;
            EXPECT_LE(errors(3), errors(0)) << rows[block].sites << " sites, seed " << seed;
            EXPECT_LE(errors(5), errors(4)) << rows[block].sites << " sites, seed " << seed;
            EXPECT_GT(errors(4), errors(0)) << rows[block].sites << " sites, seed " << seed;
        }
    }
}

// The numbers behind Fig. 4.16 / 4.17 at 64^3 and 128^3 (25-50 s on 2 cores). Run with
//   build/jfa3d/tests/jfa3d_test --gtest_also_run_disabled_tests --gtest_filter='*Fig416*'
TEST(Jfa3dExperiment, DISABLED_Fig416And417) {
    Experiment3dConfig config; // 64^3 and 128^3; 100, 1000, 5000 sites; seeds 1..3
    for (const Experiment3dRow& row : runExperiment3d(config)) std::cout << row.describe() << "\n";
}

} // namespace
} // namespace fl::jfa
