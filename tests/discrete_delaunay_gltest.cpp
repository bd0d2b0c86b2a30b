// The GL backend of steps G1-G6 (geometry_gl/GlDiscreteDelaunay.h) against the CPU backend
// (geometry/DiscreteDelaunay.h): every stage equal exactly (mapping, pixels, kept and missing
// sites, both id textures, island statistics, corner cases and counts, row chains, vertices,
// triangles in the same order, triangle statistics), for random and dense site sets, plans that
// leave islands, and hand-made textures for the corner cases of Fig. 6.6 and the four-colour
// split. Without stages, run() makes one upload and one read-back (issue 31) and still gives the
// CPU's result, on the benchmark's distributions and when its first bounds fall short.
#include "GlTest.h"

#include <geometry/Delaunay.h>
#include <geometry_gl/GlDiscreteDelaunay.h>

#include <gpu/ShaderLibrary.h>
#include <jfa/Sites.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace fl::geom {
namespace {

class DiscreteDelaunayGlTest : public test::GlTest {
  public:
    // One compiled backend for the whole suite: it is what callers are meant to hold.
    // It reads every stage back (the tests compare them) unless a test says otherwise.
    static GlDiscreteDelaunay& backend() {
        static GlDiscreteDelaunay instance = [] {
            GlDiscreteDelaunay b{gl::ShaderLibrary{}, floodKind()};
            b.setReadStages(true);
            return b;
        }();
        return instance;
    }
    // FLOODLIGHT_GL_DELAUNAY_KERNEL=compute switches G2 to the compute flood kernel.
    static jfa::GlKernelKind floodKind() {
        const char* kind = std::getenv("FLOODLIGHT_GL_DELAUNAY_KERNEL");
        return kind && std::string(kind) == "compute" ? jfa::GlKernelKind::Compute
                                                      : jfa::GlKernelKind::Fragment;
    }
};

std::vector<glm::dvec2> randomSites(int count, std::uint64_t seed, glm::dvec2 lo, glm::dvec2 hi) {
    jfa::SplitMix64 rng(seed);
    std::vector<glm::dvec2> sites(static_cast<std::size_t>(count));
    for (glm::dvec2& s : sites) s = lo + (hi - lo) * glm::dvec2(rng.unit(), rng.unit());
    return sites;
}

DiscreteDelaunayOptions optionsFor(int size, const char* plan = "1+JFA") {
    DiscreteDelaunayOptions o;
    o.size = size;
    o.plan = plan;
    o.countIslands = true;
    return o;
}

// Every stage of the two backends, field by field so that a failure names the stage.
void expectSameStages(const DiscreteDelaunay& cpu, const DiscreteDelaunay& gl) {
    const TextureMapping &mc = cpu.snapped.mapping, &mg = gl.snapped.mapping;
    EXPECT_EQ(mc.origin, mg.origin);
    EXPECT_EQ(mc.scale, mg.scale);
    EXPECT_EQ(mc.offset, mg.offset);
    EXPECT_EQ(mc.size, mg.size);
    EXPECT_EQ(cpu.snapped.pixels, gl.snapped.pixels) << "G1 pixels";
    EXPECT_EQ(cpu.snapped.kept, gl.snapped.kept) << "G1 kept";
    EXPECT_EQ(cpu.missing(), gl.missing()) << "G1 missing";
    EXPECT_TRUE(cpu.voronoi == gl.voronoi) << "G2 texture";
    EXPECT_EQ(cpu.islandsBefore, gl.islandsBefore) << "G2 islands";
    EXPECT_TRUE(cpu.cleaned == gl.cleaned) << "G3 texture";
    EXPECT_EQ(cpu.islands.passes, gl.islands.passes) << "G3 passes";
    EXPECT_EQ(cpu.islands.reassigned, gl.islands.reassigned) << "G3 reassigned";
    EXPECT_EQ(cpu.islands.converged, gl.islands.converged) << "G3 converged";
    EXPECT_TRUE(cpu.corners.cases == gl.corners.cases) << "G4 cases";
    EXPECT_EQ(cpu.corners.counts, gl.corners.counts) << "G4 counts";
    EXPECT_EQ(cpu.corners.width, gl.corners.width);
    EXPECT_EQ(cpu.corners.height, gl.corners.height);
    EXPECT_TRUE(cpu.chain == gl.chain) << "G5 chain";
    EXPECT_TRUE(cpu.mesh.vertices == gl.mesh.vertices) << "G6 vertices";
    EXPECT_EQ(cpu.mesh.triangles, gl.mesh.triangles) << "G6 triangles";
    EXPECT_EQ(cpu.mesh.triangleVertex, gl.mesh.triangleVertex) << "G6 triangle vertices";
    EXPECT_EQ(cpu.mesh.stats, gl.mesh.stats) << "G6 stats";
}

void expectSameResult(const DiscreteDelaunay& cpu, const DiscreteDelaunay& gl);

DiscreteDelaunay expectSameAsCpu(const std::vector<glm::dvec2>& sites,
                                 const DiscreteDelaunayOptions& options) {
    const DiscreteDelaunay cpu = discreteDelaunay(sites, options);
    const DiscreteDelaunay gl = DiscreteDelaunayGlTest::backend().run(sites, options);
    expectSameStages(cpu, gl);
    return gl;
}

// G4-G6 of both backends on a hand-made texture.
void expectSameTriangles(const IdTexture& ids, const std::vector<glm::ivec2>& pixels) {
    const CornerTexture cpuCorners = classifyCorners(ids);
    const VertexChain cpuChain = chainRowsJfa(cpuCorners);
    const DiscreteTriangles cpu = buildTriangles(ids, cpuCorners, cpuChain, pixels);
    CornerTexture glCorners;
    VertexChain glChain;
    const DiscreteTriangles gl =
        DiscreteDelaunayGlTest::backend().buildTriangles(ids, pixels, &glCorners, &glChain);
    EXPECT_TRUE(cpuCorners == glCorners) << "G4";
    EXPECT_TRUE(cpuChain == glChain) << "G5";
    EXPECT_TRUE(cpu == gl) << "G6: " << cpu.triangleCount() << " vs " << gl.triangleCount();
}

TEST_F(DiscreteDelaunayGlTest, RandomSitesGiveTheCpuStagesExactly) {
    std::int64_t four = 0, islands = 0;
    for (int size : {64, 128, 256}) {
        for (int count : {30, 400, size * 8}) {
            for (std::uint64_t seed = 1; seed <= 3; ++seed) {
                SCOPED_TRACE(testing::Message()
                             << size << "^2, " << count << " sites, seed " << seed);
                const auto sites =
                    randomSites(count, seed * 7919 + std::uint64_t(size), {-3.0, 2.0}, {7.0, 9.0});
                const DiscreteDelaunay r = expectSameAsCpu(sites, optionsFor(size));
                four += r.corners.count(CornerCase::Four);
                islands += r.islands.reassigned;
            }
        }
    }
    EXPECT_GT(four, 0); // the four-colour split ran on real diagrams
    std::printf("four-colour corners %lld, island pixels %lld\n", static_cast<long long>(four),
                static_cast<long long>(islands));
}

TEST_F(DiscreteDelaunayGlTest, DenseSitesWithCollisionsAndIslands) {
    // Far more sites than pixels: most sites are missing, G1's atomic claims decide a lot.
    for (auto [size, count] : {std::pair{64, 12000}, {128, 30000}}) {
        SCOPED_TRACE(testing::Message() << size << "^2, " << count << " sites");
        const DiscreteDelaunay r =
            expectSameAsCpu(randomSites(count, 99, {0.0, 0.0}, {1.0, 1.0}), optionsFor(size));
        EXPECT_GT(r.missing().size(), std::size_t(count) / 2);
    }
    // Plain JFA leaves islands (discrete_delaunay_test.cpp shows it), so G3 iterates.
    std::int64_t reassigned = 0;
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
        for (const char* plan : {"JFA", "half:jfa"}) {
            SCOPED_TRACE(testing::Message() << plan << ", seed " << seed);
            const DiscreteDelaunay r = expectSameAsCpu(
                randomSites(2000, seed, {0.0, 0.0}, {1.0, 1.0}), optionsFor(256, plan));
            reassigned += r.islands.reassigned;
        }
    }
    EXPECT_GT(reassigned, 0);
}

TEST_F(DiscreteDelaunayGlTest, SmallAndDegenerateInputs) {
    const std::vector<std::vector<glm::dvec2>> sets{
        {},
        {{3.0, 4.0}},
        {{1.0, 1.0}, {1.0, 1.0}, {1.0, 1.0}},
        {{0.0, 0.0}, {3.0, 10.0}, {10.0, 2.0}},
        {{0.0, 0.0}, {10.0, 0.0}, {10.0, 10.0}, {0.0, 10.0}}, // four co-circular: a Four corner
        {{0.0, 0.0}, {1.0, 1.0}, {2.0, 2.0}, {3.0, 3.0}},     // collinear
        {{0.0, 0.0}, {15.0, 15.0}, {0.2, 0.1}, {15.0, 15.0}, {14.0, 1.0}, {0.1, -0.3}},
    };
    for (std::size_t i = 0; i < sets.size(); ++i) {
        for (int size : {2, 3, 16, 64, 100}) {
            SCOPED_TRACE(testing::Message() << "set " << i << ", " << size << "^2");
            expectSameAsCpu(sets[i], optionsFor(size));
        }
    }
    const DiscreteDelaunay square = backend().run(sets[4], optionsFor(64));
    EXPECT_EQ(square.corners.count(CornerCase::Four), 1);
    EXPECT_EQ(square.mesh.triangles, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
}

TEST_F(DiscreteDelaunayGlTest, IslandPassesMatchOnAHandMadeTexture) {
    // discrete_delaunay_test.cpp's example: pixel 6 becomes an island only after pixel 5 has
    // been recoloured, so it takes a second pass (and a third that changes nothing).
    const std::vector<glm::ivec2> px{{0, 1}, {3, 1}};
    IdTexture ids(7, 3, 0);
    for (int y = 0; y < 3; ++y)
        for (int x = 2; x < 7; ++x) ids.at(x, y) = 1;
    ids.at(5, 1) = ids.at(6, 1) = 0;
    IdTexture cpu = ids, gl = ids;
    const IslandStats cpuStats = removeIslands(cpu, px);
    const IslandStats glStats = backend().removeIslands(gl, px);
    EXPECT_EQ(glStats.passes, 3);
    EXPECT_EQ(glStats.reassigned, 2);
    EXPECT_EQ(glStats.passes, cpuStats.passes);
    EXPECT_EQ(glStats.reassigned, cpuStats.reassigned);
    EXPECT_TRUE(glStats.converged);
    EXPECT_TRUE(cpu == gl);
}

TEST_F(DiscreteDelaunayGlTest, CornerCasesOfFigure66) {
    // One 2x2 texture per case; pixels 1-4 counterclockwise from the lower left.
    struct Case {
        std::uint32_t c1, c2, c3, c4;
        CornerCase expect;
    };
    const std::vector<glm::ivec2> px{{0, 0}, {9, 0}, {9, 9}, {0, 9}, {4, 12}, {12, 4}, {5, 5}};
    for (const Case c : {Case{1, 1, 1, 1, CornerCase::None},
                         {1, 1, 2, 2, CornerCase::None},
                         {1, 2, 1, 2, CornerCase::Alternating},
                         {6, 6, 2, 3, CornerCase::ThreeA},
                         {3, 6, 6, 2, CornerCase::ThreeB},
                         {2, 3, 6, 6, CornerCase::ThreeC},
                         {6, 2, 3, 6, CornerCase::ThreeD},
                         {2, 6, 3, 6, CornerCase::ExcludedA},
                         {6, 2, 6, 3, CornerCase::ExcludedB},
                         {0, 1, 2, 3, CornerCase::Four}}) {
        IdTexture ids(2, 2);
        ids.at(0, 0) = c.c1, ids.at(1, 0) = c.c2, ids.at(1, 1) = c.c3, ids.at(0, 1) = c.c4;
        CornerTexture corners;
        backend().buildTriangles(ids, px, &corners);
        EXPECT_EQ(corners.at(0, 0), c.expect) << c.c1 << c.c2 << c.c3 << c.c4;
        EXPECT_EQ(corners.count(c.expect), c.expect == CornerCase::None ? 4 : 1);
        expectSameTriangles(ids, px);
    }
}

TEST_F(DiscreteDelaunayGlTest, FourColourSplitFollowsTheCpuRule) {
    // discrete_delaunay_test.cpp's quadrilateral: pixel 4's site lies inside the circle through
    // the other three, so the diagonal is 2-4.
    IdTexture ids(2, 2);
    ids.at(0, 0) = 0, ids.at(1, 0) = 1, ids.at(1, 1) = 2, ids.at(0, 1) = 3;
    const std::vector<glm::ivec2> quad{{-3, -1}, {2, -6}, {3, 1}, {0, 1}};
    const DiscreteTriangles mesh = backend().buildTriangles(ids, quad);
    EXPECT_EQ(mesh.triangles, (std::vector<std::uint32_t>{0, 1, 3, 1, 2, 3}));
    expectSameTriangles(ids, quad);
    // Every other branch: only one diagonal valid (concave), neither (clockwise), co-circular
    // ties (a-c), collinear (degenerate) and coordinates near 2^13, where the empty-circle test
    // needs all 64 bits.
    const std::vector<std::vector<glm::ivec2>> quads{
        {{0, 0}, {4, 0}, {1, 1}, {0, 4}},
        {{0, 0}, {0, 4}, {4, 4}, {4, 0}},
        {{0, 0}, {4, 0}, {4, 4}, {0, 4}},
        {{0, 0}, {2, 0}, {4, 0}, {6, 0}},
        {{0, 0}, {8191, 1}, {8190, 8191}, {2, 8190}},
        {{1, 8191}, {0, 0}, {8191, 3}, {8191, 8191}},
    };
    for (const auto& q : quads) expectSameTriangles(ids, q);
}

TEST_F(DiscreteDelaunayGlTest, RandomTexturesHitEveryCaseAlike) {
    // Few colours on odd, non-square sizes: every corner case, clockwise and flat triangles,
    // chains over widths that are not powers of two, and many rows in one texture.
    jfa::SplitMix64 rng(2024);
    std::array<std::int64_t, kCornerCaseCount> seen{};
    for (auto [w, h, colours, span] : {std::tuple{37, 23, 4, 8},
                                       {64, 64, 5, 8192},
                                       {2, 50, 3, 4},
                                       {129, 3, 6, 100},
                                       {1, 9, 2, 4},
                                       {200, 150, 7, 8192}}) {
        std::vector<glm::ivec2> px(static_cast<std::size_t>(colours));
        for (glm::ivec2& p : px)
            p = {int(rng.below(std::uint64_t(span))), int(rng.below(std::uint64_t(span)))};
        IdTexture ids(w, h);
        for (std::uint32_t& id : ids.ids) id = std::uint32_t(rng.below(std::uint64_t(colours)));
        SCOPED_TRACE(testing::Message() << w << "x" << h << ", " << colours << " colours");
        expectSameTriangles(ids, px);
        const CornerTexture corners = classifyCorners(ids);
        for (std::size_t k = 0; k < kCornerCaseCount; ++k) seen[k] += corners.counts[k];
        // G3 walks from a pixel towards its site, so there the sites must lie in the texture.
        std::vector<glm::ivec2> inside(px.size());
        for (glm::ivec2& p : inside)
            p = {int(rng.below(std::uint64_t(w))), int(rng.below(std::uint64_t(h)))};
        IdTexture cpu = ids, gl = ids;
        const IslandStats a = removeIslands(cpu, inside), b = backend().removeIslands(gl, inside);
        EXPECT_EQ(a.passes, b.passes);
        EXPECT_EQ(a.reassigned, b.reassigned);
        EXPECT_EQ(a.converged, b.converged);
        EXPECT_TRUE(cpu == gl) << "G3";
    }
    for (std::size_t k = 0; k < kCornerCaseCount; ++k) EXPECT_GT(seen[k], 0) << "case " << k;
}

TEST_F(DiscreteDelaunayGlTest, ChainsOverLongSparseRowsMatch) {
    // Wide rows with few vertices: chain entries travel far, through the plain passes of the
    // long steps (>= 256) and across the strips of the fused shared-memory pass.
    jfa::SplitMix64 rng(77);
    for (auto [w, h, breaks] : {std::tuple{300, 5, 2},
                                {700, 4, 3},
                                {2049, 3, 5},
                                {1500, 6, 1},
                                {513, 2, 0},
                                {256, 3, 2},
                                {257, 4, 2}}) {
        IdTexture ids(w, h);
        for (int y = 0; y < h; ++y) {
            std::vector<int> at;
            for (int k = 0; k < breaks; ++k) at.push_back(int(rng.below(std::uint64_t(w))));
            for (int x = 0; x < w; ++x) {
                const auto segment =
                    std::count_if(at.begin(), at.end(), [x](int b) { return b <= x; });
                ids.at(x, y) = std::uint32_t((segment + y) % 4);
            }
        }
        const std::vector<glm::ivec2> px{{0, 0}, {5, 1}, {3, 7}, {-2, 4}};
        SCOPED_TRACE(testing::Message() << w << "x" << h << ", " << breaks << " breaks per row");
        expectSameTriangles(ids, px);
    }
}

TEST_F(DiscreteDelaunayGlTest, OneBackendServesChangingSizes) {
    // Textures are reallocated when N changes and buffers grow; results must not remember the
    // previous run.
    for (int size : {256, 64, 128, 64, 256}) {
        SCOPED_TRACE(testing::Message() << size << "^2");
        expectSameAsCpu(randomSites(size * 4, std::uint64_t(size), {0.0, 0.0}, {2.0, 1.0}),
                        optionsFor(size));
    }
    // The one-off function, too (it reads no stages back but G2's, which countIslands needs).
    const auto sites = randomSites(300, 5, {0.0, 0.0}, {1.0, 1.0});
    const DiscreteDelaunay cpu = discreteDelaunay(sites, optionsFor(128));
    const DiscreteDelaunay gl = glDiscreteDelaunay(sites, optionsFor(128));
    expectSameResult(cpu, gl);
    EXPECT_TRUE(cpu.voronoi == gl.voronoi);
    EXPECT_EQ(cpu.islandsBefore, gl.islandsBefore);
    EXPECT_TRUE(gl.corners.cases.empty() && gl.chain.next.empty());
}

// The benchmark's distributions (bench/delaunay_bench.cpp), small: `count` points of `name`.
std::vector<glm::dvec2> distribution(const std::string& name, int count, std::uint64_t seed) {
    jfa::SplitMix64 rng(seed);
    std::vector<glm::dvec2> p;
    const double twoPi = 2.0 * std::numbers::pi;
    if (name == "grid") {
        const int side = int(std::lround(std::sqrt(double(count))));
        for (int y = 0; y < side; ++y)
            for (int x = 0; x < side; ++x) p.emplace_back(double(x), double(y));
        return p;
    }
    for (int i = 0; i < count; ++i) {
        const double u = rng.unit(), v = rng.unit();
        if (name == "uniform") {
            p.emplace_back(u, v);
        } else if (name == "gaussian") { // Box-Muller, sigma 1
            const double r = std::sqrt(-2.0 * std::log(1.0 - u));
            p.emplace_back(r * std::cos(twoPi * v), r * std::sin(twoPi * v));
        } else if (name == "circle") {
            p.emplace_back(std::cos(twoPi * u), std::sin(twoPi * u));
        } else { // two-lines: half on y = x, half on y = 1 - x
            p.emplace_back(u, i % 2 == 0 ? u : 1.0 - u);
        }
    }
    return p;
}

// What the CPU steps C1-C4 take from G1-G6 (and the rest a lean run() still fills), equal.
void expectSameResult(const DiscreteDelaunay& cpu, const DiscreteDelaunay& gl) {
    EXPECT_EQ(cpu.snapped.pixels, gl.snapped.pixels) << "G1 pixels";
    EXPECT_EQ(cpu.snapped.kept, gl.snapped.kept) << "G1 kept";
    EXPECT_EQ(cpu.missing(), gl.missing()) << "G1 missing";
    EXPECT_TRUE(cpu.cleaned == gl.cleaned) << "G3 texture";
    EXPECT_EQ(cpu.islands.passes, gl.islands.passes) << "G3 passes";
    EXPECT_EQ(cpu.islands.reassigned, gl.islands.reassigned) << "G3 reassigned";
    EXPECT_EQ(cpu.islands.converged, gl.islands.converged) << "G3 converged";
    EXPECT_TRUE(cpu.mesh == gl.mesh)
        << "G6: " << cpu.mesh.triangleCount() << " vs " << gl.mesh.triangleCount() << " triangles";
}

// Lets a test run the shared backend without stage read-backs or with other bounds.
class LeanRuns {
  public:
    explicit LeanRuns(const GlDiscreteBounds& bounds = {}) {
        DiscreteDelaunayGlTest::backend().setReadStages(false);
        DiscreteDelaunayGlTest::backend().setBounds(bounds);
    }
    ~LeanRuns() {
        DiscreteDelaunayGlTest::backend().setReadStages(true);
        DiscreteDelaunayGlTest::backend().setBounds({});
    }
    LeanRuns(const LeanRuns&) = delete;
    LeanRuns& operator=(const LeanRuns&) = delete;
};

TEST_F(DiscreteDelaunayGlTest, RunMakesOneUploadAndOneReadBack) {
    const LeanRuns lean;
    std::size_t missing = 0;
    for (const char* name : {"uniform", "gaussian", "grid", "circle", "two-lines"}) {
        for (auto [size, count] : {std::pair{64, 900}, {128, 3000}, {256, 5000}}) {
            SCOPED_TRACE(testing::Message()
                         << name << ", " << count << " points, " << size << "^2");
            const auto sites = distribution(name, count, std::uint64_t(size));
            DiscreteDelaunayOptions options = optionsFor(size);
            options.countIslands = false;
            const DiscreteDelaunay gl = backend().run(sites, options);
            const GlDiscreteExtras extras = backend().extras();
            EXPECT_EQ(extras.uploads, 1);
            EXPECT_EQ(extras.readbacks, 1);
            EXPECT_EQ(extras.attempts, 1);
            const DiscreteDelaunay cpu = discreteDelaunay(sites, options);
            expectSameResult(cpu, gl);
            // The stages stayed on the GPU.
            EXPECT_TRUE(gl.voronoi.ids.empty() && gl.corners.cases.empty() &&
                        gl.chain.next.empty());
            missing += gl.missing().size();
            // The whole pipeline (C1-C4 on the GL result) gives the CPU backend's triangulation.
            DelaunayOptions cpuPipeline, glPipeline;
            cpuPipeline.discrete = glPipeline.discrete = options;
            glPipeline.discreteBackend = [](const std::vector<glm::dvec2>& s,
                                            const DiscreteDelaunayOptions& o) {
                return backend().run(s, o);
            };
            EXPECT_EQ(delaunay(sites, cpuPipeline).mesh.triangles,
                      delaunay(sites, glPipeline).mesh.triangles);
        }
    }
    EXPECT_GT(missing, std::size_t(0)); // the missing-site list came back non-empty somewhere
    // Asking for the stages costs one read-back each.
    backend().setReadStages(true);
    const auto sites = distribution("uniform", 500, 3);
    expectSameAsCpu(sites, optionsFor(64));
    EXPECT_EQ(backend().extras().uploads, 1);
    EXPECT_EQ(backend().extras().readbacks, 4);
}

TEST_F(DiscreteDelaunayGlTest, ShortBoundsRunAgainWithTheSameResult) {
    // One queued G3 pass where plain JFA needs several, and no room for G6's records: the first
    // attempt's read-back says so and the second runs with the full bounds.
    GlDiscreteBounds shortBounds;
    shortBounds.islandPasses = 1;
    shortBounds.meshPerSite = 0.0;
    shortBounds.meshSlack = 0;
    const LeanRuns lean(shortBounds);
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        SCOPED_TRACE(testing::Message() << "seed " << seed);
        const auto sites = randomSites(2000, seed, {0.0, 0.0}, {1.0, 1.0});
        DiscreteDelaunayOptions options = optionsFor(256, "JFA");
        options.countIslands = false;
        const DiscreteDelaunay gl = backend().run(sites, options);
        const DiscreteDelaunay cpu = discreteDelaunay(sites, options);
        EXPECT_GT(cpu.islands.passes, 1); // so one queued pass was too few
        EXPECT_EQ(backend().extras().attempts, 2);
        EXPECT_EQ(backend().extras().uploads, 1);
        EXPECT_EQ(backend().extras().readbacks, 2);
        expectSameResult(cpu, gl);
        backend().setBounds(shortBounds); // forget the passes this run needed
    }
}

TEST_F(DiscreteDelaunayGlTest, BadInputIsRejectedAsOnTheCpu) {
    const std::vector<glm::dvec2> one{{0.0, 0.0}};
    EXPECT_THROW(backend().run(one, optionsFor(1)), std::invalid_argument);
    EXPECT_THROW(backend().run(one, optionsFor(kMaxDiscreteSize + 1)), std::invalid_argument);
    EXPECT_THROW(backend().run(one, optionsFor(16, "nonsense")), std::invalid_argument);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(backend().run({{0.0, 0.0}, {nan, 1.0}}, optionsFor(16)), std::invalid_argument);
    DiscreteDelaunayOptions threads = optionsFor(16);
    threads.threads = -1;
    EXPECT_THROW(backend().run(one, threads), std::invalid_argument);
    IdTexture empty;
    EXPECT_THROW(backend().removeIslands(empty, {}), std::invalid_argument);
}

// Not a test: the llvmpipe (or GPU) timings per step against the CPU backend. Run with
// --gtest_also_run_disabled_tests; FLOODLIGHT_GL_DELAUNAY_SIZES="1024:10000,2048:100000".
TEST_F(DiscreteDelaunayGlTest, DISABLED_TimingsPerStep) {
    const char* env = std::getenv("FLOODLIGHT_GL_DELAUNAY_SIZES");
    std::vector<std::pair<int, int>> cases{{1024, 10000}, {2048, 100000}};
    if (env) {
        cases.clear();
        int size = 0, count = 0, used = 0;
        for (const char* p = env; std::sscanf(p, "%d:%d%n", &size, &count, &used) == 2;) {
            cases.emplace_back(size, count);
            p += used;
            if (*p != ',') break;
            ++p;
        }
    }
    std::printf("renderer: %s, G2 kernel %s\n", gl::rendererName().c_str(),
                jfa::kernelName(floodKind()));
    for (auto [size, count] : cases) {
        const auto sites = randomSites(count, 1, {0.0, 0.0}, {1.0, 1.0});
        DiscreteDelaunayOptions options = optionsFor(size);
        options.countIslands = false;
        backend().run(sites, options); // warm-up: first-use allocations and shader variants
        // The fastest of a few runs per step: other processes only ever add time.
        auto fastest = [](DiscreteTimings& best, const DiscreteTimings& t) {
            double* b[] = {&best.g1, &best.g2, &best.g3, &best.g4, &best.g5, &best.g6};
            const double v[] = {t.g1, t.g2, t.g3, t.g4, t.g5, t.g6};
            for (int k = 0; k < 6; ++k) *b[k] = *b[k] > 0.0 ? std::min(*b[k], v[k]) : v[k];
        };
        DiscreteTimings c, g;
        DiscreteDelaunay gl, cpu;
        double readback = 0.0;
        for (int run = 0; run < 3; ++run) {
            gl = backend().run(sites, options);
            readback = run == 0 ? backend().extras().readbackMs
                                : std::min(readback, backend().extras().readbackMs);
            cpu = discreteDelaunay(sites, options);
            fastest(g, gl.timings);
            fastest(c, cpu.timings);
        }
        expectSameStages(cpu, gl);
        std::printf("%d^2, %d sites, %zu triangles (ms)\n", size, count, gl.mesh.triangleCount());
        std::printf("  step   cpu       gl\n");
        const double cs[] = {c.g1, c.g2, c.g3, c.g4, c.g5, c.g6, c.total()};
        const double gs[] = {g.g1, g.g2, g.g3, g.g4, g.g5, g.g6, g.total()};
        const char* names[] = {"G1", "G2", "G3", "G4", "G5", "G6", "total"};
        for (int k = 0; k < 7; ++k) std::printf("  %-5s %8.1f %8.1f\n", names[k], cs[k], gs[k]);
        std::printf("  gl read-back of the stage textures: %.1f ms\n", readback);
    }
}

} // namespace
} // namespace fl::geom
