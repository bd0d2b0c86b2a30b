// The GL 3D flood (jfa_gl/GlJfa3d.h, shaders/jfa3d_pass.comp.glsl) against its CPU twin
// (jfa/Jfa3d.h), voxel for voxel, for every variant of the table: random sites on grids that are
// not cubes or powers of two, and sites made of ties (equal distances, shared voxels, equal ids),
// where only the exact integer rule "distance, then id, then index" gives one answer. Grids stay
// at or below 64^3 (llvmpipe).

#include "GlTest.h"

#include <jfa/Jfa3d.h>
#include <jfa_gl/GlJfa3d.h>

#include <cstdint>
#include <string>

namespace fl::jfa {
namespace {

class Jfa3dGlTest : public test::GlTest {};

// Voxels where two or more sites lie at the nearest distance: what the tie rule decides.
std::int64_t tiedVoxels(const std::vector<Site3>& sites, Extent3 e) {
    std::int64_t tied = 0;
    for (int z = 0; z < e.depth; ++z)
        for (int y = 0; y < e.height; ++y)
            for (int x = 0; x < e.width; ++x) {
                std::int64_t best = INT64_MAX;
                int count = 0;
                for (const Site3& s : sites) {
                    const std::int64_t dx = s.x - x, dy = s.y - y, dz = s.z - z;
                    const std::int64_t d = dx * dx + dy * dy + dz * dz;
                    if (d < best) {
                        best = d;
                        count = 0;
                    }
                    count += d == best;
                }
                tied += count > 1;
            }
    return tied;
}

// Every variant on the GPU equals its CPU run, cell for cell; says where the first one differs.
void expectGlEqualsCpu(GlJfa3d& kernel, const std::vector<Site3>& sites, Extent3 e) {
    for (const Flood3dVariant& v : flood3dVariants()) {
        SCOPED_TRACE(std::string(v.label) + " on " + std::to_string(e.width) + "x" +
                     std::to_string(e.height) + "x" + std::to_string(e.depth));
        const SiteGrid3 cpu = floodVariant3d(v, sites, e, 2);
        const SiteGrid3 gl = glFloodVariant3d(kernel, v, sites, e);
        ASSERT_EQ(gl.extent, cpu.extent);
        std::size_t differ = 0, first = 0;
        for (std::size_t i = 0; i < cpu.cells.size(); ++i) {
            if (gl.cells[i] != cpu.cells[i] && differ++ == 0) first = i;
        }
        EXPECT_EQ(differ, 0u) << "first at cell " << first << ": GL " << gl.cells[first] << ", CPU "
                              << cpu.cells[first];
        // The flood ran: no voxel is left without a site (every plan here reaches every voxel).
        EXPECT_EQ(std::count(gl.cells.begin(), gl.cells.end(), kNoSite), 0);
    }
}

TEST_F(Jfa3dGlTest, RandomSitesEqualTheCpuEveryVariant) {
    GlJfa3d kernel(test::testShaders());
    // 64^3 once: llvmpipe with unoptimised shaders (GALLIVM_PERF=nopt) takes seconds a variant.
    const std::pair<Extent3, std::vector<int>> cases[] = {{{1, 1, 1}, {1}},
                                                          {{7, 3, 5}, {1, 3, 40}},
                                                          {{33, 20, 17}, {1, 3, 200}},
                                                          {{64, 64, 64}, {300}}};
    for (const auto& [e, counts] : cases)
        for (int count : counts)
            expectGlEqualsCpu(kernel, randomSites3d(count, e, std::uint64_t(count) + 7), e);
}

TEST_F(Jfa3dGlTest, TiesGoToTheSmallerIdThenTheSmallerIndexAsOnTheCpu) {
    GlJfa3d kernel(test::testShaders());
    const Extent3 e{24, 24, 24};
    std::vector<Site3> sites;
    // A lattice of step 6 (every voxel between two lattice sites is a tie), ids counting down so
    // that the smaller id is the later index, and every fifth id shared with the next site so
    // that the index decides there.
    int id = 1000;
    for (int z = 3; z < 24; z += 6)
        for (int y = 3; y < 24; y += 6)
            for (int x = 3; x < 24; x += 6) {
                sites.push_back({x, y, z, id});
                id -= sites.size() % 5 == 0 ? 0 : 1;
            }
    // Two sites on one voxel (the seed keeps one by the same rule) and a symmetric pair.
    sites.push_back({9, 9, 9, 5});
    sites.push_back({1, 12, 12, 7});
    sites.push_back({23, 12, 12, 7});
    ASSERT_GT(tiedVoxels(sites, e), std::int64_t(e.voxels() / 10));
    expectGlEqualsCpu(kernel, sites, e);
}

TEST_F(Jfa3dGlTest, RefusesGridsBeyondTheDriversLargest3dTexture) {
    const int limit = gl::max3dTextureSize();
    ASSERT_GT(limit, 0);
    try {
        checkGlExtent3d({limit + 1, 1, 1});
        FAIL() << "a side of " << limit + 1 << " was accepted";
    } catch (const std::invalid_argument& e) {
        const std::string text = e.what();
        // Jfa3d's own limit comes first where the driver's is the larger.
        const std::string named = limit + 1 > kMaxGridExtent3d ? std::to_string(kMaxGridExtent3d)
                                                               : "GL_MAX_3D_TEXTURE_SIZE";
        EXPECT_NE(text.find(named), std::string::npos) << text;
    }
    EXPECT_NO_THROW(checkGlExtent3d({std::min(limit, 64), 2, 2}));
}

TEST_F(Jfa3dGlTest, RefusesPlansItCannotRun) {
    GlJfa3d kernel(test::testShaders());
    const Extent3 e{8, 8, 8};
    const std::vector<Site3> sites = randomSites3d(4, e, 1);
    kernel.upload(sites, seedGrid3d(sites, e));
    EXPECT_THROW(kernel.run(parsePlan("flood", 8, 8), Flood3dShape::Volume), std::invalid_argument);
    EXPECT_THROW(kernel.run(parsePlan("jfa", 16, 8), Flood3dShape::Slices), std::invalid_argument);
    std::vector<std::int32_t> bad(e.voxels(), kNoSite);
    bad[0] = 4; // no site 4
    SiteGrid3 badGrid(e);
    badGrid.cells = bad;
    EXPECT_THROW(kernel.upload(sites, badGrid), std::invalid_argument);
}

} // namespace
} // namespace fl::jfa
