// The `raytrace` method through the renderer: the frame's surfaces in, visibility out, against
// the closed form of a straight edge under a disk light (TestScenes.h).

#include "GlTest.h"
#include "ImageCompare.h"
#include "TestScenes.h"

#include <renderer/Renderer.h>
#include <renderer/io/Capture.h>
#include <renderer/io/ImageIO.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <stdexcept>

#include <cmath>

namespace fl::test {
namespace {

class RayTraceMethodTest : public GlTest {};

// A thin occluder over x < 0 at height h = 1 (a zero-height box, wider than the ground), a spot
// light of radius 1 at height H = 5 straight above the edge, seen from low on the lit side so
// that the ground under the occluder is in view.
constexpr float kH = 1.0f, kLightH = 5.0f, kRadius = 1.0f;
SceneView edgeScene() {
    Scene scene = groundAndBox(4.0f, {-8.0f, kH, -8.0f}, {0.0f, kH, 8.0f}, {0, -1, 0});
    scene.light->type = Light::Type::Spot;
    scene.light->position = {0.0f, kLightH, 0.0f};
    scene.light->direction = {0.0f, -1.0f, 0.0f};
    scene.light->radius = kRadius;
    scene.light->outerConeAngle = 1.2f;
    CameraSpec spec;
    spec.kind = CameraSpec::Kind::LookAt;
    spec.eye = {2.5f, 0.6f, 0.3f};
    spec.target = {-0.3f, 0.0f, 0.0f};
    CameraView camera = makeCameraView(scene, spec, 1.0f);
    return {std::move(scene), camera};
}

// One frame of the edge scene with `method`: its error against the closed form over the ground
// pixels near the edge, and the images (the method's, and the closed form where it applies).
struct EdgeFrame {
    int ground = 0, penumbra = 0;
    double rmse = 0.0, worst = 0.0;
    FloatImage visibility, exact;
};
EdgeFrame renderEdge(const std::string& method, int mapSize) {
    const SceneView v = edgeScene();
    const gl::ShaderLibrary shaders;
    RenderSettings settings;
    settings.shadow.size = mapSize;
    settings.method = method;
    Renderer r(shaders, v.scene, settings);
    r.resize(128, 128);
    r.render(v.camera);
    const FloatImage position = readTexture(r.surfaces().position, 4);
    EdgeFrame e;
    e.visibility = readTexture(r.visibility(), 1);
    e.exact = e.visibility;
    double sum2 = 0.0;
    for (int y = 0; y < 128; ++y)
        for (int x = 0; x < 128; ++x) {
            if (position.at(x, y, 3) == 0.0f || std::abs(position.at(x, y, 1)) > 1e-4f) continue;
            const double px = position.at(x, y, 0), pz = position.at(x, y, 2);
            if (std::abs(pz) > 1.0 || std::abs(px) > 1.0) continue; // the occluder is "infinite"
            const double exact = straightEdgeVisibility(px, kH, kLightH, kRadius);
            e.exact.data[static_cast<std::size_t>(y) * 128 + static_cast<std::size_t>(x)] =
                static_cast<float>(exact);
            const double d = e.visibility.at(x, y, 0) - exact;
            sum2 += d * d;
            e.worst = std::max(e.worst, std::abs(d));
            ++e.ground;
            e.penumbra += exact > 0.0 && exact < 1.0;
        }
    e.rmse = e.ground ? std::sqrt(sum2 / e.ground) : 0.0;
    return e;
}

TEST_F(RayTraceMethodTest, EdgePenumbraMatchesTheClosedFormThroughTheRenderer) {
    const EdgeFrame e = renderEdge("raytrace", 256);
    ASSERT_GT(e.penumbra, 200) << "the view must hold the penumbra";
    ASSERT_GT(e.ground - e.penumbra, 200) << "and lit and shadowed ground";
    // N = 256 jittered strata: sigma <= sqrt(2 sqrt(N) / 4) / N = 0.011 per pixel (see
    // raytrace_test.cpp); RMSE within one sigma, every pixel within 4.5.
    const double sigma = std::sqrt(2.0 * 16.0 / 4.0) / 256.0;
    EXPECT_LT(e.rmse, sigma);
    EXPECT_LT(e.worst, 4.5 * sigma);
    if (!(e.rmse < sigma && e.worst < 4.5 * sigma))
        ADD_FAILURE() << writeVisibilityDiff(e.visibility, e.exact, "raytrace_edge");
}

TEST_F(RayTraceMethodTest, AVertexBeyondEmbreesRangeIsRefusedNamingTheNode) {
    SceneView v = edgeScene();
    // The box's node scaled so far that its vertices leave float's useful range for a BVH (the
    // GPU draws it; Embree would build a tree of infinities).
    v.scene.instances[1].world = glm::scale(glm::mat4(1.0f), glm::vec3(1e20f));
    v.scene.instances[1].nodeName = "giant";
    try {
        (void)renderFrame(v.scene, v.camera, "raytrace", 64, 16);
        ADD_FAILURE() << "accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("node 'giant'"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace fl::test
