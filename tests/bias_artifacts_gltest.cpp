// Acne and peter-panning (renderer/metrics/BiasArtifacts.h) on scenes made to show each: a box
// standing on the ground under a low spot light, hard shadows against the ray-traced truth. No
// depth bias gives acne on the lit ground, a depth bias far too large detaches the shadow from
// the box's foot (peter-panning), and the default bias shows little of either.

#include "GlTest.h"
#include "TestScenes.h"

#include <renderer/Renderer.h>
#include <renderer/io/TextureImage.h>
#include <renderer/metrics/BiasArtifacts.h>
#include <renderer/soft/ShadowRayInputs.h>

#include <glm/geometric.hpp>

#include <cstdio>

namespace fl::test {
namespace {

class BiasArtifactsTest : public GlTest {};

// The box on the ground under a small spot light low on its side (grazing light: acne shows at
// small slopes' bias first), seen from above the shadow's side.
SceneView lowSpotOnBox() {
    Scene scene = groundAndBox(3.0f, {-0.5f, 0.0f, -0.5f}, {0.5f, 1.0f, 0.5f}, {1, -0.4f, 0.2f});
    scene.light->type = Light::Type::Spot;
    scene.light->position = {-4.0f, 2.0f, -0.8f};
    scene.light->direction = glm::normalize(glm::vec3(4.0f, -2.0f, 0.8f));
    scene.light->radius = 0.05f;
    return {scene, lookAtCamera(scene, {2.5f, 3.5f, 3.0f}, {0.8f, 0.0f, 0.2f}, 50.0f)};
}

struct Figures {
    BiasArtifactCounts counts;
    std::size_t contactPixels = 0;
};

// Hard shadows with the given depth bias, against the ray-traced truth of the same frame.
Figures hardWithBias(const SceneView& v, float slope, float constant) {
    constexpr int kSize = 128;
    RenderSettings truthSettings;
    truthSettings.method = "raytrace";
    truthSettings.options.set("--raytrace-samples", 64);
    Renderer truth(testShaders(), v.scene, truthSettings);
    truth.resize(kSize, kSize);
    truth.render(v.camera);
    const FloatImage exact = readTexture(truth.visibility(), 1);
    const BiasMasks masks =
        biasMasks(surfaceGeometry(truth.surfaces(), v.camera), truth.disk().center);
    RenderSettings s;
    s.method = "hard";
    s.shadow.size = 512;
    s.shadow.slopeBias = slope;
    s.shadow.constantBias = constant;
    Renderer hard(testShaders(), v.scene, s);
    hard.resize(kSize, kSize);
    hard.render(v.camera);
    Figures f;
    f.counts = biasArtifacts(readTexture(hard.visibility(), 1), exact, masks);
    for (float c : masks.contact.data) f.contactPixels += c > 0.5f;
    return f;
}

TEST_F(BiasArtifactsTest, TooLittleBiasGivesAcneTooMuchGivesPeterPanning) {
    const SceneView v = lowSpotOnBox();
    const Figures none = hardWithBias(v, 0.0f, 0.0f);
    const Figures standard =
        hardWithBias(v, ShadowMapSettings{}.slopeBias, ShadowMapSettings{}.constantBias);
    // Far too much: 100 times the default slope bias, and a constant bias of about 0.1 in the
    // light's post-perspective depth (2e6 float steps of 6e-8 at depth 0.5).
    const Figures huge = hardWithBias(v, 200.0f, 2e6f);
    std::printf("acne: none %.4f default %.4f huge %.4f (of %zu); peter-panning: none %.4f "
                "default %.4f huge %.4f (of %zu; %zu contact pixels)\n",
                none.counts.acneShare(), standard.counts.acneShare(), huge.counts.acneShare(),
                standard.counts.acneCandidates, none.counts.peterPanningShare(),
                standard.counts.peterPanningShare(), huge.counts.peterPanningShare(),
                standard.counts.peterPanningCandidates, standard.contactPixels);
    ASSERT_GT(standard.counts.acneCandidates, 2000u) << "lit ground in view";
    ASSERT_GT(standard.counts.peterPanningCandidates, 100u) << "the box's foot in its shadow";
    ASSERT_GT(standard.contactPixels, 50u);
    // Measured on llvmpipe: acne 0.50 without bias (a depth compared with itself is a coin
    // toss on any driver), 0.0014 at the default, 0 when huge; peter-panning 1.0 with the huge
    // bias (the shadow starts well past the foot), 0.035 at the default, 0.018 without bias (the
    // few umbra pixels a 512^2 map's texel lights next to the foot). The bounds leave a factor
    // of 2.5 or more to a driver that rounds otherwise.
    EXPECT_GT(none.counts.acneShare(), 0.2);
    EXPECT_LT(standard.counts.acneShare(), 0.02);
    EXPECT_LE(huge.counts.acneShare(), standard.counts.acneShare());
    EXPECT_GT(huge.counts.peterPanningShare(), 0.5);
    EXPECT_LT(standard.counts.peterPanningShare(), 0.15);
    EXPECT_LT(none.counts.peterPanningShare(), 0.15);
}

} // namespace
} // namespace fl::test
