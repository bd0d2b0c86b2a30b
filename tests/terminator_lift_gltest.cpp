// The surfaces pass's lift (shaders/terminator.glsl, surfaces.geom.glsl) against its CPU twin
// (renderer/passes/TerminatorLift.h): a smooth-shaded triangle lit at a grazing angle, every
// pixel's lift recomputed from its decoded position, the triangle's corners and normals.

#include "GlTest.h"
#include "TestScenes.h"

#include <io/ImageIO.h>
#include <renderer/Renderer.h>
#include <renderer/io/TextureImage.h>
#include <renderer/passes/SurfaceDecode.h>
#include <renderer/passes/TerminatorLift.h>

namespace fl::test {
namespace {

class TerminatorLiftTest : public GlTest {};

// One triangle whose vertex normals lean outward by 20-30 degrees (a facet of a coarse curved
// body), under a point light nearly in its plane.
Scene grazedFacet() {
    Scene s;
    s.source = "test:grazedFacet";
    Mesh m;
    m.name = "facet";
    m.positions = {{-1.0f, 0.0f, -1.0f}, {1.0f, 0.0f, -1.0f}, {0.0f, 0.0f, 1.0f}};
    m.normals = {glm::normalize(glm::vec3(-0.4f, 1.0f, -0.3f)),
                 glm::normalize(glm::vec3(0.5f, 1.0f, -0.3f)),
                 glm::normalize(glm::vec3(0.0f, 1.0f, 0.55f))};
    m.indices = {0, 2, 1}; // counter-clockwise from above
    m.material = 0;
    s.meshes = {m};
    s.materials = {{"facet", glm::vec4(0.8f), -1, false}};
    s.instances = {{0, glm::mat4(1.0f), 1, "facet"}};
    Light l;
    l.type = Light::Type::Point;
    l.position = {-6.0f, 0.3f, 0.2f};
    l.direction = glm::normalize(-l.position);
    l.radius = 0.1f;
    s.light = l;
    s.computeBounds();
    return s;
}

TEST_F(TerminatorLiftTest, TheLiftTargetIsTheCpuTwinsAtEveryPixel) {
    const Scene scene = grazedFacet();
    const CameraView camera = lookAtCamera(scene, {0.2f, 3.0f, 0.5f}, {0.0f, 0.0f, -0.3f}, 50.0f);
    RenderSettings settings;
    settings.method = "hard";
    Renderer r(testShaders(), scene, settings);
    r.resize(64, 64);
    r.render(camera);
    const SurfacesPass::Outputs out = r.surfaces();
    const FloatImage position = out.positions().read(); // row 0 at the top
    const FloatImage lift = readTexture(out.lift, 1);
    const FloatImage shading = out.readNormals(SurfacesPass::Outputs::Normal::Shading);
    const Mesh& m = scene.meshes[0];
    const std::array<glm::vec3, 3> corner{m.positions[0], m.positions[2], m.positions[1]};
    const std::array<glm::vec3, 3> normal{m.normals[0], m.normals[2], m.normals[1]};
    const surface::TangentPlanes t = surface::terminatorPlanes(corner, normal);
    ASSERT_NE(t.front, glm::vec3(0.0f)) << "a curved facet";
    const glm::vec3 faceNormal = t.front;
    std::size_t covered = 0, lifted = 0;
    float worst = 0.0f, largest = 0.0f;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            if (position.at(x, y, 3) == 0.0f) continue;
            ++covered;
            const glm::vec3 p(position.at(x, y, 0), position.at(x, y, 1), position.at(x, y, 2));
            // Barycentric weights of p (on the triangle, up to the depth's rounding).
            const glm::vec3 e0 = corner[1] - corner[0], e1 = corner[2] - corner[0],
                            d = p - corner[0];
            const float d00 = glm::dot(e0, e0), d01 = glm::dot(e0, e1), d11 = glm::dot(e1, e1);
            const float d20 = glm::dot(d, e0), d21 = glm::dot(d, e1);
            const float den = d00 * d11 - d01 * d01;
            const float v = (d11 * d20 - d01 * d21) / den, w = (d00 * d21 - d01 * d20) / den;
            const glm::vec3 bary(1.0f - v - w, v, w);
            const glm::vec3 n(shading.at(x, y, 0), shading.at(x, y, 1), shading.at(x, y, 2));
            const glm::vec3 plane = glm::dot(faceNormal, n) < 0.0f ? -faceNormal : faceNormal;
            const glm::vec3 l = glm::normalize(scene.light->position - p);
            const float cpu = surface::terminatorLift(p, bary, t, n, plane, l);
            const float gpu = lift.at(x, y, 0);
            lifted += gpu > 0.0f;
            largest = std::max(largest, cpu);
            worst = std::max(worst, std::abs(gpu - cpu));
        }
    std::printf("%zu pixels, %zu lifted, largest lift %.4g, worst difference %.3g\n", covered,
                lifted, double(largest), double(worst));
    ASSERT_GT(covered, 500u);
    EXPECT_GT(lifted, covered / 4) << "the light grazes the facet: the lift applies";
    // Positions decode from a float depth and the GPU interpolates the weights and the normal in
    // its own way: the lifts agree to 1e-3 of the largest (~1e-4 of the facet's size).
    EXPECT_LE(worst, 1e-3f * largest);
}

} // namespace
} // namespace fl::test
