// Band-limited flooding on the GPU (jfa_gl/GlKernel.h, jfa/Band.h): the tile list built on the GPU
// and the passes over it give the full grid's result texel for texel, for both kernel kinds,
// plans of every shape and grids that are not powers of two; the GPU's band is the CPU's.

#include "GlTest.h"

#include <jfa/Band.h>
#include <jfa/CpuKernel.h>
#include <jfa/NearestSite.h>
#include <jfa_gl/GlKernel.h>

#include <cstdint>

namespace fl::jfa {
namespace {

class JfaBandGlTest : public test::GlTest, public ::testing::WithParamInterface<GlKernelKind> {};

Grid randomSites(int w, int h, int count, std::uint64_t seed) {
    Grid g(w, h);
    std::uint64_t s = seed;
    auto next = [&s] {
        s = s * 6364136223846793005ull + 1442695040888963407ull;
        return s >> 33;
    };
    for (int i = 0; i < count; ++i) {
        const int x = int(next() % std::uint64_t(w)), y = int(next() % std::uint64_t(h));
        g.at(x, y) = Cell{float(x), float(y), float(i), 0.0f};
    }
    return g;
}

TEST_P(JfaBandGlTest, BandEqualsFullAndTheCpuTexelForTexel) {
    const gl::ShaderLibrary& shaders = fl::test::testShaders();
    GlFloodKernel<NearestSite> band(shaders, GetParam()), full(shaders, GetParam());
    band.setRegion(FloodRegion::Band, 16);
    const NearestSite crit{true};
    for (auto [w, h] : {std::pair{7, 3}, {64, 64}, {200, 150}, {513, 7}}) {
        const Grid seeds = randomSites(w, h, 5, 3);
        // Short plans (the band is smaller than the grid) and ones that fill it (run full).
        for (const char* spec : {"flood:3", "flood:12", "half:flood:6", "jfa", "half:jfa+2"}) {
            const Plan plan = parsePlan(spec, w, h);
            const Grid b = band.run(plan, seeds, crit);
            const Grid f = full.run(plan, seeds, crit);
            FloodOptions cpuBand;
            cpuBand.region = FloodRegion::Band;
            cpuBand.bandTile = 16;
            const FloodResult cpu = floodWithStats(plan, seeds, crit, cpuBand);
            EXPECT_EQ(b, f) << spec << " " << w << "x" << h;
            EXPECT_EQ(b, cpu.grid) << spec << " " << w << "x" << h;
            const Band expected = floodBand(plan, seeds, crit, 16);
            // NearestSite bounds nothing: the kernel bands only plans of shorter reach than the
            // grid.
            EXPECT_EQ(band.lastRunBanded(), planBandReach(plan) < std::max(w, h) - 1)
                << spec << " " << w << "x" << h;
            if (band.lastRunBanded()) {
                EXPECT_DOUBLE_EQ(band.activeShare(), expected.activeShare())
                    << spec << " " << w << "x" << h;
            }
        }
    }
}

TEST_P(JfaBandGlTest, EmptySeedsAndStaleTexturesStayEmpty) {
    const gl::ShaderLibrary& shaders = fl::test::testShaders();
    GlFloodKernel<NearestSite> kernel(shaders, GetParam());
    kernel.setRegion(FloodRegion::Band);
    const Plan plan = parsePlan("flood:4", 96, 80);
    // A first run fills part of the ping-pong textures; a run with sites elsewhere must not see
    // them (the band's texels are cleared, not left from the last frame).
    (void)kernel.run(plan, randomSites(96, 80, 8, 1), NearestSite{true});
    const Grid other = randomSites(96, 80, 2, 99);
    EXPECT_EQ(kernel.run(plan, other, NearestSite{true}), flood(plan, other, NearestSite{true}));
    const Grid none = kernel.run(plan, Grid(96, 80), NearestSite{true});
    for (const Cell& c : none.cells) ASSERT_EQ(c, kEmptyCell);
    EXPECT_EQ(kernel.activeShare(), 0.0);
}

// Named after the risk of clearing only the last band: a band run clears what the run before
// wrote over that run's tile list alone. One kernel, frame after frame, sites moving, the
// region switched to full and back, plans whose stages change size (a half-resolution stage
// 0, then a full-resolution one) and tiles that change size: every result equals the CPU's full
// flood.
TEST_P(JfaBandGlTest, ClearingOnlyTheLastBandLeavesNoStaleCells) {
    const gl::ShaderLibrary& shaders = fl::test::testShaders();
    GlFloodKernel<NearestSite> kernel(shaders, GetParam());
    const NearestSite crit{true};
    const int w = 150, h = 110;
    struct Frame {
        const char* plan;
        FloodRegion region;
        int sites;
        int tile = 16;
    };
    const Frame frames[] = {
        {"flood:6", FloodRegion::Band, 6},       {"flood:6", FloodRegion::Band, 3},
        {"flood:9", FloodRegion::Band, 9},       {"flood:6", FloodRegion::Full, 4},
        {"flood:6", FloodRegion::Band, 2},       {"half:flood:5", FloodRegion::Band, 5},
        {"flood:4", FloodRegion::Band, 7},       {"half:flood:3", FloodRegion::Band, 1},
        {"flood:5", FloodRegion::Band, 0},       {"flood:5", FloodRegion::Band, 8},
        {"half:flood:7", FloodRegion::Band, 12}, {"flood:2", FloodRegion::Band, 1},
        {"half:flood:7", FloodRegion::Band, 1},  {"flood:6", FloodRegion::Band, 12, 16},
        {"flood:6", FloodRegion::Band, 1, 32},   {"flood:6", FloodRegion::Band, 12, 8},
        {"flood:6", FloodRegion::Band, 1, 16}};
    std::uint64_t seed = 11;
    for (const Frame& f : frames) {
        kernel.setRegion(f.region, f.tile);
        const Grid sites = randomSites(w, h, f.sites, ++seed);
        const Plan plan = parsePlan(f.plan, w, h);
        EXPECT_EQ(kernel.run(plan, sites, crit), flood(plan, sites, crit))
            << f.plan << ", " << f.sites << " sites, frame seed " << seed;
    }
}

// The view limit (FloodRegion::View, jfa/Band.h) on the GPU computes the tiles the CPU's does:
// the whole grid, view or not, equals the CPU's view-limited flood texel for texel (the texels
// beyond the view's reach hold the same partial flood), its share is the CPU's, and band runs in
// between, on the same kernel, still equal the full flood.
TEST_P(JfaBandGlTest, ViewLimitEqualsTheCpusTexelForTexel) {
    const gl::ShaderLibrary& shaders = fl::test::testShaders();
    GlFloodKernel<NearestSite> kernel(shaders, GetParam());
    const NearestSite crit{true};
    const int w = 203, h = 150, tile = 8;
    const int tiles = ((w + tile - 1) / tile) * ((h + tile - 1) / tile);
    std::uint64_t seed = 40;
    bool limited = false;
    for (const char* spec : {"flood:6", "flood:11", "half:flood:5", "flood:6", "jfa", "flood:3"}) {
        for (FloodRegion region : {FloodRegion::View, FloodRegion::Band}) {
            const Grid sites = randomSites(w, h, 9, ++seed);
            std::vector<std::uint8_t> view(std::size_t(tiles), 0);
            std::uint64_t s = seed;
            for (int i = 0; i < 3; ++i) {
                s = s * 6364136223846793005ull + 1442695040888963407ull;
                view[(s >> 33) % view.size()] = 1;
            }
            const std::vector<GLuint> flags(view.begin(), view.end());
            const gl::Buffer buffer(GLsizeiptr(flags.size() * sizeof(GLuint)), flags.data(), 0);
            kernel.setRegion(region, tile);
            kernel.setViewTiles(&buffer);
            const Plan plan = parsePlan(spec, w, h);
            const Grid gpu = kernel.run(plan, sites, crit);
            kernel.setViewTiles(nullptr);
            FloodOptions o;
            o.region = region;
            o.bandTile = tile;
            o.viewTiles = &view;
            const FloodResult cpu = floodWithStats(plan, sites, crit, o);
            // At a half-resolution stage the GPU computes whole stage tiles, the CPU the texels
            // whose grid point is in the band: beyond the view's reach their partial floods
            // differ, so there the view's texels are compared, with the full flood.
            if (plan.stages().size() == 1) {
                EXPECT_EQ(gpu, cpu.grid) << spec << " " << floodRegionName(region);
            } else {
                const Grid full = flood(plan, sites, crit);
                const int tilesX = (w + tile - 1) / tile;
                std::size_t differ = 0, viewTexels = 0;
                for (int y = 0; y < h; ++y)
                    for (int x = 0; x < w; ++x)
                        if (view[std::size_t(y / tile * tilesX + x / tile)] != 0) {
                            ++viewTexels;
                            differ += !(gpu.at(x, y) == full.at(x, y));
                        }
                EXPECT_EQ(differ, 0u) << spec << " " << floodRegionName(region);
                EXPECT_GT(viewTexels, 0u);
            }
            if (kernel.lastRunBanded()) {
                EXPECT_DOUBLE_EQ(kernel.activeShare(), cpu.activeShare) << spec;
                limited =
                    limited || (region == FloodRegion::View &&
                                cpu.activeShare < floodBand(plan, sites, crit, tile).activeShare());
            }
            if (region == FloodRegion::Band) {
                EXPECT_EQ(gpu, flood(plan, sites, crit)) << spec;
            }
        }
    }
    EXPECT_TRUE(limited) << "no run left band tiles out";
}

// The flood's front (jfa/Band.h) on the GPU: with long jumps from sparse sites over a band the
// plan bounds, every pass's tile list is the CPU's (the computed shares are equal), and the result
// is the full flood's, texel for texel; the same kernel without the front computes the band.
TEST_P(JfaBandGlTest, TheFrontListsTheCpusTilesWithTheFullFloodsResult) {
    const gl::ShaderLibrary& shaders = fl::test::testShaders();
    GlFloodKernel<NearestSite> kernel(shaders, GetParam());
    const NearestSite crit{true};
    for (auto [w, h] : {std::pair{300, 260}, {97, 513}}) {
        const Grid seeds = randomSites(w, h, 2, 17);
        Stage halving{w, h, extraPasses(6)}, doubling{w, h, {1, 2, 4, 8, 16, 32}};
        for (const Plan& plan : {Plan("halving from 32", {halving}),
                                 Plan("doubling to 32", {doubling}), parsePlan("flood:12", w, h)}) {
            for (int tile : {8, 16}) {
                const std::string what = plan.name() + ", " + std::to_string(w) + "x" +
                                         std::to_string(h) + ", tile " + std::to_string(tile);
                FloodOptions cpuBand;
                cpuBand.region = FloodRegion::Band;
                cpuBand.bandTile = tile;
                const FloodResult cpu = floodWithStats(plan, seeds, crit, cpuBand);
                ASSERT_EQ(cpu.grid, flood(plan, seeds, crit)) << what;
                kernel.setRegion(FloodRegion::Band, tile);
                for (bool front : {true, false}) {
                    kernel.setFrontLimited(front);
                    EXPECT_EQ(kernel.run(plan, seeds, crit), cpu.grid) << what << front;
                    ASSERT_TRUE(kernel.lastRunBanded()) << what;
                    EXPECT_DOUBLE_EQ(kernel.activeShare(), cpu.activeShare) << what;
                    EXPECT_DOUBLE_EQ(kernel.computedShare(),
                                     front ? cpu.computedShare : cpu.activeShare)
                        << what << front;
                }
                // Step-1 passes reach the band's tiles of 16 within the first few passes.
                if (plan.stages()[0].steps[0] > 1) {
                    EXPECT_LT(cpu.computedShare, cpu.activeShare) << what;
                }
            }
        }
    }
}

TEST_P(JfaBandGlTest, BadTilesAreRefused) {
    const gl::ShaderLibrary& shaders = fl::test::testShaders();
    GlFloodKernel<NearestSite> kernel(shaders, GetParam());
    EXPECT_THROW(kernel.setRegion(FloodRegion::Band, 12), std::invalid_argument);
    EXPECT_THROW(kernel.setRegion(FloodRegion::Band, 0), std::invalid_argument);
}

INSTANTIATE_TEST_SUITE_P(Kinds, JfaBandGlTest,
                         ::testing::Values(GlKernelKind::Fragment, GlKernelKind::Compute));

} // namespace
} // namespace fl::jfa
