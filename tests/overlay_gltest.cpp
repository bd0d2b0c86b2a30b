// The overlays (renderer/overlays): every computing overlay against its CPU reference (the GL
// floods against jfa::flood on the same seeds, error counts and difference masks against CPU
// counts, the trapezoid against geom::fitTrapezoid), the drawn pixels against the colours
// OverlayColours.h predicts, and a golden per mode on the default scene. 256^2 throughout.
// Regenerate the goldens with FLOODLIGHT_UPDATE_GOLDENS=1 (tests/golden/README.md).

#include "GlTest.h"
#include "ImageCompare.h"

#include <renderer/overlays/OverlayCapture.h>
#include <renderer/overlays/OverlayColours.h>
#include <renderer/overlays/SiteDiagram.h>
#include <renderer/soft/EyeSoftShadow.h>
#include <renderer/soft/PenumbraMap.h>
#include <scene/GltfLoader.h>

#include <jfa/CpuKernel.h>
#include <jfa/NearestSite.h>
#include <jfa/Reference.h>
#include <jfa/Sites.h>

#include <functional>
#include <sstream>

namespace fl::test {
namespace {

constexpr int kSize = 256;
const std::filesystem::path kDefaultAsset =
    std::filesystem::path(FLOODLIGHT_SOURCE_DIR) / "assets" / "default.glb";

// One rendered frame of the default scene (light radius 1.5 as in the soft-shadow goldens, so
// penumbrae span several texels) with an overlay renderer beside it.
struct Frame {
    Scene scene;
    gl::ShaderLibrary shaders;
    std::unique_ptr<Renderer> renderer;
    CameraView camera;
    std::unique_ptr<OverlayRenderer> overlays;
    OverlayControls controls;

    explicit Frame(std::string_view method, ShadowMapProvider provider = ShadowMapProvider::Uniform,
                   float radius = 1.5f, int passes = 6)
        : scene(loadGltf(kDefaultAsset)) {
        scene.light->radius = radius;
        RenderSettings settings;
        settings.shadow.size = kSize;
        settings.shadow.provider = provider;
        settings.method = std::string(method);
        settings.options.set(floodPassesOption().flag, passes);
        // As the window and `render --overlay` do for the overlays that show the whole map
        // (the default flood region, view, is exact only where the eye's pixels read).
        settings.wholeFlood = true;
        renderer = std::make_unique<Renderer>(shaders, scene, settings);
        renderer->resize(kSize, kSize);
        camera = makeCameraView(scene, {}, 1.0f);
        renderer->render(camera);
        overlays = std::make_unique<OverlayRenderer>(shaders);
    }
    OverlayCapture capture(OverlayMode mode) {
        return captureOverlay(*overlays, mode, *renderer, camera, controls, kSize, kSize);
    }
    /// The frame's flood (flooding methods only).
    [[nodiscard]] const FloodFrame& flood() const {
        const FloodFrame* f = renderer->flood();
        if (!f) throw std::logic_error("the frame's method does not flood");
        return *f;
    }
    /// JFA-L's settings as the frame's options ask for them.
    [[nodiscard]] PenumbraSettings penumbraSettings() const {
        PenumbraSettings ps;
        ps.passes = renderer->settings().options.integer(floodPassesOption());
        return ps;
    }
};

using Rgb = glm::u8vec3;
Rgb pixel(const ByteImage& img, int x, int glY) { // glY: row 0 at the bottom
    const std::size_t i =
        (std::size_t(img.height - 1 - glY) * std::size_t(img.width) + std::size_t(x)) * 4;
    return {img.data[i], img.data[i + 1], img.data[i + 2]};
}

// Every pixel of a 1:1 picture against `expected(x, y)`: at most `tolerance` 8-bit steps off.
void expectPixels(const ByteImage& img, const std::function<glm::vec3(int, int)>& expected,
                  int tolerance, const char* what) {
    std::int64_t bad = 0;
    std::string first;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const Rgb got = pixel(img, x, y), want = overlay::toBytes(expected(x, y));
            const glm::ivec3 d = glm::abs(glm::ivec3(got) - glm::ivec3(want));
            if (std::max({d.x, d.y, d.z}) > tolerance && bad++ == 0) {
                std::ostringstream o;
                o << "(" << x << ", " << y << ") got " << glm::ivec3(got).x << ","
                  << glm::ivec3(got).y << "," << glm::ivec3(got).z << " want " << glm::ivec3(want).x
                  << "," << glm::ivec3(want).y << "," << glm::ivec3(want).z;
                first = o.str();
            }
        }
    EXPECT_EQ(bad, 0) << what << ": first " << first;
}

// The colour overlay_grid.frag.glsl gives a Voronoi texel (mode 3).
glm::vec3 voronoiColour(const jfa::Grid& g, const std::vector<std::uint8_t>& mask, int x, int y) {
    const jfa::Cell& c = g.at(x, y);
    if (mask[std::size_t(y) * std::size_t(g.width) + std::size_t(x)]) return overlay::kErrorColour;
    if (c.z < 0.0f) return overlay::kEmptyColour;
    if (jfa::pixelOf(c.x) == x && jfa::pixelOf(c.y) == y) return glm::vec3(0.0f);
    return overlay::idColour(std::uint32_t(c.z));
}

void expectGolden(const ByteImage& img, const std::string& name) {
    // Overlays are exact functions of the frame's data; on the machine that made the goldens
    // they reproduce bit for bit. Another driver may flip shadow-map comparisons and silhouette
    // tests within float precision of the surface, which moves single seeds and the regions
    // they own: allow 2% of pixels to differ by more than 16 steps and a mean of 3 steps. A
    // wrong colour map, a wrong mode or a shifted grid breaks both by far.
    const Tolerance tol{.maxAbs = 255, .meanAbs = 3.0, .pixelThreshold = 16, .maxPercentOver = 2.0};
    const CompareResult c = compareWithGolden(img, name, tol);
    std::printf("%s: %s\n", name.c_str(), c.report.c_str());
    EXPECT_TRUE(c.pass) << c.report;
}

class OverlayTest : public GlTest {};

TEST(OverlayNames, RoundTripAndOrder) {
    ASSERT_EQ(allOverlayModes().size(), 11u);
    EXPECT_EQ(allOverlayModes().front(), OverlayMode::None);
    for (const OverlayMode m : allOverlayModes()) EXPECT_EQ(parseOverlay(overlayName(m)), m);
    EXPECT_FALSE(parseOverlay("nope"));
    EXPECT_EQ(OverlayRenderer::variantNames().size(), overlay::variantSpecs().size());
    EXPECT_EQ(OverlayRenderer::delaunayStageNames().size(), 9u);
}

TEST(OverlayPlans, TruncateKeepsThePrefix) {
    const jfa::Plan p = penumbraPlan({}, 256);
    EXPECT_EQ(overlay::truncatePlan(p, 2).steps(), (std::vector<int>{32, 16}));
    EXPECT_EQ(overlay::truncatePlan(p, 0).passCount(), 0);
    EXPECT_EQ(overlay::truncatePlan(p, -1), p);
    EXPECT_THROW(overlay::truncatePlan(jfa::Plan::halfResolution(64, 64), 1),
                 std::invalid_argument);
}

// Voronoi of the JFA-L silhouette seeds, every variant: the GL diagram equals the CPU kernel's
// on the same seeds, the error count equals the CPU count, and the pixels are its colours.
TEST_F(OverlayTest, VoronoiOfSeedsMatchesCpuKernel) {
    Frame s("jfa-l");
    const jfa::Grid sites = overlay::sitesFromSeeds(readFloodGrid(s.flood(), *s.flood().seeds));
    ASSERT_GT(jfa::siteCells(sites).size(), 100u);
    const jfa::NearestSite crit{true};
    const jfa::ExactField exact = jfa::exactNearest(sites, crit);
    std::int64_t totalErrors = 0;
    for (int v = 0; v < int(OverlayRenderer::variantNames().size()); ++v) {
        s.controls.variant = v;
        const OverlayCapture cap = s.capture(OverlayMode::Voronoi);
        const OverlayResult& r = s.overlays->lastResult();
        ASSERT_TRUE(r.drawn);
        const jfa::Grid cpu = jfa::flood(overlay::variantPlan(v, kSize, kSize), sites, crit);
        EXPECT_TRUE(r.grid == cpu) << "variant " << v;
        EXPECT_EQ(r.count, jfa::countErrors(cpu, exact, crit)) << "variant " << v;
        totalErrors += r.count;
        expectPixels(
            cap.image, [&](int x, int y) { return voronoiColour(cpu, r.mask, x, y); }, 0,
            "voronoi");
        if (v == 0) expectGolden(cap.image, "overlay_256_voronoi");
    }
    EXPECT_GT(totalErrors, 0) << "no variant made an error: the red errors were never drawn";
}

// Distance transform of the JFA-E boundary seeds (eye space).
TEST_F(OverlayTest, DistanceTransformOfBoundarySeeds) {
    Frame s("jfa-e");
    const OverlayCapture cap = s.capture(OverlayMode::DistanceTransform);
    const OverlayResult& r = s.overlays->lastResult();
    ASSERT_TRUE(r.drawn);
    const jfa::Grid sites = overlay::sitesFromSeeds(readFloodGrid(s.flood(), *s.flood().seeds));
    ASSERT_GT(jfa::siteCells(sites).size(), 100u)
        << "the JFA-E frame has (almost) no boundary seeds";
    const jfa::NearestSite crit{true};
    const jfa::Grid cpu = jfa::flood(overlay::variantPlan(0, kSize, kSize), sites, crit);
    EXPECT_TRUE(r.grid == cpu);
    const jfa::ExactField exact = jfa::exactNearest(sites, crit);
    double maxSq = 0.0;
    for (double d : exact.distSq) maxSq = std::max(maxSq, d);
    const float top = std::max(float(std::sqrt(maxSq)), 1.0f);
    // The ramp is evaluated in float on both sides; length() may round differently: 1 step.
    expectPixels(
        cap.image,
        [&](int x, int y) {
            if (r.mask[std::size_t(y) * kSize + std::size_t(x)]) return overlay::kErrorColour;
            const jfa::Cell& c = cpu.at(x, y);
            if (c.z < 0.0f) return overlay::kEmptyColour;
            return overlay::ramp(glm::length(glm::vec2(c.x - float(x), c.y - float(y))) / top);
        },
        1, "distance transform");
    expectGolden(cap.image, "overlay_256_distance-transform");
}

ReceiverGrid receiversOf(const gl::Texture& t) {
    const jfa::Grid g = jfa::readGrid(t);
    ReceiverGrid r{g.width, g.height, {}};
    for (const jfa::Cell& c : g.cells) r.points.emplace_back(c.x, c.y, c.z, c.w);
    return r;
}

// Flood pass by pass: after k passes the GL state equals the CPU kernel's run of the frame's
// plan cut after k passes; all passes reproduce the frame's own penumbra map.
TEST_F(OverlayTest, FloodPassesMatchTruncatedCpuPlan) {
    Frame s("jfa-l");
    const ReceiverGrid receivers = receiversOf(s.renderer->decodedShadowReceivers());
    PenumbraCriterion crit;
    crit.light = s.renderer->disk();
    crit.receivers = &receivers;
    crit.umbraDepth = s.flood().umbraDepth; // --penumbra both (the default): the umbra side
    const jfa::Grid seeds = readFloodGrid(s.flood(), *s.flood().seeds);
    const jfa::Plan full = penumbraPlan(s.penumbraSettings(), kSize);
    for (int k : {0, 1, 3, -1}) {
        s.controls.floodPass = k;
        const OverlayCapture cap = s.capture(OverlayMode::FloodPasses);
        const jfa::Grid cpu = jfa::flood(overlay::truncatePlan(full, k), seeds, crit);
        EXPECT_TRUE(s.overlays->lastResult().grid == cpu) << "after " << k << " passes";
        if (k == 3) expectGolden(cap.image, "overlay_256_flood-passes-3");
    }
    EXPECT_TRUE(s.overlays->lastResult().grid == readFloodGrid(s.flood(), *s.flood().flooded));
}

// The default flood region, view, finds seeds and floods JFA-L's map only around what the eye's
// pixels read; a frame for an overlay that shows the whole map (RenderSettings::wholeFlood) floods
// the band, unless the user chose a region.
TEST_F(OverlayTest, OverlaysOfTheWholeMapGetTheBand) {
    for (OverlayMode m : allOverlayModes())
        EXPECT_EQ(overlayReadsWholeFlood(m),
                  m == OverlayMode::Seeds || m == OverlayMode::PenumbraMap ||
                      m == OverlayMode::FloodPasses || m == OverlayMode::Voronoi ||
                      m == OverlayMode::DistanceTransform || m == OverlayMode::JfaVsFlood)
            << overlayName(m);
    Frame s("jfa-l");
    EXPECT_EQ(s.flood().region, jfa::FloodRegion::Band);
    RenderSettings st = s.renderer->settings();
    st.wholeFlood = false;
    s.renderer->setSettings(st);
    s.renderer->render(s.camera);
    EXPECT_EQ(s.flood().region, jfa::FloodRegion::View) << "the default region";
    st.wholeFlood = true;
    st.options.set(floodRegionOption().flag, "view");
    s.renderer->setSettings(st);
    s.renderer->render(s.camera);
    EXPECT_EQ(s.flood().region, jfa::FloodRegion::View) << "the user's choice stands";
}

// JFA vs standard flooding: the reference equals the CPU standard flood of the same seeds, and
// the mask and the red pixels are exactly the texels where the two read-back floods differ.
TEST_F(OverlayTest, JfaVsFloodMaskIsTheCpuComparison) {
    // Light radius 6: at 1.5 the two floods agree on every texel of this 256^2 map (measured:
    // 0 differ; 4 at radius 3, 149 at 6), which would leave nothing to check.
    Frame s("jfa-l", ShadowMapProvider::Uniform, 6.0f);
    const OverlayCapture cap = s.capture(OverlayMode::JfaVsFlood);
    const OverlayResult& r = s.overlays->lastResult();
    ASSERT_TRUE(r.drawn);
    const ReceiverGrid receivers = receiversOf(s.renderer->decodedShadowReceivers());
    PenumbraCriterion crit;
    crit.light = s.renderer->disk();
    crit.receivers = &receivers;
    crit.umbraDepth = s.flood().umbraDepth; // --penumbra both (the default): the umbra side
    PenumbraSettings ps = s.penumbraSettings();
    ps.standardFlooding = true;
    const jfa::Grid flood =
        jfa::flood(penumbraPlan(ps, kSize), readFloodGrid(s.flood(), *s.flood().seeds), crit);
    EXPECT_TRUE(r.reference == flood);
    const jfa::Grid jfa = readFloodGrid(s.flood(), *s.flood().flooded);
    std::int64_t differ = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const bool d = !(jfa.at(x, y) == flood.at(x, y));
            differ += d;
            EXPECT_EQ(r.mask[std::size_t(y) * kSize + std::size_t(x)], d ? 1 : 0);
        }
    EXPECT_EQ(r.count, differ);
    EXPECT_GT(differ, 0) << "JFA and flooding agree everywhere: nothing to highlight";
    expectPixels(
        cap.image,
        [&](int x, int y) {
            if (!(jfa.at(x, y) == flood.at(x, y))) return overlay::kErrorColour;
            return jfa.at(x, y).w != 0.0f ? overlay::kSameColour : glm::vec3(0.0f);
        },
        0, "jfa-vs-flood");
    expectGolden(cap.image, "overlay_256_jfa-vs-flood");
    // A second draw of the same frame reuses the reference flood and draws the same picture.
    const OverlayCapture again = s.capture(OverlayMode::JfaVsFlood);
    EXPECT_NE(again.hud.back().find("reused"), std::string::npos);
    EXPECT_EQ(again.image.data, cap.image.data);
    EXPECT_TRUE(s.overlays->lastResult().reference == flood);
}

// The same in eye space (JFA-E): the mask is the comparison of the two read-back floods. Four
// passes (15 for flooding) keep the eye-space floods of llvmpipe within a few seconds.
TEST_F(OverlayTest, JfaVsFloodEyeSpace) {
    Frame s("jfa-e", ShadowMapProvider::Uniform, 1.5f, 4);
    s.capture(OverlayMode::JfaVsFlood);
    const OverlayResult& r = s.overlays->lastResult();
    ASSERT_TRUE(r.drawn);
    ASSERT_GT(
        jfa::siteCells(overlay::sitesFromSeeds(readFloodGrid(s.flood(), *s.flood().seeds))).size(),
        100u)
        << "the JFA-E frame has (almost) no boundary seeds";
    const jfa::Grid jfa = readFloodGrid(s.flood(), *s.flood().flooded);
    EXPECT_TRUE(r.grid == jfa);
    std::int64_t differ = 0;
    for (std::size_t i = 0; i < jfa.cells.size(); ++i) {
        const bool d = !(jfa.cells[i] == r.reference.cells[i]);
        differ += d;
        EXPECT_EQ(r.mask[i], d ? 1 : 0);
    }
    EXPECT_EQ(r.count, differ);
    EXPECT_GT(differ, 0);
    // The reference is what a flood-E frame of the same view floods.
    Frame floodE("flood-e", ShadowMapProvider::Uniform, 1.5f, 4);
    EXPECT_TRUE(r.reference == readFloodGrid(floodE.flood(), *floodE.flood().flooded));
}

// The playground's live error count is the CPU count for the same sites and variant; clicked
// sites are added; the red pixels are the error texels.
TEST_F(OverlayTest, PlaygroundCountsErrorsLikeTheCpu) {
    Frame s("hard");
    s.controls.playgroundSites = 400;
    s.controls.seed = 7;
    s.controls.clickedSites = {{0.25f, 0.75f}};
    std::int64_t total = 0;
    for (int v = 0; v < int(OverlayRenderer::variantNames().size()); ++v) {
        s.controls.variant = v;
        const OverlayCapture cap = s.capture(OverlayMode::VoronoiPlayground);
        const OverlayResult& r = s.overlays->lastResult();
        std::vector<jfa::Site> sites = jfa::randomIntegerSites(400, kSize, kSize, 7);
        sites.push_back({64.0f, 192.0f});
        const jfa::Grid seeds = jfa::seedPoints(sites, kSize, kSize, true).grid;
        const jfa::NearestSite crit{true};
        const jfa::Grid cpu = jfa::flood(overlay::variantPlan(v, kSize, kSize), seeds, crit);
        EXPECT_TRUE(r.grid == cpu);
        EXPECT_EQ(r.count, jfa::countErrors(cpu, jfa::exactNearest(seeds, crit), crit));
        total += r.count;
        std::int64_t red = 0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) red += pixel(cap.image, x, y) == Rgb(255, 0, 0);
        EXPECT_EQ(red, r.count);
        EXPECT_NE(cap.hud.back().find("errors (red): " + std::to_string(r.count)),
                  std::string::npos);
        if (v == 0) expectGolden(cap.image, "overlay_256_playground");
    }
    EXPECT_GT(total, 0);
    s.controls.regenerate = true;
    s.capture(OverlayMode::VoronoiPlayground);
    EXPECT_EQ(s.controls.seed, 8u);
    EXPECT_TRUE(s.controls.clickedSites.empty());
}

// The trapezoid's corners are fitTrapezoid's, and the drawn lines pass through the projected
// corners' edges (sampled inside the view).
TEST_F(OverlayTest, TrapezoidLinesAreTheFitsCorners) {
    Frame s("hard", ShadowMapProvider::Tsm);
    const OverlayCapture cap = s.capture(OverlayMode::Trapezoid);
    const OverlayResult& r = s.overlays->lastResult();
    const ShadowMapPass::Outputs& sh = *s.renderer->shadow();
    ASSERT_NE(sh.trapezoid, nullptr);
    // The fit as ShadowMapPass makes it: the eye frustum clamped to the scene's depth range.
    const glm::mat4 proj = geom::clampDepthRange(s.camera.proj, s.camera.view, s.scene.bounds);
    const geom::TrapezoidFit fit = geom::fitTrapezoid(
        glm::dmat4(sh.lightViewProj), glm::inverse(glm::dmat4(proj) * glm::dmat4(s.camera.view)),
        s.renderer->settings().shadow.tsm);
    ASSERT_EQ(r.corners.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(r.corners[i], fit.corners[i]);
        EXPECT_EQ(r.corners[i], sh.trapezoid->corners[i]);
    }
    // The line colour within one level: 0.9 x 255 = 229.5, which GL may round either way.
    const Rgb yellow = overlay::toBytes({1.0f, 0.9f, 0.1f});
    const auto isYellow = [&](const Rgb& c) {
        return glm::all(
            glm::lessThanEqual(glm::abs(glm::ivec3(c) - glm::ivec3(yellow)), glm::ivec3(1)));
    };
    int sampled = 0, found = 0;
    for (std::size_t i = 0; i < 4; ++i)
        for (int k = 1; k < 20; ++k) {
            const glm::vec2 ndc =
                glm::mix(fit.corners[i], fit.corners[(i + 1) % 4], float(k) / 20.0f);
            const glm::ivec2 p = glm::ivec2(glm::floor((ndc * 0.5f + 0.5f) * float(kSize)));
            if (p.x < 2 || p.y < 2 || p.x >= kSize - 2 || p.y >= kSize - 2) continue;
            ++sampled;
            bool hit = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    hit |= isYellow(pixel(cap.image, p.x + dx, p.y + dy));
            found += hit;
        }
    ASSERT_GT(sampled, 10);
    EXPECT_GE(found, sampled * 9 / 10) << found << " of " << sampled;
    expectGolden(cap.image, "overlay_256_trapezoid");
}

// The picture-only modes: each draws, restores the GL state, and matches its golden.
TEST_F(OverlayTest, PictureGoldens) {
    Frame s("jfa-l");
    for (OverlayMode m : {OverlayMode::ShadowMap, OverlayMode::Seeds, OverlayMode::PenumbraMap,
                          OverlayMode::FloodPasses}) {
        glViewport(3, 4, 5, 6);
        glEnable(GL_DEPTH_TEST);
        const OverlayCapture cap = s.capture(m);
        GLint vp[4];
        glGetIntegerv(GL_VIEWPORT, vp);
        EXPECT_EQ(vp[0], 0); // captureOverlay set the viewport to the target; draw restored it
        EXPECT_EQ(vp[2], kSize);
        EXPECT_TRUE(glIsEnabled(GL_DEPTH_TEST));
        glDisable(GL_DEPTH_TEST);
        EXPECT_TRUE(s.overlays->lastResult().drawn);
        if (m != OverlayMode::FloodPasses) // its golden is FloodPassesMatchTruncatedCpuPlan's
            expectGolden(cap.image, "overlay_256_" + std::string(overlayName(m)));
    }
    // draw() leaves the caller's framebuffer, viewport and depth test as they were, also after
    // a mode that runs a flood kernel (which binds its own framebuffers and viewports).
    {
        const gl::Texture target(GL_RGBA8, 64, 32);
        const gl::Framebuffer fbo = gl::Framebuffer::forColor(target, "test target");
        glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
        glViewport(3, 4, 50, 20);
        glEnable(GL_DEPTH_TEST);
        s.overlays->draw(OverlayMode::FloodPasses, *s.renderer, s.camera, s.controls, 64, 32);
        GLint bound = 0, vp[4];
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
        glGetIntegerv(GL_VIEWPORT, vp);
        EXPECT_EQ(GLuint(bound), fbo.id());
        EXPECT_EQ(std::vector<GLint>(vp, vp + 4), (std::vector<GLint>{3, 4, 50, 20}));
        EXPECT_TRUE(glIsEnabled(GL_DEPTH_TEST));
        glDisable(GL_DEPTH_TEST);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }
    // Seeds are drawn exactly where the seed texture holds one.
    const OverlayCapture seeds = s.capture(OverlayMode::Seeds);
    const jfa::Grid g = readFloodGrid(s.flood(), *s.flood().seeds);
    expectPixels(
        seeds.image,
        [&](int x, int y) {
            return g.at(x, y).w != 0.0f ? overlay::idColour(std::uint32_t(y * kSize + x))
                                        : glm::vec3(0.0f);
        },
        0, "seeds");
    // A hard-shadow frame has no seeds: the soft modes say so instead of drawing.
    Frame hard("hard");
    const OverlayCapture none = hard.capture(OverlayMode::Voronoi);
    EXPECT_FALSE(hard.overlays->lastResult().drawn);
    EXPECT_NE(none.hud.back().find("needs a soft method"), std::string::npos);
}

// The Delaunay visualiser steps through the nine stages; the islands stage marks exactly the
// pixels G3 recoloured.
TEST_F(OverlayTest, DelaunayStages) {
    Frame s("hard");
    s.controls.delaunayPoints = 300;
    for (int k = 0; k < 9; ++k) {
        s.controls.delaunayStep = k;
        const OverlayCapture cap = s.capture(OverlayMode::Delaunay);
        ASSERT_TRUE(s.overlays->lastResult().drawn) << cap.hud.back();
        EXPECT_NE(cap.hud[1].find(OverlayRenderer::delaunayStageNames()[std::size_t(k)]),
                  std::string::npos);
        if (k == 1 || k == 2 || k == 3 || k == 8)
            expectGolden(cap.image, "overlay_256_delaunay-" + std::to_string(k + 1));
    }
    s.controls.delaunayStep = 99;
    s.capture(OverlayMode::Delaunay);
    EXPECT_EQ(s.controls.delaunayStep, 8);
}

} // namespace
} // namespace fl::test
