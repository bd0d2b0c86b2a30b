// Animation on the GPU against the CPU (issue 15, item 2): skinning and morph targets posed in
// the vertex stages (shaders/pose.glsl) cast the shadow that the same pose, baked on the CPU
// (scene/Pose.h posedVertices), casts for the ray caster; the ray-traced truth follows
// the pose; the motion target follows an animated object.

#include "GlTest.h"
#include "TestScenes.h"

#include <renderer/Renderer.h>
#include <renderer/run/Capture.h>
#include <scene/Pose.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <string>

namespace fl::test {
namespace {

class PoseTest : public GlTest {};

/// Ground, a bar of two joints whose upper joint swings 90 degrees about z over one second, and a
/// floating quad whose morph target lifts one edge (and moves it out) as its weight goes from 0
/// to 1.
Scene animatedScene() {
    Scene s = groundAndBox(3.0f, {-0.2f, 0.0f, -0.2f}, {0.2f, 1.0f, 0.2f}, {0.3f, -1, 0.2f});
    s.light->type = Light::Type::Point;
    s.light->position = {-1.0f, 6.0f, 0.5f};
    s.light->radius = 0.0f;
    // Nodes: 0 ground, 1 bar (mesh node), 2 lower joint, 3 upper joint (child of 2), 4 quad.
    s.nodes.resize(5);
    s.nodes[3].parent = 2;
    s.nodes[3].translation = {0.0f, 0.5f, 0.0f};
    s.nodes[4].translation = {1.2f, 1.5f, 0.0f};
    Mesh& bar = s.meshes[1];
    for (const glm::vec3& p : bar.positions) {
        bar.joints.push_back(p.y > 0.5f ? glm::uvec4(1, 0, 0, 0) : glm::uvec4(0, 0, 0, 0));
        bar.weights.emplace_back(1.0f, 0.0f, 0.0f, 0.0f);
    }
    s.skins.push_back(
        {"bar", {2, 3}, {glm::mat4(1.0f), glm::translate(glm::mat4(1.0f), {0.0f, -0.5f, 0.0f})}});
    s.instances[0].node = 0;
    s.instances[1].node = 1;
    s.instances[1].skin = 0;
    Mesh quad;
    quad.name = "morph quad";
    quad.positions = {{-0.5f, 0, -0.5f}, {0.5f, 0, -0.5f}, {0.5f, 0, 0.5f}, {-0.5f, 0, 0.5f}};
    quad.normals.assign(4, glm::vec3(0, 1, 0));
    quad.indices = {0, 2, 1, 0, 3, 2};
    quad.material = 0;
    quad.targets.push_back({{{0, 0, 0}, {0.6f, 0.8f, 0}, {0.6f, 0.8f, 0}, {0, 0, 0}}, {}});
    quad.morphWeights = {0.0f};
    s.meshes.push_back(quad);
    s.instances.push_back(
        {2, glm::translate(glm::mat4(1.0f), s.nodes[4].translation), 3, "quad", 4, -1});
    Animation a;
    a.name = "swing";
    const glm::quat quarter = glm::angleAxis(glm::radians(-90.0f), glm::vec3(0, 0, 1));
    a.samplers.push_back({Animation::Interpolation::Linear,
                          {0.0f, 1.0f},
                          {0, 0, 0, 1, quarter.x, quarter.y, quarter.z, quarter.w},
                          4});
    a.samplers.push_back({Animation::Interpolation::Linear, {0.0f, 1.0f}, {0.0f, 1.0f}, 1});
    a.channels.push_back({3, Animation::Path::Rotation, 0});
    a.channels.push_back({4, Animation::Path::Weights, 1});
    a.duration = 1.0f;
    s.animations.push_back(a);
    s.computeBounds();
    return s;
}

/// `s` in `pose` as a static scene: every instance's posed vertices in world space.
Scene baked(const Scene& s, const Pose& pose) {
    Scene out = s;
    out.nodes.clear();
    out.skins.clear();
    out.animations.clear();
    out.meshes.clear();
    for (std::size_t i = 0; i < s.instances.size(); ++i) {
        Mesh m = s.meshes[static_cast<std::size_t>(s.instances[i].mesh)];
        posedVertices(s, pose, i, m.positions, &m.normals);
        m.joints.clear();
        m.weights.clear();
        m.targets.clear();
        m.morphWeights.clear();
        out.meshes.push_back(m);
        out.instances[i] = {static_cast<int>(i),
                            glm::mat4(1.0f),
                            s.instances[i].objectId,
                            s.instances[i].nodeName,
                            -1,
                            -1};
    }
    out.computeBounds();
    return out;
}

CameraView overhead(const Scene& scene) {
    return lookAtCamera(scene, {0.5f, 9.0f, 0.01f}, {0.5f, 0.0f, 0.0f}, 40.0f);
}

TEST_F(PoseTest, GpuPoseCastsTheShadowOfTheCpuPose) {
    const Scene scene = animatedScene();
    const CameraView camera = overhead(scene);
    const gl::ShaderLibrary& shaders = fl::test::testShaders();
    const int size = 128;
    for (double t : {0.0, 0.5, 1.0}) {
        const Scene cpu = baked(scene, evaluatePose(scene, std::vector<int>{0}, t));
        for (const char* method : {"hard", "raytrace"}) {
            SCOPED_TRACE(std::string(method) + " at t = " + std::to_string(t));
            RenderSettings settings;
            settings.method = method;
            settings.shadow.size = 1024;
            settings.options.set("--raytrace-samples", 1);
            Renderer renderer(shaders, scene, settings);
            renderer.setTime(t);
            renderer.resize(size, size);
            renderer.render(camera);
            const FrameImages frame = readFrame(renderer);
            int compared = 0, shadowed = 0, mismatched = 0;
            for (float x = -2.5f; x <= 2.5f; x += 0.1f)
                for (float z = -2.5f; z <= 2.5f; z += 0.1f) {
                    const glm::vec3 p{x, 0.0f, z};
                    const float ref = rayCastVisibility(cpu, *cpu.light, p);
                    // Away from shadow edges, and ground the bar or the quad does not hide
                    // from the camera, both within a margin (a pixel's footprint).
                    Light eye;
                    eye.position = {0.5f, 9.0f, 0.01f};
                    bool skip = rayCastVisibility(cpu, eye, p) == 0.0f;
                    for (glm::vec3 d : {glm::vec3(0.05f, 0, 0), glm::vec3(-0.05f, 0, 0),
                                        glm::vec3(0, 0, 0.05f), glm::vec3(0, 0, -0.05f)})
                        skip = skip || rayCastVisibility(cpu, *cpu.light, p + d) != ref ||
                               rayCastVisibility(cpu, eye, p + d) == 0.0f;
                    int px = 0, py = 0;
                    if (skip || !project(camera, size, size, p, px, py)) continue;
                    ++compared;
                    shadowed += ref == 0.0f ? 1 : 0;
                    if ((frame.visibility.at(px, py, 0) >= 0.5f) != (ref == 1.0f)) ++mismatched;
                }
            EXPECT_GT(shadowed, 20);
            EXPECT_EQ(mismatched, 0) << "of " << compared;
        }
    }
}

TEST_F(PoseTest, PosesDifferOverTheClip) {
    // The test above means something only if the shadow moves: the baked poses differ.
    const Scene scene = animatedScene();
    std::vector<glm::vec3> a, b;
    posedVertices(scene, evaluatePose(scene, std::vector<int>{0}, 0.0), 1, a);
    posedVertices(scene, evaluatePose(scene, std::vector<int>{0}, 1.0), 1, b);
    float moved = 0.0f;
    for (std::size_t i = 0; i < a.size(); ++i) moved = std::max(moved, glm::length(a[i] - b[i]));
    EXPECT_GT(moved, 0.3f);
    posedVertices(scene, evaluatePose(scene, std::vector<int>{0}, 1.0), 2, b);
    EXPECT_NEAR(b[1].y, 1.5f + 0.8f, 1e-5f) << "the morph target at weight 1";
}

TEST_F(PoseTest, MotionTargetFollowsTheAnimatedObject) {
    // The camera stands still; the quad's lifted edge moves between the two times: its pixels'
    // motion points to where the same surface point was.
    const Scene scene = animatedScene();
    const CameraView camera = overhead(scene);
    const gl::ShaderLibrary& shaders = fl::test::testShaders();
    Renderer renderer(shaders, scene, {});
    renderer.setTime(1.0, 0.5);
    renderer.resize(128, 128);
    renderer.render(camera, camera);
    const FrameImages frame = readFrame(renderer);
    // The quad's corner (0.5, 0, 0.5) of vertex 2, in world space, at both times.
    const Pose now = evaluatePose(scene, std::vector<int>{0}, 1.0);
    const Pose before = evaluatePose(scene, std::vector<int>{0}, 0.5);
    std::vector<glm::vec3> pNow, pBefore;
    posedVertices(scene, now, 2, pNow);
    posedVertices(scene, before, 2, pBefore);
    // A point a little inside the lifted edge (between vertices 1 and 2, towards the centre).
    const glm::vec3 inside = 0.45f * (pNow[1] + pNow[2]) + 0.1f * (pNow[0] + pNow[3]);
    const glm::vec3 wasAt = 0.45f * (pBefore[1] + pBefore[2]) + 0.1f * (pBefore[0] + pBefore[3]);
    int px = 0, py = 0, qx = 0, qy = 0;
    ASSERT_TRUE(project(camera, 128, 128, inside, px, py));
    ASSERT_TRUE(project(camera, 128, 128, wasAt, qx, qy));
    EXPECT_NEAR(frame.motion.at(px, py, 0), static_cast<float>(qx) + 0.5f, 1.5f);
    EXPECT_NEAR(frame.motion.at(px, py, 1), static_cast<float>(qy) + 0.5f, 1.5f);
    EXPECT_GT(std::abs(frame.motion.at(px, py, 0) - (static_cast<float>(px) + 0.5f)) +
                  std::abs(frame.motion.at(px, py, 1) - (static_cast<float>(py) + 0.5f)),
              0.5f)
        << "the point moved on screen";
}

} // namespace
} // namespace fl::test
