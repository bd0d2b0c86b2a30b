// The shapes of public real models that the soft-shadow methods used to get wrong (issue 41;
// bench/real_models.sh measures the models themselves), as small scenes scored against the
// ray-traced truth (`raytrace`, the exact visibility of the drawn triangles):
//  - a comb of thin plates (an engine's fins): its solid umbra, which JFA-L's umbra side lit
//    through the plates' own silhouette edges (one edge per point), and JFA-E too;
//  - a box under a small light, whose penumbra is a few map texels wide: JFA-E's comb;
//  - a coarse smooth-shaded sphere: the map methods' terminator teeth, where a point of a facet
//    turned slightly from the light lies behind its neighbour's edge in the map.
// A failure writes the frames' visibility next to the truth's under tests/output/real_models/;
// FLOODLIGHT_KEEP_FRAMES=1 writes every frame there, and each scene as sceneN.glb (N in test
// order) for `floodlight render --scene`.

#include "GlTest.h"
#include "TestPaths.h"
#include "TestScenes.h"

#include <io/ImageIO.h>
#include <renderer/Renderer.h>
#include <renderer/metrics/Metrics.h>
#include <renderer/run/Capture.h>
#include <scene/SceneGenerator.h>

#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstdio>
#include <string>

namespace fl::test {
namespace {

class RealModelShadowsTest : public GlTest {};

constexpr int kSize = 128;      // frame pixels per side
constexpr int kMapSize = 512;   // shadow map texels per side
constexpr int kTruthRays = 256; // the truth's rays per pixel

// A ground quad (y = 0, [-half, half]^2) and `parts` (each its own object), under a spot light
// at `light` aimed at `target` with a disk of `radius`.
Scene groundWith(float half, std::vector<Mesh> parts, glm::vec3 light, glm::vec3 target,
                 float radius) {
    Scene s = groundAndBox(half, {-0.1f, 0.0f, -0.1f}, {0.1f, 0.1f, 0.1f}, {0.0f, -1.0f, 0.0f});
    s.meshes.resize(1); // the ground alone; its material 0
    s.instances.resize(1);
    for (Mesh& m : parts) {
        m.material = 1;
        s.meshes.push_back(std::move(m));
        const int mesh = static_cast<int>(s.meshes.size()) - 1;
        s.instances.push_back(
            {mesh, glm::mat4(1.0f), static_cast<std::uint32_t>(mesh + 1), "part"});
    }
    s.light->type = Light::Type::Spot;
    s.light->position = light;
    s.light->direction = glm::normalize(target - light);
    s.light->radius = radius;
    s.computeBounds();
    return s;
}

// A UV sphere of `segments` x `rings` quads, smooth normals (the vertex's direction from the
// centre): the coarse, smooth-shaded curved body of a real model.
Mesh sphere(glm::vec3 centre, float radius, int segments, int rings) {
    Mesh m;
    m.name = "sphere";
    for (int j = 0; j <= rings; ++j)
        for (int i = 0; i <= segments; ++i) {
            const float theta = glm::pi<float>() * float(j) / float(rings);
            const float phi = glm::two_pi<float>() * float(i) / float(segments);
            const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                              std::sin(theta) * std::sin(phi));
            m.positions.push_back(centre + radius * n);
            m.normals.push_back(n);
        }
    const auto at = [&](int i, int j) { return std::uint32_t(j * (segments + 1) + i); };
    for (int j = 0; j < rings; ++j)
        for (int i = 0; i < segments; ++i) {
            const std::uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1),
                                d = at(i, j + 1);
            // Counter-clockwise seen from outside, as glTF's front faces.
            if (j > 0) m.indices.insert(m.indices.end(), {a, b, c});
            if (j + 1 < rings) m.indices.insert(m.indices.end(), {a, c, d});
        }
    return m;
}

struct Scored {
    FrameImages frame;
    ShadowLeaks leaks;                 // leak and dark (renderer/metrics/Metrics.h)
    FrameMetrics error;                // RMSE, over the truth's penumbra too
    std::vector<float> penumbraErrors; // |method - truth| over the truth's penumbra
    [[nodiscard]] double penumbraMedian() const {
        std::vector<float> e = penumbraErrors;
        if (e.empty()) return 0.0;
        std::nth_element(e.begin(), e.begin() + std::ptrdiff_t(e.size() / 2), e.end());
        return e[e.size() / 2];
    }
};

FrameImages render(const SceneView& v, std::string_view method, int mapSize = kMapSize) {
    if (std::getenv("FLOODLIGHT_KEEP_FRAMES") && method == "raytrace") {
        static int n = 0;
        writeGlb(v.scene, outputDir("real_models") / ("scene" + std::to_string(n++) + ".glb"));
    }
    RenderSettings settings;
    settings.shadow.size = mapSize;
    settings.method = std::string(method);
    if (method == "raytrace") settings.options.set("--raytrace-samples", kTruthRays);
    Renderer r(testShaders(), v.scene, settings);
    r.resize(kSize, kSize);
    r.render(v.camera);
    return readFrame(r);
}

// The method's frame against the truth's over the truth's receivers, with the metrics that
// bench/real_models_bench reports: leak and dark (shadowLeaks), the penumbra's RMSE, and here
// also the median |error| over the truth's penumbra (its classes: classifyVisibility).
Scored score(const SceneView& v, std::string_view method, const FrameImages& truth,
             const std::string& label, int mapSize = kMapSize) {
    Scored s{render(v, method, mapSize), {}, {}, {}};
    s.leaks = shadowLeaks(s.frame.visibility, truth.visibility, truth.receivers);
    s.error = compareWithReference(s.frame.visibility, truth.visibility, truth.receivers);
    const std::vector<float>& t = truth.visibility.data;
    const std::vector<float>& m = s.frame.visibility.data;
    for (std::size_t i = 0; i < t.size(); ++i)
        if (isReceiver(truth.receivers, i) && classifyVisibility(t[i]) == ShadowClass::Penumbra)
            s.penumbraErrors.push_back(std::abs(m[i] - t[i]));
    if (std::getenv("FLOODLIGHT_KEEP_FRAMES")) {
        const std::filesystem::path dir = outputDir("real_models");
        std::filesystem::create_directories(dir);
        writePng(dir / (label + "_" + std::string(method) + ".png"), toSrgb8(s.frame.visibility));
        writePng(dir / (label + "_truth.png"), toSrgb8(truth.visibility));
        writePng(dir / (label + "_receivers.png"), toSrgb8(truth.receivers));
    }
    std::printf("%s %s: %zu receivers, leak %.2f%% of %zu, dark %.2f%% of %zu, penumbra RMSE "
                "%.4f, median |error| %.4f over %zu\n",
                label.c_str(), std::string(method).c_str(), s.error.pixels, 100.0 * s.leaks.leak,
                s.leaks.umbra, 100.0 * s.leaks.dark, s.leaks.lit, s.error.rmsePenumbra,
                s.penumbraMedian(), s.error.penumbraPixels);
    return s;
}

// Writes the method's and the truth's visibility for a failed expectation.
void keep(const Scored& s, const FrameImages& truth, const std::string& name) {
    const std::filesystem::path dir = outputDir("real_models");
    std::filesystem::create_directories(dir);
    writePng(dir / (name + ".png"), toSrgb8(s.frame.visibility));
    writePng(dir / (name + ".truth.png"), toSrgb8(truth.visibility));
    ADD_FAILURE() << "see " << (dir / (name + ".png")).string();
}

// Ten plates 0.04 thick and 0.12 apart, 0.6 tall, floating 0.3 over the ground, under a light
// tilted across them: their shadows on the ground overlap into one solid umbra, and from the
// light each plate's top edge is a silhouette against the next plate's face.
SceneView fins() {
    std::vector<Mesh> plates;
    for (int k = 0; k < 10; ++k) {
        const float x = -0.6f + 0.12f * float(k);
        plates.push_back(box({x, 0.3f, -0.8f}, {x + 0.04f, 0.9f, 0.8f}));
    }
    Scene s = groundWith(3.0f, std::move(plates), {-2.5f, 5.0f, 0.5f}, {0.3f, 0.0f, 0.0f}, 0.6f);
    return {s, lookAtCamera(s, {2.8f, 3.2f, 2.4f}, {0.6f, 0.0f, 0.0f}, 50.0f)};
}

TEST_F(RealModelShadowsTest, NoLightThroughTheSolidUmbraOfACombOfFins) {
    const SceneView v = fins();
    const FrameImages truth = render(v, "raytrace");
    for (const char* method : {"jfa-l", "jfa-e"}) {
        const Scored s = score(v, method, truth, "fins");
        ASSERT_GT(s.leaks.umbra, 500u) << "the fins must cast a solid umbra in view";
        // The bound on every real model: at most 0.5% of the umbra lit by > 0.3.
        // Before the edges and the fused occluders JFA-L lit 8.4% of the engine's.
        EXPECT_LE(s.leaks.leak, 0.005);
        if (s.leaks.leak > 0.005) keep(s, truth, std::string("fins_") + method);
    }
}

TEST_F(RealModelShadowsTest, ANarrowPenumbraIsARampNotAComb) {
    // The unit box under a light of radius 0.08 six units up: on the ground its penumbra is a
    // few map texels wide.
    Scene s = groundWith(3.0f, {box({-0.5f, 0.0f, -0.5f}, {0.5f, 1.0f, 0.5f})},
                         {-2.0f, 6.0f, -1.0f}, {0.5f, 0.0f, 0.3f}, 0.08f);
    const SceneView v{s, lookAtCamera(s, {2.5f, 3.0f, 2.5f}, {0.9f, 0.0f, 0.6f}, 30.0f)};
    const FrameImages truth = render(v, "raytrace");
    const Scored e = score(v, "jfa-e", truth, "narrow");
    ASSERT_GT(e.error.penumbraPixels, 100u);
    // A comb puts every other penumbra pixel off by a step: the thesis' points (and the edge
    // points before the fitted edges) gave a median |error| of 0.20 here, the fitted edges 0.06
    // (the truth's 256 rays alone scatter by 0.03). The median, not the RMSE: at the shadow's
    // corners, where two edges meet in one window, the fit is rougher, and a few corner pixels
    // would decide an RMSE.
    EXPECT_LE(e.penumbraMedian(), 0.1);
    if (e.penumbraMedian() > 0.1) keep(e, truth, "narrow_jfa-e");
}

// Named after what the real-model benchmark showed once the light's frustum held only the model:
// where the map is finer than the frame, a boundary pixel's own texel lies several texels inside
// the occluder, the flood took the edge for that much further in, and the penumbra's inner half
// (inside the hard shadow) stayed black. Phase 3 now walks each seed's occluder to the silhouette.
TEST_F(RealModelShadowsTest, AMapFinerThanTheFrameKeepsTheInnerPenumbra) {
    Scene s = groundWith(3.0f, {box({-0.5f, 0.0f, -0.5f}, {0.5f, 1.0f, 0.5f})},
                         {-2.0f, 6.0f, -1.0f}, {0.5f, 0.0f, 0.3f}, 0.2f);
    const SceneView v{s, lookAtCamera(s, {2.5f, 3.0f, 2.5f}, {0.9f, 0.0f, 0.6f}, 40.0f)};
    const FrameImages truth = render(v, "raytrace");
    // 2048^2 texels over the light's view of the 6 x 6 ground: ~3 texels to a frame pixel on it.
    const Scored e = score(v, "jfa-e", truth, "inner", 2048);
    // The inner half: the truth's penumbra darker than 0.4 (inside the hard shadow) but lit
    // by at least 0.1. Black (< 0.02) there is the bug: 15 of 87 pixels without the walk, 0 with.
    std::size_t inner = 0, black = 0;
    const std::vector<float>& t = truth.visibility.data;
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (!isReceiver(truth.receivers, i) || t[i] < 0.1f || t[i] > 0.4f) continue;
        ++inner;
        black += e.frame.visibility.data[i] < 0.02f;
    }
    std::printf("inner penumbra: %zu pixels, %zu black\n", inner, black);
    ASSERT_GT(inner, 50u);
    EXPECT_LE(black, inner / 20);
    if (black > inner / 20) keep(e, truth, "inner_jfa-e");
}

TEST_F(RealModelShadowsTest, ACoarseSmoothSphereHasNoTerminatorTeeth) {
    // 16 x 8 quads with smooth normals, lit from the upper left: the terminator crosses the
    // facets at every angle.
    Scene s = groundWith(3.0f, {sphere({0.0f, 0.8f, 0.0f}, 0.8f, 16, 8)}, {-4.0f, 4.5f, 1.0f},
                         {0.0f, 0.4f, 0.0f}, 0.2f);
    const SceneView v{s, lookAtCamera(s, {0.5f, 1.6f, 3.5f}, {0.0f, 0.7f, 0.0f}, 35.0f)};
    const FrameImages truth = render(v, "raytrace");
    // Before the lift every map method but VSM darkened 0.57-1.13% of the lit receivers (PCF:
    // 0.69%, 0.77% with the lift alone: its taps against the triangle's plane).
    for (const char* method : {"hard", "pcf", "pcss", "vsm", "jfa-l", "jfa-e", "reference"}) {
        const Scored m = score(v, method, truth, "sphere");
        ASSERT_GT(m.leaks.lit, 1000u);
        // Teeth are facets darkened where the rays see the smooth surface lit.
        EXPECT_LE(m.leaks.dark, 0.005) << method;
        if (m.leaks.dark > 0.005) keep(m, truth, std::string("sphere_") + method);
    }
}

} // namespace
} // namespace fl::test
