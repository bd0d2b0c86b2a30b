// Soft shadows on bad or extreme input (issue 5): a huge disk light and a light inside an
// object give finite visibility in [0, 1] from every method, with the answers that can be known.

#include "GlTest.h"
#include "TestScenes.h"

#include <renderer/Renderer.h>
#include <renderer/run/Capture.h>

#include <cmath>
#include <iostream>

namespace fl::test {
namespace {

class SoftBadInputTest : public GlTest {};

// The soft methods under test: the flooding ones of the table (JFA-L/E and their
// standard-flooding references).
std::vector<const MethodDescriptor*> softMethods() {
    std::vector<const MethodDescriptor*> out;
    for (const MethodDescriptor& m : methodTable())
        if (m.floods) out.push_back(&m);
    return out;
}

// A unit box on a 6 x 6 ground, a spot light above it looking down, a camera from the side.
Scene spotScene(glm::vec3 lightPosition, float radius) {
    Scene scene = groundAndBox(3.0f, {-0.5f, 0.0f, -0.5f}, {0.5f, 1.0f, 0.5f}, {0.3f, -1, 0.2f});
    scene.light->type = Light::Type::Spot;
    scene.light->position = lightPosition;
    scene.light->direction = glm::normalize(glm::vec3(0.1f, -1.0f, 0.05f));
    scene.light->radius = radius;
    return scene;
}

CameraView sideCamera(const Scene& scene) {
    CameraSpec spec;
    spec.kind = CameraSpec::Kind::LookAt;
    spec.eye = {3.0f, 3.5f, 4.5f};
    spec.target = {0.0f, 0.3f, 0.0f};
    return makeCameraView(scene, spec, 1.0f);
}

FrameImages renderFrame(const Scene& scene, std::string_view method) {
    return test::renderFrame(scene, sideCamera(scene), method, 256, 64);
}

FloatImage renderVisibility(const Scene& scene, std::string_view method) {
    return renderFrame(scene, method).visibility;
}

// JFA-L/flood-L with --penumbra outer: the thesis' lit-side-only form (the default is both).
FrameImages renderOuter(const Scene& scene, std::string_view method) {
    RenderSettings settings;
    settings.shadow.size = 256;
    settings.method = std::string(method);
    settings.options.set("--penumbra", "outer");
    Renderer r(testShaders(), scene, settings);
    r.resize(64, 64);
    r.render(sideCamera(scene));
    return readFrame(r);
}

std::size_t zerosOf(const FloatImage& v) {
    std::size_t zeros = 0;
    for (float x : v.data) zeros += x == 0.0f;
    return zeros;
}

void expectFiniteUnit(const FloatImage& v, std::string_view what) {
    for (float x : v.data) {
        ASSERT_TRUE(std::isfinite(x)) << what;
        ASSERT_GE(x, 0.0f) << what;
        ASSERT_LE(x, 1.0f) << what;
    }
}

// A disk far larger than the scene: every occluder's ray reaches it, so every pixel the flood
// covers gets an intensity, and the composites must stay finite and in [0, 1]. What cannot be
// kept is the width of the penumbra (wider than the 63-texel reach): the flooded region ends
// there. JFA-L's thesis form (--penumbra outer) keeps the hard-shadow pixels at 0 (thesis §5.3.1:
// "hard-shadowed -> 0"), so its count of zeros equals the hard method's; with both halves (the
// default) the umbra side within the flood's reach sees half of so large a disk, so it has fewer.
TEST_F(SoftBadInputTest, HugeLightRadiusStaysFiniteAndKeepsTheUmbra) {
    const Scene huge = spotScene({0.3f, 6.0f, 0.2f}, 1.0e4f);
    const FloatImage hard = renderVisibility(huge, "hard");
    std::size_t hardZeros = 0;
    for (float x : hard.data) hardZeros += x == 0.0f;
    ASSERT_GT(hardZeros, 0u) << "the test view must see the box's hard shadow";
    for (const MethodDescriptor* d : softMethods()) {
        const std::string_view m = d->name;
        const FloatImage v = renderVisibility(huge, m);
        expectFiniteUnit(v, m);
        if (d->space == MethodSpace::Light) { // JFA-L, flood-L
            EXPECT_LT(zerosOf(v), hardZeros) << m << ": both halves light the umbra side";
            const FloatImage outer = renderOuter(huge, m).visibility;
            expectFiniteUnit(outer, m);
            EXPECT_EQ(zerosOf(outer), hardZeros) << m << " --penumbra outer";
        }
        // A disk of radius 1e4 around a point 6 units above a unit box: any lit pixel near the
        // box sees the box cover part of the disk, so some pixels must be partly lit.
        std::size_t partial = 0;
        for (float x : v.data) partial += x > 0.0f && x < 1.0f;
        EXPECT_GT(partial, 0u) << m;
    }
}

// The light inside the box: every ray from outside to the light crosses the box, so every
// light-facing surface outside it is in the umbra. JFA-L's and flood-L's thesis form (--penumbra
// outer) must give exactly the hard shadows (no silhouette exists in a map that sees only the
// box's inside).
// Known limitations, measured and bounded rather than hidden:
// - JFA-E: the box's faces pass the depth test (each is its own nearest surface to the light)
//   while facing away from it, and the thesis' boundary test (a shadowed pixel with a lit
//   neighbour) has no facing condition, so the ground pixels touching the box's base become
//   boundary seeds and get a penumbra: 32 of the 4,096 pixels' colours differ (one pixel wide
//   along the base). A facing condition removes them, but it also removes the default scene's
//   umbra holes that jfae_gltest shows the jump-too-far fixes remove, so it is not applied.
// - JFA-L with both halves (the default): the ground along the box's base is the umbra side of
//   the walls' edge where they meet the ground, so its inner half lights it (up to 0.46): 40
//   pixels in a band one or two pixels wide along the base at 64².
// The bound for both is that band: fewer than 48 pixels (the base's visible outline is about 40
// pixels long at 64²).
TEST_F(SoftBadInputTest, LightInsideAnObjectShadowsEverythingOutside) {
    const Scene inside = spotScene({0.0f, 0.5f, 0.0f}, 0.2f);
    const FrameImages hard = renderFrame(inside, "hard");
    expectFiniteUnit(hard.visibility, "hard");
    std::size_t zeros = 0;
    for (float x : hard.visibility.data) zeros += x == 0.0f;
    EXPECT_GT(zeros, hard.visibility.data.size() / 8) << "the ground in view must be shadowed";
    for (const MethodDescriptor* d : softMethods()) {
        const std::string_view m = d->name;
        const FrameImages f = renderFrame(inside, m);
        expectFiniteUnit(f.visibility, m);
        if (d->space == MethodSpace::Light) { // JFA-L, flood-L
            const FrameImages outer = renderOuter(inside, m);
            EXPECT_EQ(outer.visibility.data, hard.visibility.data) << m << " --penumbra outer";
            EXPECT_EQ(outer.color.data, hard.color.data) << m << " --penumbra outer";
        }
        std::size_t differ = 0;
        for (std::size_t i = 0; i < f.color.data.size(); i += 4)
            differ += f.color.data[i] != hard.color.data[i] ||
                      f.color.data[i + 1] != hard.color.data[i + 1] ||
                      f.color.data[i + 2] != hard.color.data[i + 2];
        EXPECT_LT(differ, 48u) << m;
        std::cout << m << " colour differs at " << differ << " pixels\n";
    }
}

} // namespace
} // namespace fl::test
