// Alpha cut-outs (glTF alphaMode MASK and BLEND) in every pass that decides visibility: a card
// textured with a checker of alpha 1 and 0 must cast a checker shadow with every shadow method,
// as the CPU ray caster (which asks scene/AlphaCoverage) says. Without the cut-out the
// card casts a solid square and half the compared points disagree.

#include "GlTest.h"
#include "TestMethods.h"
#include "TestPaths.h"
#include "TestScenes.h"

#include <renderer/Renderer.h>
#include <renderer/run/Capture.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace fl::test {
namespace {

class AlphaCutoutTest : public GlTest, public ::testing::WithParamInterface<AlphaMode> {};

constexpr int kCells = 4; // 4 x 4 checker over the 2 x 2 card: cells 0.5 wide
// Each cell 8 texels wide, so that alpha is exactly 0 or 1 but within a texel of a cell's border.
// Where bilinear filtering mixes texels, where alpha crosses the cutoff depends on the driver's
// filtering precision (a 1-texel-per-cell checker is 0.5 along whole borders and nearly so about
// every corner), so no point is compared within the bilinear footprint (one texel) plus one texel
// of a border: 2 texels of 2/32 on the card, 4/3 as wide in its shadow on the ground, 0.17; 0.2
// leaves room for the shadow map's texels and the 0.02 light's penumbra.
constexpr int kTexelsPerCell = 8;
constexpr float kMargin = 0.2f; // points this close to a shadow edge are not compared
// The same footprint on the card, whose texels are 2/32 wide: points whose light ray crosses the
// card this close to its border are not compared.
constexpr float kEdgeTexels = 2.0f * 2.0f / (kCells * kTexelsPerCell);
static_assert(kMargin >= 2.0f * (2.0f / (kCells * kTexelsPerCell)) * (4.0f / 3.0f));

/// The card and its shadow seen from above.
CameraView overheadCamera(const Scene& scene) {
    return lookAtCamera(scene, {0.8f, 8.0f, 0.31f}, {0.8f, 0.0f, 0.3f}, 35.0f);
}

/// Settings that keep every method small enough for llvmpipe: few reference maps and rays.
RenderSettings smallSettings(std::string_view method) {
    RenderSettings s;
    s.method = std::string(method);
    s.shadow.size = 512;
    s.options.set("--reference-samples", 16);
    s.options.set("--reference-map-size", 512);
    s.options.set("--raytrace-samples", 16);
    return s;
}

TEST_P(AlphaCutoutTest, CheckerCardCastsCheckerShadowWithEveryMethod) {
    Scene scene = checkerCardOverGround(GetParam(), kCells, kTexelsPerCell);
    scene.light->radius = 0.02f; // penumbrae well inside kMargin: the checker stays sharp
    const CameraView camera = overheadCamera(scene);
    const int size = 96;
    const gl::ShaderLibrary& shaders = fl::test::testShaders();
    const std::string mode = GetParam() == AlphaMode::Mask ? "mask" : "blend";
    Light eye;
    eye.type = Light::Type::Point;
    eye.position = glm::vec3(glm::inverse(camera.view)[3]);
    for (const MethodDescriptor& method : methodTable()) {
        SCOPED_TRACE(std::string(method.name));
        Renderer renderer(shaders, scene, smallSettings(method.name));
        renderer.resize(size, size);
        renderer.render(camera);
        const FrameImages frame = readFrame(renderer);
        int compared = 0, shadowed = 0, lit = 0, mismatched = 0;
        // Ground points around the card's shadow, away from its edges
        // and not behind the card's solid cells from the eye (asked of the same ray caster,
        // with a point light at the eye).
        for (float x = -1.0f; x <= 2.7f; x += 0.05f)
            for (float z = -1.2f; z <= 1.8f; z += 0.05f) {
                const glm::vec3 p{x, 0.0f, z};
                const float ref = rayCastVisibility(scene, *scene.light, p);
                bool skip = rayCastVisibility(scene, eye, p) == 0.0f;
                for (glm::vec3 d : {glm::vec3(kMargin, 0, 0), glm::vec3(-kMargin, 0, 0),
                                    glm::vec3(0, 0, kMargin), glm::vec3(0, 0, -kMargin)})
                    skip = skip || rayCastVisibility(scene, *scene.light, p + d) != ref ||
                           rayCastVisibility(scene, eye, p + d) == 0.0f;
                // The card's own border is an alpha edge too: GL's default wrap (repeat) mixes
                // the opposite border's texels into the last half texel.
                const glm::vec3 onCard = p + (scene.light->position - p) / scene.light->position.y;
                skip = skip || std::abs(std::max(std::abs(onCard.x), std::abs(onCard.z)) - 1.0f) <
                                   kEdgeTexels;
                int px = 0, py = 0;
                if (skip || !project(camera, size, size, p, px, py)) continue;
                const float gpu = frame.visibility.at(px, py, 0);
                ++compared;
                (ref == 0.0f ? shadowed : lit) += 1;
                if ((gpu >= 0.5f) != (ref == 1.0f)) ++mismatched;
            }
        EXPECT_GT(shadowed, 30) << "the checker's solid cells must shadow ground we compare";
        EXPECT_GT(lit, 30);
        EXPECT_EQ(mismatched, 0) << "of " << compared << " ground points";
        if (mismatched > 0)
            writeFrame(frame, outputDir("alpha"), mode + "_" + std::string(method.name));
    }
}

INSTANTIATE_TEST_SUITE_P(Modes, AlphaCutoutTest,
                         ::testing::Values(AlphaMode::Mask, AlphaMode::Blend), [](const auto& p) {
                             return p.param == AlphaMode::Mask ? std::string("Mask")
                                                               : std::string("Blend");
                         });

} // namespace
} // namespace fl::test
