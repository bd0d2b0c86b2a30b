// Band-limited flooding on the CPU (jfa/Band.h): for every plan, criterion, tile size and grid,
// the band's result equals the full grid's texel for texel; the tile logic itself; and that the
// band leaves work out where seeds cannot reach.

#include <jfa/Band.h>
#include <jfa/CpuKernel.h>
#include <jfa/NearestSite.h>

#include <gtest/gtest.h>

#include <cstdint>

namespace fl::jfa {
namespace {

// Nearest site, but a site is accepted only within Chebyshev distance R of its pixel (R in w):
// a Reaching criterion whose reach() is exact, like the penumbra criteria's bound.
struct NearestWithin {
    static constexpr const char* glslFile = nullptr; // CPU only
    NearestSite nearest{true};
    [[nodiscard]] bool empty(const Cell& c) const { return nearest.empty(c); }
    [[nodiscard]] bool accepts(int px, int py, const Cell& c) const {
        return std::abs(px - int(c.x)) <= int(c.w) && std::abs(py - int(c.y)) <= int(c.w);
    }
    [[nodiscard]] bool better(int px, int py, const Cell& a, const Cell& b) const {
        return nearest.better(px, py, a, b);
    }
    [[nodiscard]] ReachRect reach(int px, int py, const Cell& c) const {
        const long long r = static_cast<long long>(c.w);
        return {px - r, py - r, px + r, py + r};
    }
};
static_assert(Reaching<NearestWithin>);
static_assert(!Reaching<NearestSite>);

Grid randomSeeds(int w, int h, int count, std::uint64_t seed, int maxRadius) {
    Grid g(w, h);
    std::uint64_t s = seed;
    auto next = [&s] {
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        return s >> 33;
    };
    for (int i = 0; i < count; ++i) {
        const int x = int(next() % std::uint64_t(w)), y = int(next() % std::uint64_t(h));
        g.at(x, y) =
            Cell{float(x), float(y), float(i), float(1 + next() % std::uint64_t(maxRadius))};
    }
    return g;
}

const char* const kPlans[] = {"jfa",      "jfa+2",   "1+jfa",    "half:jfa+2",
                              "doubling", "flood:3", "flood:20", "flood"};

TEST(JfaBand, BandEqualsFullForEveryPlanTileAndGrid) {
    for (auto [w, h] : {std::pair{1, 1}, {7, 3}, {64, 64}, {200, 150}, {513, 7}}) {
        const Grid seeds = randomSeeds(w, h, 6, 11, 9);
        for (const char* spec : kPlans) {
            const Plan plan = parsePlan(spec, w, h);
            for (int tile : {8, 16, 32}) {
                FloodOptions band;
                band.region = FloodRegion::Band;
                band.bandTile = tile;
                // A plain criterion: only the plan bounds the band.
                const NearestSite nearest{true};
                EXPECT_EQ(flood(plan, seeds, nearest, band), flood(plan, seeds, nearest))
                    << spec << " " << w << "x" << h << " tile " << tile;
                // A reaching criterion: the per-seed rects bound it.
                const NearestWithin within;
                const FloodResult b = floodWithStats(plan, seeds, within, band);
                const FloodResult f = floodWithStats(plan, seeds, within);
                EXPECT_EQ(b.grid, f.grid) << spec << " " << w << "x" << h << " tile " << tile;
                ASSERT_EQ(b.passes.size(), f.passes.size()) << spec;
                for (std::size_t i = 0; i < b.passes.size(); ++i)
                    EXPECT_EQ(b.passes[i].changed, f.passes[i].changed) << spec << " pass " << i;
            }
        }
    }
}

// A few random view tiles (the tiles a reader reads), one flag per tile of side `tile`.
std::vector<std::uint8_t> randomView(int w, int h, int tile, int count, std::uint64_t seed) {
    const int tx = (w + tile - 1) / tile, ty = (h + tile - 1) / tile;
    std::vector<std::uint8_t> v(std::size_t(tx) * std::size_t(ty), 0);
    std::uint64_t s = seed;
    for (int i = 0; i < count; ++i) {
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        v[(s >> 33) % v.size()] = 1;
    }
    return v;
}

// The view limit (jfa/Band.h): every texel of a view tile holds what the full flood leaves
// there, for every plan, criterion, tile and grid, with seeds and views scattered at random;
// and where the plan's reach is short against the grid, it computes less than the band.
TEST(JfaBand, ViewLimitIsExactAtTheViewForEveryPlanTileAndGrid) {
    bool savedWork = false;
    for (auto [w, h] : {std::pair{1, 1}, {7, 3}, {64, 64}, {200, 150}, {513, 7}}) {
        for (std::uint64_t trial = 0; trial < 3; ++trial) {
            const Grid seeds = randomSeeds(w, h, 12, 5 + trial, 9);
            for (const char* spec : kPlans) {
                const Plan plan = parsePlan(spec, w, h);
                for (int tile : {8, 16}) {
                    const std::vector<std::uint8_t> view = randomView(w, h, tile, 2, 7 + trial);
                    FloodOptions o;
                    o.region = FloodRegion::View;
                    o.bandTile = tile;
                    o.viewTiles = &view;
                    const auto check = [&](const auto& criterion) {
                        const FloodResult v = floodWithStats(plan, seeds, criterion, o);
                        const Grid f = flood(plan, seeds, criterion);
                        FloodOptions b = o;
                        b.region = FloodRegion::Band;
                        const double bandShare =
                            floodWithStats(plan, seeds, criterion, b).activeShare;
                        EXPECT_LE(v.activeShare, bandShare) << spec;
                        savedWork = savedWork || v.activeShare < bandShare;
                        const int tilesX = (w + tile - 1) / tile;
                        for (int y = 0; y < h; ++y)
                            for (int x = 0; x < w; ++x)
                                if (view[std::size_t(y / tile * tilesX + x / tile)] != 0) {
                                    ASSERT_EQ(v.grid.at(x, y), f.at(x, y))
                                        << spec << " " << w << "x" << h << " tile " << tile
                                        << " at " << x << "," << y;
                                }
                        // Until-unchanged plans are not limited: the whole grid is exact.
                        if (plan.untilUnchanged()) {
                            EXPECT_EQ(v.grid, f) << spec;
                        }
                    };
                    check(NearestSite{true});
                    check(NearestWithin{});
                }
            }
        }
    }
    EXPECT_TRUE(savedWork);
}

TEST(JfaBand, ViewTileReachIsThePlansReachPlusATexelInTiles) {
    // jfa on 256^2: steps 128 .. 1, reach 255 (+1 texel) = 32 tiles of 8: wider than the limit.
    EXPECT_EQ(viewTileReach(parsePlan("jfa", 256, 256), 8), -1);
    // flood:7 reaches 7 texels, +1 = 8: one tile of 8, one of 16.
    EXPECT_EQ(viewTileReach(parsePlan("flood:7", 256, 256), 8), 1);
    EXPECT_EQ(viewTileReach(parsePlan("flood:8", 256, 256), 8), 2);
    EXPECT_EQ(viewTileReach(parsePlan("flood:7", 256, 256), 16), 1);
    EXPECT_EQ(viewTileReach(parsePlan("flood", 256, 256), 8), -1); // until unchanged
    // limitToView keeps the band tiles within the reach of a view tile, and says when the band
    // is whole; a view of the wrong size is refused.
    Band b = markTiles(64, 16, 8, std::vector<ReachRect>(16, ReachRect{0, 0, 63, 15}));
    ASSERT_TRUE(b.full);
    std::vector<std::uint8_t> view(16, 0);
    view[3] = 1; // tile (3, 0)
    limitToView(b, view, 1);
    EXPECT_FALSE(b.full);
    EXPECT_EQ(b.activeTexels(), 6 * 64); // tiles 2..4 of both rows
    EXPECT_TRUE(b.covers(16, 15));
    EXPECT_FALSE(b.covers(40, 0));
    EXPECT_THROW(limitToView(b, std::vector<std::uint8_t>(15, 1), 1), std::invalid_argument);
}

TEST(JfaBand, EmptySeedsGiveAnEmptyBandAndAnEmptyGrid) {
    const Grid seeds(100, 60);
    FloodOptions band;
    band.region = FloodRegion::Band;
    const FloodResult r =
        floodWithStats(parsePlan("flood:9", 100, 60), seeds, NearestWithin{}, band);
    EXPECT_EQ(r.activeShare, 0.0);
    for (const Cell& c : r.grid.cells) EXPECT_EQ(c, kEmptyCell);
}

TEST(JfaBand, TheBandFollowsTheSeedsReachNotTheGrid) {
    // Two seeds of radius 3 on a 256^2 grid: the band is their tiles, a few percent of the grid.
    Grid seeds(256, 256);
    seeds.at(40, 40) = Cell{40, 40, 0, 3};
    seeds.at(200, 100) = Cell{200, 100, 1, 3};
    const Band b = floodBand(parsePlan("jfa", 256, 256), seeds, NearestWithin{}, 16);
    EXPECT_FALSE(b.full);
    EXPECT_EQ(b.activeTexels(), 2 * 16 * 16); // each rect lies within one tile
    EXPECT_TRUE(b.covers(40, 40));
    EXPECT_FALSE(b.covers(120, 120));
    // Without a criterion bound, a plan of short reach still limits it: flood:20 reaches 20.
    const Band p = floodBand(parsePlan("flood:20", 256, 256), seeds, NearestSite{true}, 16);
    EXPECT_FALSE(p.full);
    // Each seed's tile (32..47 and 192..207 per axis) widened by 20 texels touches 5 x 5 tiles:
    // 50 of the grid's 256.
    EXPECT_EQ(p.activeTexels(), 50 * 16 * 16);
    // A plan that reaches the whole grid from a seed with no criterion bound: every tile.
    EXPECT_TRUE(floodBand(parsePlan("jfa", 256, 256), seeds, NearestSite{true}, 16).full);
}

TEST(JfaBand, MaxSeedReachAndAutoPasses) {
    Grid seeds(300, 300);
    seeds.at(150, 150) = Cell{150, 150, 0, 40};
    seeds.at(5, 5) = Cell{5, 5, 1, 10};
    EXPECT_EQ(maxSeedReach(seeds, NearestWithin{}), 40);
    EXPECT_EQ(maxSeedReach(Grid(30, 30), NearestWithin{}), -1);
    // An unbounded criterion reaches the grid's far side from its farthest seed.
    EXPECT_EQ(maxSeedReach(seeds, NearestSite{true}), 294);
    // The fewest halving passes whose reach 2^k - 1 covers it.
    EXPECT_EQ(passesForReach(40, 9), 6); // 63 >= 40 > 31
    EXPECT_EQ(passesForReach(31, 9), 5);
    EXPECT_EQ(passesForReach(0, 9), 1);
    EXPECT_EQ(passesForReach(-1, 9), 1);
    EXPECT_EQ(passesForReach(1000, 8), 8);
}

// One stage of k halving steps 2^(k-1), ..., 1 (extraPasses): JFA's long jumps with a reach
// (2^k - 1) short of the grid, so that a plan-bounded band is smaller than the grid.
Plan halvingPlan(int k, int w, int h) {
    return Plan("halving from " + std::to_string(1 << (k - 1)), {Stage{w, h, extraPasses(k)}});
}

// The flood's front (jfa/Band.h): with long jumps from sparse seeds, the passes compute less than
// the band, and the result and every pass's count of changes are the full flood's, for halving,
// doubling and step-1 plans, both criteria, two tiles and grids that are not powers of two.
TEST(JfaBand, TheFrontComputesLessThanTheBandWithTheSameResult) {
    for (auto [w, h] : {std::pair{300, 260}, {97, 513}}) {
        const Grid seeds = randomSeeds(w, h, 2, 5, 60);
        const Plan plans[] = {halvingPlan(6, w, h), halvingPlan(5, w, h),
                              Plan("doubling to 32", {Stage{w, h, {1, 2, 4, 8, 16, 32}}}),
                              parsePlan("flood:20", w, h)};
        for (const Plan& plan : plans) {
            for (int tile : {8, 16}) {
                FloodOptions front;
                front.region = FloodRegion::Band;
                front.bandTile = tile;
                FloodOptions plain = front;
                plain.front = false;
                // `saves`: the band is the plan's square around the seeds (NearestSite), most of
                // it out of the first long jumps' reach. NearestWithin's band is already the
                // seeds' small rects, which the front cannot cut by much.
                auto check = [&](const auto& criterion, const char* name, bool saves) {
                    const std::string what = plan.name() + ", " + name + ", " + std::to_string(w) +
                                             "x" + std::to_string(h) + ", tile " +
                                             std::to_string(tile);
                    const FloodResult full = floodWithStats(plan, seeds, criterion);
                    const FloodResult f = floodWithStats(plan, seeds, criterion, front);
                    const FloodResult p = floodWithStats(plan, seeds, criterion, plain);
                    EXPECT_EQ(f.grid, full.grid) << what;
                    EXPECT_EQ(p.grid, full.grid) << what;
                    ASSERT_EQ(f.passes.size(), full.passes.size()) << what;
                    for (std::size_t i = 0; i < f.passes.size(); ++i)
                        EXPECT_EQ(f.passes[i].changed, full.passes[i].changed) << what << i;
                    ASSERT_LT(p.activeShare, 1.0) << what << ": the band must not be the grid";
                    EXPECT_DOUBLE_EQ(p.computedShare, p.activeShare) << what;
                    EXPECT_LE(f.computedShare, p.computedShare) << what;
                    if (saves) {
                        EXPECT_LT(f.computedShare, 0.9 * p.computedShare) << what;
                    }
                };
                check(NearestSite{true}, "nearest site", true);
                check(NearestWithin{}, "nearest within", false);
            }
        }
    }
}

TEST(JfaBand, FrontTilesAreTheBandTilesAStepFromAFlaggedTile) {
    // A 64 x 40 grid of 8 x 8 tiles (8 x 5), all in the band; one flagged tile (3, 2).
    Band band = markTiles(64, 40, 8, std::vector<ReachRect>(40, ReachRect{0, 0, 63, 39}));
    band.full = false;
    std::vector<std::uint8_t> front(40, 0);
    front[2 * 8 + 3] = 1;
    auto tiles = [&](int step) {
        std::vector<std::pair<int, int>> out;
        const Band b = frontTiles(band, front, step);
        for (int y = 0; y < 5; ++y)
            for (int x = 0; x < 8; ++x)
                if (b.active[std::size_t(y * 8 + x)] != 0) out.emplace_back(x, y);
        return out;
    };
    using T = std::vector<std::pair<int, int>>;
    // Step 8: the tile and its 8 neighbours, a whole tile away.
    EXPECT_EQ(tiles(8),
              (T{{2, 1}, {3, 1}, {4, 1}, {2, 2}, {3, 2}, {4, 2}, {2, 3}, {3, 3}, {4, 3}}));
    // Step 16: two tiles away on each axis, and nothing between (tile 1 reads tiles 1 and 3 ...
    // only at offsets 0 and +-16, i.e. tiles 1, 3 and -1, 3 +- 2 = 1 and 5 on x).
    EXPECT_EQ(tiles(16),
              (T{{1, 0}, {3, 0}, {5, 0}, {1, 2}, {3, 2}, {5, 2}, {1, 4}, {3, 4}, {5, 4}}));
    // Step 4: half a tile reaches the neighbours too.
    EXPECT_EQ(tiles(4).size(), 9u);
    // Off the band: nothing, whatever the front.
    band.active[2 * 8 + 3] = 0;
    EXPECT_EQ(tiles(8).size(), 8u);
    EXPECT_THROW((void)frontTiles(band, std::vector<std::uint8_t>(3, 0), 1), std::invalid_argument);
}

TEST(JfaBand, TileLogic) {
    EXPECT_EQ(checkBandTile(16), "");
    EXPECT_NE(checkBandTile(12), "");
    EXPECT_NE(checkBandTile(0), "");
    EXPECT_NE(checkBandTile(512), "");
    EXPECT_EQ(parseFloodRegion("band"), FloodRegion::Band);
    EXPECT_EQ(parseFloodRegion("full"), FloodRegion::Full);
    EXPECT_EQ(parseFloodRegion("view"), FloodRegion::View);
    EXPECT_EQ(floodRegionName(FloodRegion::View), "view");
    EXPECT_TRUE(banded(FloodRegion::View));
    EXPECT_FALSE(banded(FloodRegion::Full));
    EXPECT_FALSE(parseFloodRegion("half").has_value());
    const ReachRect r = clipRect({-50, 3, 500, 9}, 10, 5, 4, 100, 100);
    EXPECT_EQ(r.x0, 6);
    EXPECT_EQ(r.x1, 14);
    EXPECT_EQ(r.y0, 3);
    EXPECT_EQ(r.y1, 9);
    EXPECT_EQ(rectReach(r, 10, 5), 4);
    EXPECT_EQ(rectReach({1, 1, 0, 0}, 0, 0), -1);
    // Partial edge tiles count only their texels.
    const Band b = markTiles(20, 10, 16, {ReachRect{0, 0, 19, 9}, ReachRect{1, 1, 0, 0}});
    EXPECT_TRUE(b.full);
    EXPECT_EQ(b.activeTexels(), 200);
    FloodOptions bad;
    bad.region = FloodRegion::Band;
    bad.bandTile = 10;
    EXPECT_THROW((void)flood(parsePlan("jfa", 8, 8), Grid(8, 8), NearestSite{}, bad),
                 std::invalid_argument);
}

} // namespace
} // namespace fl::jfa
