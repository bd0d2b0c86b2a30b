// The GL flood kernels (fragment and compute) against the CPU kernel, texel for texel, for every
// plan variant, integer and sub-pixel sites, and grid sizes that are not powers of two.

#include "GlTest.h"

#include <jfa/CpuKernel.h>
#include <jfa/NearestSite.h>
#include <jfa/Sites.h>
#include <jfa_gl/GlKernel.h>

#include <cstdint>

namespace fl::jfa {
namespace {

class JfaGlKernelTest : public test::GlTest, public ::testing::WithParamInterface<GlKernelKind> {};

// A kernel runs only the criterion whose GLSL it was built with: any other does not compile.
struct OtherCriterion {
    static constexpr const char* glslFile = "other_criterion.glsl";
    [[nodiscard]] bool empty(const Cell& c) const { return c.z < 0.0f; }
    [[nodiscard]] bool better(int, int, const Cell& a, const Cell& b) const { return a.z < b.z; }
};
template <class Kernel, class C>
concept RunsWith = requires(Kernel& k, const Plan& p, const Grid& g, const C& c) {
    k.run(p, g, c);
};
static_assert(RunsWith<GlFloodKernel<NearestSite>, NearestSite>);
static_assert(!RunsWith<GlFloodKernel<NearestSite>, OtherCriterion>);
static_assert(!RunsWith<GlFloodKernel<OtherCriterion>, NearestSite>);

// Deterministic sites without depending on the CPU side's generators.
Grid randomSeeds(int w, int h, int count, std::uint64_t seed, bool integer) {
    Grid g(w, h);
    std::uint64_t s = seed;
    auto next = [&s] {
        s += 0x9E3779B97F4A7C15ull;
        std::uint64_t z = s;
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    };
    for (int i = 0; i < count; ++i) {
        const int x = int(next() % std::uint64_t(w)), y = int(next() % std::uint64_t(h));
        Cell c{float(x), float(y), float(i), 0.0f};
        if (!integer) {
            c.x += float(next() % 1000) / 1000.0f - 0.5f;
            c.y += float(next() % 1000) / 1000.0f - 0.5f;
        }
        g.at(x, y) = c; // a later site on the same pixel replaces the earlier one
    }
    return g;
}

TEST_P(JfaGlKernelTest, OneSeedFillsAnyGrid) {
    const gl::ShaderLibrary& shaders = fl::test::testShaders();
    GlFloodKernel<NearestSite> kernel(shaders, GetParam());
    for (auto [w, h] : {std::pair{1, 1}, {2, 1}, {7, 3}, {64, 64}, {300, 200}, {513, 7}}) {
        for (const char* spec : {"jfa", "1+jfa", "half:jfa", "doubling"}) {
            Grid seeds(w, h);
            seeds.at(w - 1, 0) = Cell{float(w - 1), 0.0f, 5.0f, 0.0f};
            const Grid out = kernel.run(parsePlan(spec, w, h), seeds, NearestSite{});
            ASSERT_EQ(out.width, w);
            for (const Cell& c : out.cells)
                ASSERT_EQ(c, seeds.at(w - 1, 0)) << spec << " " << w << "x" << h;
        }
    }
}

TEST_P(JfaGlKernelTest, FragmentAndComputeAgree) {
    const gl::ShaderLibrary& shaders = fl::test::testShaders();
    GlFloodKernel<NearestSite> kernel(shaders, GetParam());
    const GlKernelKind other =
        GetParam() == GlKernelKind::Fragment ? GlKernelKind::Compute : GlKernelKind::Fragment;
    GlFloodKernel<NearestSite> reference(shaders, other);
    for (bool integer : {true, false}) {
        const Grid seeds = randomSeeds(200, 150, 60, 7, integer);
        for (const char* spec : {"jfa", "jfa+2", "1+jfa", "half:jfa+2", "flood", "flood:20"}) {
            const Plan plan = parsePlan(spec, 200, 150);
            const NearestSite crit{integer};
            EXPECT_TRUE(kernel.run(plan, seeds, crit) == reference.run(plan, seeds, crit))
                << spec << (integer ? " integer" : " float");
        }
    }
}

// The reason the GL kernels exist twice: for the same plan, criterion and input the GPU result
// equals the CPU reference kernel's in every texel (all four floats), for every variant.
TEST_P(JfaGlKernelTest, EqualsCpuKernelTexelForTexel) {
    const gl::ShaderLibrary& shaders = fl::test::testShaders();
    GlFloodKernel<NearestSite> kernel(shaders, GetParam());
    const char* specs[] = {"jfa",      "jfa+1",    "jfa+2", "jfa2",     "1+jfa",      "1+jfa+1",
                           "doubling", "flood:12", "flood", "half:jfa", "half:jfa+2", "half:1+jfa"};
    for (auto [w, h, sites] : {std::tuple{128, 128, 40}, {200, 150, 300}, {97, 61, 25}}) {
        for (bool integer : {true, false}) {
            const std::vector<Site> points =
                integer ? randomIntegerSites(sites, w, h, 11) : randomFloatSites(sites, w, h, 11);
            const Grid seeds = seedPoints(points, w, h, integer).grid;
            const NearestSite crit{integer};
            for (const char* spec : specs) {
                const Plan plan = parsePlan(spec, w, h);
                const Grid cpu = flood(plan, seeds, crit);
                const Grid gpu = kernel.run(plan, seeds, crit);
                ASSERT_EQ(gpu.cells.size(), cpu.cells.size());
                size_t differing = 0;
                for (size_t i = 0; i < cpu.cells.size(); ++i)
                    differing += !(cpu.cells[i] == gpu.cells[i]);
                EXPECT_EQ(differing, 0u)
                    << spec << " " << w << "x" << h << (integer ? " integer" : " float");
            }
        }
    }
}

TEST_P(JfaGlKernelTest, UntilUnchangedStopsWhenTheCpuKernelDoes) {
    const gl::ShaderLibrary& shaders = fl::test::testShaders();
    GlFloodKernel<NearestSite> kernel(shaders, GetParam());
    const Grid seeds = seedPoints(randomIntegerSites(30, 90, 70, 3), 90, 70, true).grid;
    const Plan plan = parsePlan("flood", 90, 70);
    const FloodResult cpu = floodWithStats(plan, seeds, NearestSite{});
    const Grid gpu = kernel.run(plan, seeds, NearestSite{});
    EXPECT_EQ(kernel.passesRun(), cpu.passesRun());
    EXPECT_LT(kernel.passesRun(), plan.passCount());
    EXPECT_TRUE(gpu == cpu.grid);
}

INSTANTIATE_TEST_SUITE_P(Kinds, JfaGlKernelTest,
                         ::testing::Values(GlKernelKind::Fragment, GlKernelKind::Compute),
                         [](const auto& p) { return std::string(kernelName(p.param)); });

} // namespace
} // namespace fl::jfa
