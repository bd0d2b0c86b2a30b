// JFA-E (thesis §5.4) on the GPU against its CPU reference, phase by phase; the jump-too-far
// fixes on the default scene; pictures.

#include "GlTest.h"
#include "ImageCompare.h"
#include "TestMethods.h"
#include "TestPaths.h"
#include "TestScenes.h"

#include <gpu/ReadBack.h>
#include <renderer/Renderer.h>
#include <renderer/run/Capture.h>
#include <renderer/soft/EyeFloodReach.h>
#include <renderer/soft/EyeSoftShadow.h>
#include <scene/GltfLoader.h>

#include <jfa/CpuKernel.h>
#include <jfa_gl/GlKernel.h>

#include <cmath>
#include <cstdio>

namespace fl::test {
namespace {

class JfaETest : public GlTest {};

std::vector<glm::vec4> readVec4(const gl::Texture& t) {
    const jfa::Grid g = jfa::readGrid(t);
    std::vector<glm::vec4> out;
    out.reserve(g.cells.size());
    for (const jfa::Cell& c : g.cells) out.emplace_back(c.x, c.y, c.z, c.w);
    return out;
}

// An R32F texture, row 0 first (GL order, as the EyeImage).
std::vector<float> readR32F(const gl::Texture& t) {
    return gl::readTexels<float>(t, GL_RED, GL_FLOAT);
}

// Phase 2's output of an eye-space flood, decoded from its packed cells by the GPU's helpers
// (eye_decode.glsl): the bits the phases read.
EyeImage readEyeImage(const FloodFrame& f) {
    const auto [points, occluders] = f.eyeCells->decoded();
    return {points.width(), points.height(), readVec4(points), readVec4(occluders)};
}

// Phase 3 also decodes each seed's occluder once for the flood and the composite
// (eyeSeedOccluder): at every seed pixel it must be phase 2's occluder and object id, exactly.
// Phase 3's seed occluders as the flood reads them: the CPU seeds' points (phase 2's, or walked
// to the silhouette), with phase 2's object ids.
void expectSeedOccludersArePhaseThrees(const FloodFrame& f, const jfa::Grid& seeds,
                                       const EyeImage& image) {
    ASSERT_NE(f.eyeCells->seedOccluders, nullptr);
    const std::vector<glm::vec4> seedOccluders = readVec4(*f.eyeCells->seedOccluders);
    ASSERT_EQ(seedOccluders.size(), image.occluders.size());
    for (std::size_t i = 0; i < seeds.cells.size(); ++i) {
        const jfa::Cell& c = seeds.cells[i];
        if (c.w == 0.0f) continue;
        ASSERT_TRUE(seedOccluders[i] == glm::vec4(c.x, c.y, c.z, image.occluders[i].w))
            << "seed pixel " << i;
    }
}

std::size_t nonEmpty(const jfa::Grid& g) {
    std::size_t n = 0;
    for (const jfa::Cell& c : g.cells) n += c.w != 0.0f;
    return n;
}

// Each pixel's receiver plane (SurfacesPass's plane normal) in the EyeImage's layout.
std::vector<glm::vec3> receiverPlanes(const SurfacesPass::Outputs& surfaces, const EyeImage& im) {
    std::vector<glm::vec3> planes(im.points.size());
    const FloatImage n = surfaces.readNormals(SurfacesPass::Outputs::Normal::Plane);
    for (int y = 0; y < im.height; ++y) // readNormals: row 0 at the top
        for (int x = 0; x < im.width; ++x) {
            const std::size_t f = (static_cast<std::size_t>(im.height - 1 - y) * im.width + x) * 4;
            planes[im.index(x, y)] = {n.data[f], n.data[f + 1], n.data[f + 2]};
        }
    return planes;
}

// Phase 5 on the GPU (`frame`) against its CPU twin (`cpu`); the penumbra pixels counted. With
// centre points: GLSL acos is not correctly rounded (llvmpipe's polynomial is off by ~1e-5 near
// 1), so intensities agree to 5e-5 and the umbra / lit decisions are exact. With edge points the
// composite fits the occluder's edges (occluder_lines.glsl): GLSL's atan, cos, sin and divisions
// are not correctly rounded either, so the fitted edges agree to ~1e-5 of a texel and the shares
// to 5e-4; and a map test or a covered texel at a rounding boundary may decide the other way on
// either side: one fused sample of 16 moves a share by up to 1/16, which we allow on 1% of the
// penumbra pixels.
std::size_t expectCompositeMatches(const std::vector<float>& frame, const std::vector<float>& cpu,
                                   bool edges) {
    std::size_t penumbra = 0, apart = 0;
    float worst = 0.0f;
    for (std::size_t i = 0; i < frame.size(); ++i) {
        const float c = cpu[i];
        penumbra += c > 0.0f && c < 1.0f;
        if (!edges) {
            if (c == 0.0f || c == 1.0f)
                EXPECT_EQ(frame[i], c) << "pixel " << i;
            else
                EXPECT_NEAR(frame[i], c, 5e-5f) << "pixel " << i;
            continue;
        }
        const float d = std::abs(frame[i] - c);
        worst = std::max(worst, d);
        if (d > 5e-4f) {
            ++apart;
            EXPECT_LE(d, 1.0f / 16.0f + 5e-4f) << "pixel " << i;
        }
    }
    if (edges) {
        EXPECT_LE(apart, penumbra / 100) << "worst " << worst;
        std::printf("edges: %zu of %zu penumbra pixels beyond 5e-4, worst %.3g\n", apart, penumbra,
                    double(worst));
    }
    return penumbra;
}

TEST_F(JfaETest, PhasesMatchTheCpuReference) {
    // A box on a ground plane under a large disk light (the JFA-L test's scene): inner and outer
    // penumbrae on the ground, self-shadowing on the box.
    const SceneView s = spotLitBox();
    const gl::ShaderLibrary& shaders = fl::test::testShaders();
    RenderSettings hardSettings;
    hardSettings.shadow.size = 128;

    struct Case {
        std::string_view method;
        bool fixes;
        bool edges;      // --occluder-points edge (else centre)
        int width = 64;  // a width that is not a power of two checks the seed pixels the
        int height = 64; // criterion finds from their indices without an integer division
    };
    for (const Case& k : {Case{"jfa-e", true, true}, Case{"flood-e", true, true},
                          Case{"jfa-e", false, false}, Case{"jfa-e", true, true, 75, 61}}) {
        SCOPED_TRACE(std::string(k.method) + (k.fixes ? " fixes on" : " fixes off") +
                     (k.edges ? ", edge points" : ", centre points") + ", " +
                     std::to_string(k.width) + "x" + std::to_string(k.height));
        Renderer hard(shaders, s.scene, hardSettings);
        hard.resize(k.width, k.height);
        hard.render(s.camera);
        const std::vector<float> hardVisibility = readR32F(hard.visibility());
        const bool standardFlooding = isStandardFlooding(methodOrThrow(k.method));
        RenderSettings settings = hardSettings;
        settings.method = std::string(k.method);
        settings.options.set(floodPassesOption().flag, 4);
        settings.options.set("--no-object-id-fix", !k.fixes);
        settings.options.set("--no-midpoint-fix", !k.fixes);
        settings.options.set("--occluder-points", k.edges ? "edge" : "centre");
        EyeSoftSettings eyeSettings;
        eyeSettings.objectIdFix = eyeSettings.midpointFix = k.fixes;
        Renderer r(shaders, s.scene, settings);
        r.resize(k.width, k.height);
        r.render(s.camera);
        ASSERT_NE(r.flood(), nullptr);
        const FloodFrame& out = *r.flood();
        ASSERT_NE(out.eyeCells, nullptr);
        EXPECT_EQ(out.passes, 4);
        EXPECT_EQ(out.standardFlooding, standardFlooding);
        EXPECT_EQ(out.objectIdFix, k.fixes);
        EXPECT_EQ(out.midpointFix, k.fixes);
        const EyeImage image = readEyeImage(out);

        // Phase 2: the flag is the hard method's shadow test; in-shadow pixels know their
        // occluder (a receiver of the shadow map) and, with the fix, its object.
        const ReceiverGrid receivers{128, 128, readVec4(r.decodedShadowReceivers())};
        const float threshold = silhouetteThreshold(s.scene.bounds.radius());
        std::size_t shadowed = 0, misplaced = 0, moved = 0;
        for (std::size_t i = 0; i < image.points.size(); ++i) {
            const glm::vec4& p = image.points[i];
            if (p.w < 0.0f) continue;
            ASSERT_EQ(hardVisibility[i], p.w == 1.0f ? 0.0f : 1.0f) << "pixel " << i;
            if (p.w != 1.0f) continue;
            ++shadowed;
            const glm::vec4& o = image.occluders[i];
            if (k.fixes) {
                EXPECT_GE(o.w, 0.0f) << "occluder without object id at pixel " << i;
            }
            // The occluder is the receiver at the pixel's texel, moved to the silhouette's edge
            // with edge points (occluderEdgePoint, the CPU reference; the texel is recomputed
            // here in double, and may differ by rounding where the point lies on a texel edge).
            const glm::dvec4 l =
                glm::dmat4(r.shadow()->lightViewProj) * glm::dvec4(p.x, p.y, p.z, 1);
            const glm::dvec4 m = glm::dmat4(r.shadow()->warp) * l;
            const int tx = std::clamp(int((m.x / m.w * 0.5 + 0.5) * 128), 0, 127);
            const int ty = std::clamp(int((m.y / m.w * 0.5 + 0.5) * 128), 0, 127);
            const glm::vec3 centre(receivers.at(tx, ty));
            const glm::vec3 expected =
                k.edges ? occluderEdgePoint(receivers, r.disk(), tx, ty, threshold) : centre;
            misplaced += expected != glm::vec3(o);
            moved += expected != centre;
        }
        EXPECT_GT(shadowed, 100u) << "the boxes must cast shadows";
        EXPECT_LE(misplaced, shadowed / 50) << "occluders are the receivers at the pixels' texels";
        if (k.edges) {
            EXPECT_GT(moved, 10u) << "silhouette texels' points move to the edge";
        }

        // Phase 3: boundary seeds, exactly.
        const BoundaryThreshold th = boundaryThreshold(eyeSettings, s.camera.proj, k.height);
        const std::vector<std::uint32_t> cells = out.eyeCells->words();
        const BoundaryWalk walk{cells, receivers, r.disk(), threshold};
        const jfa::Grid cpuSeeds =
            eyeBoundarySeeds(image, s.camera.eye, th, k.edges ? &walk : nullptr);
        const jfa::Grid gpuSeeds = readFloodGrid(out, *out.seeds);
        ASSERT_EQ(gpuSeeds, cpuSeeds) << "boundary seeds differ";
        EXPECT_GT(nonEmpty(cpuSeeds), 20u);
        expectSeedOccludersArePhaseThrees(out, cpuSeeds, image);
        std::size_t walked = 0; // seeds whose occluder phase 3 moved off phase 2's
        for (std::size_t i = 0; i < cpuSeeds.cells.size(); ++i) {
            const jfa::Cell& c = cpuSeeds.cells[i];
            walked += c.w != 0.0f && glm::vec3(c.x, c.y, c.z) != glm::vec3(image.occluders[i]);
        }
        if (k.edges) {
            EXPECT_GT(walked, 5u) << "seeds inside the occluder walk to its silhouette";
        } else {
            EXPECT_EQ(walked, 0u) << "centre points stay the thesis' texel centres";
        }

        // Phase 4: the flood, exactly (same float operations, `precise` in the shaders).
        EyeSoftCriterion criterion;
        criterion.light = r.disk();
        criterion.image = &image;
        criterion.objectIdFix = criterion.midpointFix = k.fixes;
        const jfa::Plan plan = eyeSoftPlan(4, standardFlooding, k.width, k.height);
        const jfa::Grid cpuFlood = jfa::flood(plan, cpuSeeds, criterion);
        const jfa::Grid gpuFlood = readFloodGrid(out, *out.flooded);
        std::size_t differ = 0;
        for (std::size_t i = 0; i < cpuFlood.cells.size(); ++i)
            differ += !(cpuFlood.cells[i] == gpuFlood.cells[i]);
        EXPECT_EQ(differ, 0u);
        EXPECT_GT(nonEmpty(cpuFlood), nonEmpty(cpuSeeds)) << "the flood must spread occluders";

        // Phase 5: visibility, as the frame shows it (the shading pass reads the composite
        // for exactly the surface pixels and writes 1 on background, where the CPU composite
        // is 1 too); the tolerances: expectCompositeMatches.
        const LineMap lineMap = readLineMap(*r.shadow(), r.disk());
        const std::vector<glm::vec3> planes = receiverPlanes(r.surfaces(), image);
        const CompositeEdges edges{lineMap, planes, cells};
        const FloatImage cpuVis =
            eyeSoftVisibility(image, cpuFlood, r.disk(), k.edges ? &edges : nullptr);
        const std::vector<float> frameVis = readR32F(r.visibility());
        ASSERT_EQ(frameVis.size(), cpuVis.data.size());
        const std::size_t penumbra = expectCompositeMatches(frameVis, cpuVis.data, k.edges);
        EXPECT_GT(penumbra, 50u);
        std::printf("%s%s: %zu shadowed, %zu seeds, %zu flooded, %zu penumbra pixels\n",
                    std::string(k.method).c_str(), k.fixes ? "" : " (no fixes)", shadowed,
                    nonEmpty(cpuSeeds), nonEmpty(cpuFlood), penumbra);
    }
}

// The default scene's light (radius 0.3) casts penumbrae under a pixel; as in penumbra_gltest,
// the soft-shadow tests use a larger disk.
constexpr float kTestRadius = 1.5f;

struct Frame {
    EyeImage image;         // phase 2 (empty for the hard method)
    jfa::Grid flooded;      // phase 4 (empty for the hard method)
    std::vector<float> vis; // the frame's visibility, GL row order
    FrameImages pictures;   // for goldens
    int passes = 0;         // the JFA pass count the flood used
};

// `extra`: more method options, flag and value.
using ExtraOptions = std::vector<std::pair<std::string, std::string>>;

Frame renderDefault(std::string_view method, float radius = kTestRadius, bool objectIdFix = true,
                    bool midpointFix = true, std::string_view occluderPoints = "edge",
                    const ExtraOptions& extra = {}) {
    Scene scene = loadGltf(defaultAsset());
    scene.light->radius = radius;
    const gl::ShaderLibrary& shaders = fl::test::testShaders();
    RenderSettings settings;
    settings.shadow.size = 512;
    settings.method = std::string(method);
    settings.options.set("--no-object-id-fix", !objectIdFix);
    settings.options.set("--no-midpoint-fix", !midpointFix);
    settings.options.set("--occluder-points", std::string(occluderPoints));
    for (const auto& [flag, value] : extra) settings.options.set(flag, value);
    Renderer r(shaders, scene, settings);
    r.resize(256, 256);
    r.render(makeCameraView(scene, {}, 1.0f));
    Frame f;
    if (const FloodFrame* flood = r.flood(); flood && flood->eyeCells) {
        f.image = readEyeImage(*flood);
        f.flooded = readFloodGrid(*flood, *flood->flooded);
        f.passes = flood->passes;
    }
    f.vis = readR32F(r.visibility());
    f.pictures = readFrame(r);
    return f;
}

// Band-limited flooding equals the full grid on the default view, where the penumbra bound's
// receivers' pyramid is queried near the frame's last cells. Named after the bug it reproduces:
// llvmpipe's textureSize(sampler, lod) answered the next level's size, so the pyramid query was
// clamped to half the cells, cones were cut short and flood-E lost a seed's penumbra (6 pixels).
TEST_F(JfaETest, BandEqualsFullWherePyramidQueryReachesTheLastCells) {
    Scene scene = loadGltf(defaultAsset());
    scene.light->radius = kTestRadius;
    const gl::ShaderLibrary& shaders = fl::test::testShaders();
    const auto camera = makeCameraView(scene, {}, 1.0f);
    for (const char* method : {"flood-e", "jfa-e"})
        for (const char* passes : {"3", "auto"}) {
            SCOPED_TRACE(std::string(method) + ", passes " + passes);
            RenderSettings settings;
            settings.shadow.size = 256;
            settings.method = method;
            settings.options.set(floodPassesOption().flag, std::string(passes));
            const auto runs = renderBandAndFull(shaders, scene, camera, settings, 256, 256);
            std::size_t differ = 0;
            for (std::size_t k = 0; k < runs[0].grid.cells.size(); ++k)
                differ += !(runs[0].grid.cells[k] == runs[1].grid.cells[k]);
            EXPECT_EQ(differ, 0u);
            EXPECT_GT(nonEmpty(runs[1].grid), 1000u) << "the view must have penumbrae";
            EXPECT_TRUE(runs[0].banded);
            EXPECT_LT(runs[0].activeShare, 1.0);
        }
}

TEST_F(JfaETest, ZeroLightRadiusGivesExactlyTheHardShadows) {
    const Frame hard = renderDefault("hard", 0.0f);
    for (const MethodDescriptor* d : floodingMethods(MethodSpace::Eye)) { // jfa-e, flood-e
        const Frame soft = renderDefault(d->name, 0.0f);
        EXPECT_EQ(hard.vis, soft.vis) << d->name;
        EXPECT_NO_THROW(requireFinite(soft.pictures.color, "colour"));
    }
}

TEST_F(JfaETest, SceneWithoutCastersIsLitEverywhere) {
    Scene scene = groundAndBox(3.0f, {-0.5f, 0.0f, -0.5f}, {0.5f, 1.0f, 0.5f}, {0.3f, -1, 0.2f});
    scene.instances.erase(scene.instances.begin() + 1); // only the ground is left
    scene.light->radius = 1.0f;
    const gl::ShaderLibrary& shaders = fl::test::testShaders();
    RenderSettings settings;
    settings.shadow.size = 128;
    settings.method = "jfa-e";
    Renderer r(shaders, scene, settings);
    r.resize(48, 48);
    r.render(makeCameraView(scene, {}, 1.0f));
    for (float x : readR32F(r.visibility())) ASSERT_EQ(x, 1.0f);
    ASSERT_NE(r.flood(), nullptr);
    EXPECT_EQ(nonEmpty(readFloodGrid(*r.flood(), *r.flood()->seeds)), 0u);
}

TEST_F(JfaETest, PassCountsOutsideTheRangeAreRejected) {
    EXPECT_THROW((void)eyeSoftPlan(0, false, 256, 256), std::invalid_argument);
    EXPECT_THROW((void)eyeSoftPlan(9, false, 256, 256), std::invalid_argument); // 2^9 > 256
    EXPECT_EQ(eyeSoftPlan(8, false, 256, 100).passCount(), 8);
    EXPECT_EQ(eyeSoftPlan(6, true, 256, 256).passCount(), 63);
    EXPECT_THROW((void)eyeSoftPlan(6, false, 4096, 4096), std::invalid_argument); // 2^24 pixels
}

// Holes in umbrae (thesis §5.4.2, Fig. 5.7): pixels in hard shadow that the reference
// (standard flooding, which cannot jump) leaves in umbra but that get a high intensity.
bool isHole(const Frame& method, const Frame& reference, std::size_t i) {
    return method.image.points[i].w == 1.0f && reference.vis[i] == 0.0f && method.vis[i] > 0.25f;
}
std::size_t umbraHoles(const Frame& method, const Frame& reference) {
    std::size_t holes = 0;
    for (std::size_t i = 0; i < method.vis.size(); ++i) holes += isHole(method, reference, i);
    return holes;
}

// The midpoint check samples one pixel of the path the occluder jumped over, so it is a
// heuristic: with the thesis' occluder points (texel centres) it removes every hole of the
// default view; with edge points (the default) the points differ by half a texel and two
// pixels, (185,120) and (184,121), keep an occluder seeded 6 pixels away whose midpoint accepts
// it while every path of standard flooding rejects it. Since every hard test reads the map from
// the lifted, normal-offset point (issue 41), fewer pixels of the tree's crown are hard-shadowed
// by their own crown: the view shows 13 holes without the fixes with centre points (33 before)
// and 4 with edge points, all of them self-shadowing, which no fix is for; so the fixes' effect
// is checked with centre points, and with edge points only that they leave the pair above.
TEST_F(JfaETest, JumpTooFarFixesRemoveUmbraHoles) {
    for (const char* points : {"centre", "edge"}) {
        SCOPED_TRACE(std::string("occluder points ") + points);
        const Frame reference = renderDefault("flood-e", kTestRadius, false, false, points);
        const Frame none = renderDefault("jfa-e", kTestRadius, false, false, points);
        const Frame ids = renderDefault("jfa-e", kTestRadius, true, false, points);
        const Frame mid = renderDefault("jfa-e", kTestRadius, false, true, points);
        const Frame both = renderDefault("jfa-e", kTestRadius, true, true, points);
        const std::size_t hNone = umbraHoles(none, reference), hIds = umbraHoles(ids, reference),
                          hMid = umbraHoles(mid, reference), hBoth = umbraHoles(both, reference);
        // Holes whose occluder belongs to the object that hard-shadows the pixel (self-shadowing,
        // e.g. inside the tree's crown): the object-ID fix cannot see them (the thesis: it "still
        // fails for some concave objects"). The ids come from the frame made with the fix on (the
        // id pass runs only then); the eye images are otherwise the same.
        std::size_t sameObject = 0;
        for (std::size_t i = 0; i < none.vis.size(); ++i) {
            if (!isHole(none, reference, i)) continue;
            const std::size_t seed = static_cast<std::size_t>(none.flooded.cells[i].w) - 1;
            sameObject += ids.image.occluders[i].w == ids.image.occluders[seed].w;
        }
        std::printf("%s points: umbra holes: no fixes %zu (%zu of them self-shadowing), object id "
                    "%zu, midpoint %zu, both %zu\n",
                    points, hNone, sameObject, hIds, hMid, hBoth);
        if (std::string_view(points) == "centre") {
            EXPECT_GE(hNone, 10u) << "the default view must show the jump-too-far problem";
            EXPECT_LT(hIds, hNone) << "the object-ID fix removes the holes across objects";
        }
        EXPECT_LE(hIds, sameObject) << "and leaves at most the self-shadowing ones";
        const std::size_t left = std::string_view(points) == "centre" ? 0u : 2u;
        EXPECT_LE(hMid, left) << "the midpoint check removes all but the two explained above";
        EXPECT_LE(hBoth, left);
    }
}

// JFA-E against flood-E on the default view (thesis Fig. 5.8): few pixels differ in parity
// (the thesis reports < 6.8%) and most penumbra pixels agree closely.
TEST_F(JfaETest, JfaEIsCloseToStandardFlooding) {
    const Frame jfa = renderDefault("jfa-e");
    const Frame ref = renderDefault("flood-e");
    std::size_t penumbra = 0, parity = 0, close = 0;
    for (std::size_t i = 0; i < jfa.vis.size(); ++i) {
        const float a = jfa.vis[i], b = ref.vis[i];
        const bool pa = a > 0.0f && a < 1.0f;
        const bool pb = b > 0.0f && b < 1.0f;
        parity += pa != pb;
        if (pb) {
            ++penumbra;
            close += std::abs(a - b) < 0.05f;
        }
    }
    const double n = static_cast<double>(jfa.vis.size());
    std::printf("penumbra pixels %zu, parity differs %.3f%%, |dI| < 0.05 for %.2f%%\n", penumbra,
                100.0 * static_cast<double>(parity) / n,
                100.0 * static_cast<double>(close) / static_cast<double>(penumbra));
    ASSERT_GT(penumbra, 500u) << "the default view must show penumbrae";
    EXPECT_LT(static_cast<double>(parity) / n, 0.068);
    EXPECT_GE(static_cast<double>(close) / static_cast<double>(penumbra), 0.9);
}

// The measured auto count (issue 30 item 2, EyeFloodReach.h): the histogram and pass rule.
TEST_F(JfaETest, TravelHistogramAndPassRule) {
    jfa::Grid g(10, 6, jfa::kEmptyCell);
    const auto seedAt = [&](int x, int y) { return static_cast<float>(y * g.width + x + 1); };
    g.at(2, 1) = {0, 0, 0, seedAt(2, 1)}; // a seed: 0
    g.at(9, 1) = {0, 0, 0, seedAt(2, 1)}; // 7 along x
    g.at(3, 5) = {0, 0, 0, seedAt(2, 1)}; // 4 along y beats 1 along x
    const std::vector<std::uint32_t> bins = floodTravel(g);
    ASSERT_EQ(bins.size(), std::size_t(kTravelBins));
    EXPECT_EQ(bins[0], 1u);
    EXPECT_EQ(bins[4], 1u);
    EXPECT_EQ(bins[7], 1u);
    EXPECT_EQ(maxTravel(bins), 7);
    EXPECT_EQ(maxTravel(std::vector<std::uint32_t>(kTravelBins, 0u)), -1);
    // Coarse travel d stands for up to 4(d + 1) - 1 frame pixels.
    EXPECT_EQ(passesForTravel(7, 4, 9), 5);  // 31
    EXPECT_EQ(passesForTravel(8, 4, 9), 6);  // 35
    EXPECT_EQ(passesForTravel(-1, 4, 9), 1); // no cells
    EXPECT_EQ(passesForTravel(500, 4, 9), 9);
    EXPECT_EQ(coarseSize(75, 61, 4), glm::ivec2(19, 16));
    const BoundaryThreshold th = coarseThreshold({1.0f, 2.0f}, 4);
    EXPECT_EQ(th.absolute2, 16.0f);
    EXPECT_EQ(th.relative2, 32.0f);
}

// The coarse flood on the GPU (the boundary pass reading the frame's cells coarsely,
// jfae_criterion.glsl, jfae_travel.comp.glsl) against its CPU reference, bin for bin (the same
// float operations as the phases, which PhasesMatchTheCpuReference compares exactly).
TEST_F(JfaETest, CoarseFloodTravelMatchesTheCpuReference) {
    const gl::ShaderLibrary& shaders = fl::test::testShaders();
    EyeFloodEstimator estimator(shaders);
    struct Case {
        bool defaultScene;
        int width, height;
        bool fixes;
    };
    for (const Case& k : {Case{false, 64, 64, true}, Case{false, 75, 61, true},
                          Case{false, 64, 64, false}, Case{true, 256, 256, true}}) {
        SCOPED_TRACE(std::string(k.defaultScene ? "default scene " : "box ") +
                     std::to_string(k.width) + "x" + std::to_string(k.height) +
                     (k.fixes ? "" : ", fixes off"));
        SceneView s = k.defaultScene ? SceneView{loadGltf(defaultAsset()), {}} : spotLitBox();
        if (k.defaultScene) {
            s.scene.light->radius = kTestRadius;
            s.camera = makeCameraView(s.scene, {}, 1.0f);
        }
        RenderSettings settings;
        settings.shadow.size = k.defaultScene ? 512 : 128;
        settings.method = "jfa-e";
        settings.options.set("--no-object-id-fix", !k.fixes);
        settings.options.set("--no-midpoint-fix", !k.fixes);
        Renderer r(shaders, s.scene, settings);
        r.resize(k.width, k.height);
        r.render(s.camera);
        ASSERT_NE(r.flood(), nullptr);
        CoarseFloodSettings cs;
        cs.eye = s.camera.eye;
        cs.threshold = boundaryThreshold(EyeSoftSettings{}, s.camera.proj, k.height);
        cs.light = r.disk();
        cs.objectIdFix = cs.midpointFix = k.fixes;
        const std::vector<std::uint32_t> gpu = estimator.travel(*r.flood()->eyeCells, cs);
        const std::vector<std::uint32_t> cpu = coarseFloodTravel(readEyeImage(*r.flood()), cs);
        EXPECT_EQ(gpu, cpu);
        std::uint64_t cells = 0;
        for (std::uint32_t n : cpu) cells += n;
        EXPECT_GT(cells, 10u) << "the coarse flood must hold cells";
        EXPECT_GT(maxTravel(cpu), 0) << "and spread them";
        std::printf("%s %dx%d: %llu coarse cells, farthest %d coarse pixels\n",
                    k.defaultScene ? "default" : "box", k.width, k.height,
                    static_cast<unsigned long long>(cells), maxTravel(cpu));
    }
}

// Issue 30 item 2: auto's count is the fewest that give the full-pass picture, or one more. The
// full-pass picture is log2(256) = 8 passes; a count "gives" it when the RMS difference of the
// visibilities over the surface pixels is at most 0.001, which bounds how far its RMSE against
// any truth can be from the full-pass RMSE (the triangle inequality), the tolerance.
// Counted by running every count; two light radii, so that the answer is not one number.
TEST_F(JfaETest, AutoCountIsTheFewestThatGiveTheFullPassPicture) {
    for (const float radius : {kTestRadius, 0.5f}) {
        SCOPED_TRACE("radius " + std::to_string(radius));
        const auto render = [&](const std::string& passes, const std::string& rule) {
            return renderDefault("jfa-e", radius, true, true, "edge",
                                 {{"--jfa-passes", passes}, {"--auto-passes", rule}});
        };
        const Frame full = render("8", "measured");
        const auto rmsToFull = [&](const Frame& f) {
            double sum = 0.0;
            std::size_t n = 0;
            for (std::size_t i = 0; i < f.vis.size(); ++i) {
                if (full.image.points[i].w < 0.0f) continue;
                const double d = double(f.vis[i]) - double(full.vis[i]);
                sum += d * d;
                ++n;
            }
            return std::sqrt(sum / double(std::max<std::size_t>(n, 1)));
        };
        int fewest = 8;
        for (int k = 7; k >= 1; --k) { // the smallest k from which every count up gives it
            if (rmsToFull(render(std::to_string(k), "measured")) > 0.001) break;
            fewest = k;
        }
        const Frame measured = render("auto", "measured");
        const Frame geometric = render("auto", "geometric");
        std::printf("radius %.2f: fewest %d, measured auto %d (RMS to full %.5f), geometric "
                    "auto %d\n",
                    double(radius), fewest, measured.passes, rmsToFull(measured), geometric.passes);
        EXPECT_GE(measured.passes, fewest);
        EXPECT_LE(measured.passes, fewest + 1);
        EXPECT_LE(rmsToFull(measured), 0.001);
        EXPECT_LT(measured.passes, geometric.passes) << "the bound over-floods this view";
    }
}

// Image regression at 256² with a 512² map; tolerances as for the other soft-shadow goldens
// (penumbra_gltest.cpp): another driver may round shading and flip comparisons at float
// precision.
TEST_F(JfaETest, Goldens) {
    for (const MethodDescriptor* d : floodingMethods(MethodSpace::Eye)) { // jfa-e, flood-e
        const Frame f = renderDefault(d->name);
        expectFrameMatchesGoldens(f.pictures, "default_256_" + std::string(d->name));
    }
}

// Per-phase times at 512² (512² map) for JFA-E and flood-E (hard and JFA-L beside them), the
// thesis' Fig. 5.10(b) set-up scaled to this machine; not run by default (seconds on llvmpipe). Run
// with
// --gtest_also_run_disabled_tests --gtest_filter=*Timing*.
TEST_F(JfaETest, DISABLED_Timing512) {
    Scene scene = loadGltf(defaultAsset());
    scene.light->radius = kTestRadius;
    const gl::ShaderLibrary& shaders = fl::test::testShaders();
    for (std::string_view m : {"hard", "jfa-l", "jfa-e", "flood-e"}) {
        RenderSettings settings;
        settings.shadow.size = 512;
        settings.method = std::string(m);
        settings.timing = gl::TimingMode::Finish;
        Renderer r(shaders, scene, settings);
        r.resize(512, 512);
        const auto camera = makeCameraView(scene, {}, 1.0f);
        r.render(camera); // warm-up: llvmpipe compiles shader variants on first use
        constexpr int kFrames = 3;
        std::vector<gl::PassTime> sum;
        double frame = 0.0;
        for (int f = 0; f < kFrames; ++f) {
            r.render(camera);
            frame += r.timer().frameMs();
            const std::vector<gl::PassTime>& passes = r.timer().passes();
            if (sum.empty())
                sum = passes;
            else
                for (std::size_t i = 0; i < passes.size(); ++i) sum[i].ms += passes[i].ms;
        }
        std::printf("%s:", std::string(m).c_str());
        for (const gl::PassTime& p : sum)
            std::printf(" %s %.1f ms;", p.name.c_str(), p.ms / kFrames);
        std::printf(" frame %.1f ms\n", frame / kFrames);
    }
}

} // namespace
} // namespace fl::test
