// Hard shadow mapping against the CPU ray-cast reference, and the renderer's outputs.

#include "GlTest.h"
#include "TestPaths.h"
#include "TestScenes.h"

#include <gpu/LiveObjects.h>
#include <renderer/Renderer.h>
#include <renderer/run/Capture.h>
#include <renderer/run/FrameRunner.h>
#include <scene/GltfLoader.h>

#include <glm/gtc/matrix_transform.hpp>

#include <map>

namespace fl::test {
namespace {

class RendererTest : public GlTest {};

TEST_F(RendererTest, HardShadowMatchesRayCastReference) {
    // A box lit from the upper left casts its shadow to the right onto the ground; a camera
    // above sees most of that shadow beside the box.
    const Scene scene = groundAndBox(4.0f, {-1, 1, -1}, {1, 2, 1}, {1, -1, 0});
    const gl::ShaderLibrary& shaders = fl::test::testShaders();
    RenderSettings settings;
    settings.shadow.size = 512;
    Renderer renderer(shaders, scene, settings);
    const int w = 128, h = 128;
    renderer.resize(w, h);
    CameraSpec spec;
    spec.kind = CameraSpec::Kind::LookAt;
    spec.eye = {0.5f, 12.0f, 0.01f};
    spec.target = {0.5f, 0.0f, 0.0f};
    spec.yfovDegrees = 45.0f;
    const CameraView cam = makeCameraView(scene, spec, 1.0f);
    renderer.render(cam);
    const FrameImages frame = readFrame(renderer);
    writeFrame(frame, outputDir("renderer"), "hard_shadow_box"); // for a look when it fails

    // Ground points on a grid, skipping those within a shadow-map texel or two of the shadow
    // edge (where a 512² map legitimately rounds either way) and those hidden by the box.
    const float texel = 8.0f * 1.5f / 512.0f; // light frustum spans ~ the 8 m ground diagonal
    int compared = 0, shadowed = 0, mismatched = 0;
    for (float gx = -3.5f; gx <= 3.5f; gx += 0.25f) {
        for (float gz = -3.5f; gz <= 3.5f; gz += 0.25f) {
            const glm::vec3 p{gx, 0.0f, gz};
            if (gx > -1.3f && gx < 1.3f && gz > -1.3f && gz < 1.3f) continue; // under/behind box
            const float ref = rayCastVisibility(scene, *scene.light, p);
            bool nearEdge = false;
            for (glm::vec3 d : {glm::vec3(texel * 2, 0, 0), glm::vec3(-texel * 2, 0, 0),
                                glm::vec3(0, 0, texel * 2), glm::vec3(0, 0, -texel * 2)})
                if (rayCastVisibility(scene, *scene.light, p + d) != ref) nearEdge = true;
            if (nearEdge) continue;
            int x = 0, y = 0;
            if (!project(cam, w, h, p, x, y)) continue;
            const float gpu = frame.visibility.at(x, y, 0);
            ++compared;
            if (ref == 0.0f) ++shadowed;
            if (gpu != ref) {
                ++mismatched;
                ADD_FAILURE() << "ground (" << gx << ", " << gz << ") pixel (" << x << ", " << y
                              << "): GPU " << gpu << ", ray cast " << ref;
            }
        }
    }
    EXPECT_GT(compared, 200);
    EXPECT_GT(shadowed, 10) << "the test must see shadowed ground to mean anything";
    EXPECT_EQ(mismatched, 0);
}

TEST_F(RendererTest, OutputsAreFiniteAndBackgroundIsLit) {
    const Scene scene =
        groundAndBox(2.0f, {-0.5f, 0.5f, -0.5f}, {0.5f, 1.0f, 0.5f}, {0.3f, -1, 0.2f});
    const gl::ShaderLibrary& shaders = fl::test::testShaders();
    Renderer renderer(shaders, scene, {});
    renderer.resize(64, 48);
    renderer.render(makeCameraView(scene, {}, 64.0f / 48.0f));
    const FrameImages frame = readFrame(renderer);
    EXPECT_NO_THROW(requireFinite(frame.color, "colour"));
    EXPECT_NO_THROW(requireFinite(frame.visibility, "visibility"));
    EXPECT_EQ(frame.color.width, 64);
    EXPECT_EQ(frame.color.height, 48);
    EXPECT_EQ(frame.color.at(0, 0, 3), 0.0f) << "top-left corner should be sky (alpha 0)";
    EXPECT_EQ(frame.visibility.at(0, 0, 0), 1.0f);
    // The timed passes are the frame's steps for its method (hard: one phase), in frame order.
    const std::vector<std::string_view> phases = framePhases(renderer.method());
    ASSERT_EQ(phases.size(), 4u); // shadow map, surfaces, hard shadows, shading
    ASSERT_EQ(renderer.timer().passes().size(), phases.size());
    for (std::size_t i = 0; i < phases.size(); ++i)
        EXPECT_EQ(renderer.timer().passes()[i].name, phases[i]) << i;
    EXPECT_EQ(renderer.timer().passes()[0].name, "shadow map");
    EXPECT_GT(renderer.timer().frameMs(), 0.0);
}

// The receiver mask (what the capture metrics count) is exactly the visible surfaces facing the
// light: the ground seen from above is a receiver when the light shines on it from above, and
// not when the light is below it; the sky never is.
TEST_F(RendererTest, ReceiversAreTheVisibleSurfacesFacingTheLight) {
    const gl::ShaderLibrary& shaders = fl::test::testShaders();
    CameraSpec spec;
    spec.kind = CameraSpec::Kind::LookAt;
    spec.eye = {0.0f, 6.0f, 6.0f};
    spec.target = {0.0f, 0.0f, 0.0f};
    spec.yfovDegrees = 50.0f;
    for (const float up : {-1.0f, 1.0f}) {
        const Scene scene =
            groundAndBox(3.0f, {-0.5f, 0.0f, -0.5f}, {0.5f, 1.0f, 0.5f}, {0.3f, up, 0.2f});
        Renderer renderer(shaders, scene, {});
        const int w = 96, h = 96;
        renderer.resize(w, h);
        const CameraView cam = makeCameraView(scene, spec, 1.0f);
        renderer.render(cam);
        const FrameImages frame = readFrame(renderer);
        ASSERT_EQ(frame.receivers.width, w);
        ASSERT_EQ(frame.receivers.channels, 1);
        int sky = 0, ground = 0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                if (frame.color.at(x, y, 3) == 0.0f) {
                    ++sky;
                    EXPECT_EQ(frame.receivers.at(x, y, 0), 0.0f) << x << ", " << y;
                }
        const float expected = up < 0.0f ? 1.0f : 0.0f; // light travelling down lights the top
        for (float gx = -2.5f; gx <= 2.5f; gx += 0.5f)
            for (float gz = 1.0f; gz <= 2.5f; gz += 0.5f) { // in front of the box, seen
                int x = 0, y = 0;
                if (!project(cam, w, h, {gx, 0.0f, gz}, x, y)) continue;
                ++ground;
                EXPECT_EQ(frame.receivers.at(x, y, 0), expected)
                    << "ground (" << gx << ", " << gz << "), light y " << up;
            }
        EXPECT_GT(sky, 0) << "the view must include sky for the test to mean anything";
        EXPECT_GT(ground, 20);
    }
}

// One geometry pass from the eye per frame (the surfaces pass), whatever the method: every
// method of the table reads the surfaces instead of drawing the scene again.
TEST_F(RendererTest, EveryMethodDrawsTheSceneFromTheEyeOnce) {
    const Scene scene =
        loadGltf(std::filesystem::path(FLOODLIGHT_SOURCE_DIR) / "assets" / "default.glb");
    const gl::ShaderLibrary& shaders = fl::test::testShaders();
    const CameraView camera = makeCameraView(scene, {}, 1.0f);
    int methods = 0;
    for (const MethodDescriptor& m : methodTable()) {
        RenderSettings settings;
        settings.shadow.size = 256;
        settings.method = std::string(m.name);
        // Cheap ground truth: its light-space maps are not eye draws either way.
        settings.options.set("--reference-samples", 4);
        settings.options.set("--reference-map-size", 256);
        Renderer renderer(shaders, scene, settings);
        renderer.resize(64, 64);
        renderer.render(camera);
        EXPECT_EQ(renderer.eyeGeometryDraws(), 1) << m.name;
        renderer.render(camera); // and again on the next frame
        EXPECT_EQ(renderer.eyeGeometryDraws(), 1) << m.name << ", second frame";
        ++methods;
    }
    EXPECT_GE(methods, 8) << "the table lists every method";
}

TEST_F(RendererTest, ResizeRejectsZeroSize) {
    const Scene scene = groundAndBox(2.0f, {-0.5f, 0.5f, -0.5f}, {0.5f, 1.0f, 0.5f}, {0, -1, 0});
    const gl::ShaderLibrary& shaders = fl::test::testShaders();
    Renderer renderer(shaders, scene, {});
    EXPECT_THROW(renderer.resize(0, 10), std::invalid_argument);
    EXPECT_THROW(renderer.render(CameraView{}), std::logic_error);
}

// The bytes each phase writes (floodlight_bench's "written", issue 28) are the formats of its
// targets times their texels: worked out here by hand for a hard frame and for floods over the
// whole grid with a fixed pass count, where every pass writes every cell.
TEST_F(RendererTest, BytesWrittenAreTheTargetsFormatsTimesTheirTexels) {
    EXPECT_EQ(gl::texelBytes(GL_RGBA32F), 16);
    EXPECT_EQ(gl::texelBytes(GL_R8), 1);
    EXPECT_THROW((void)gl::texelBytes(GL_RGB10_A2), std::invalid_argument);
    const Scene scene = groundAndBox(4.0f, {-1, 1, -1}, {1, 2, 1}, {1, -1, 0});
    const gl::ShaderLibrary& shaders = fl::test::testShaders();
    const auto bytesOf = [](const Renderer& r) {
        std::map<std::string, std::int64_t> m;
        for (const auto& [name, bytes] : writtenBytes(r)) m[name] = bytes;
        return m;
    };
    const std::int64_t w = 64, h = 48, map = 256, pixels = w * h, texels = map * map;
    const CameraView camera = makeCameraView(scene, {}, float(w) / float(h));
    RenderSettings settings;
    settings.shadow.size = int(map);
    {
        Renderer r(shaders, scene, settings);
        r.resize(int(w), int(h));
        r.render(camera);
        const std::map<std::string, std::int64_t> b = bytesOf(r);
        EXPECT_EQ(b.at("shadow map"), texels * 4); // DEPTH32F
        // DEPTH32F, RGBA16_SNORM normals, RGBA8 base colour, R8 receivers, R32F lift: 21 bytes
        // a pixel.
        EXPECT_EQ(b.at("surfaces"), pixels * (4 + 8 + 4 + 1 + 4));
        EXPECT_EQ(b.at("hard shadows"), pixels * 4); // R32F
        EXPECT_EQ(b.at("shading"), pixels * 8);      // RGBA16F
        EXPECT_EQ(r.timer().frameBytes(), texels * 4 + pixels * (21 + 4 + 8));
        r.render(camera, camera); // with the previous camera: the motion target too
        EXPECT_EQ(bytesOf(r).at("surfaces"), pixels * (21 + 16));
    }
    for (const char* method : {"jfa-l", "jfa-e"}) {
        RenderSettings s = settings;
        s.method = method;
        s.options.set(floodRegionOption().flag, "full");
        s.options.set(floodPassesOption().flag, 3);
        Renderer r(shaders, scene, s);
        r.resize(int(w), int(h));
        r.render(camera);
        const std::map<std::string, std::int64_t> b = bytesOf(r);
        const bool light = std::string(method) == "jfa-l";
        EXPECT_EQ(b.at("shadow map"), texels * (4 + 4)) << method; // + the receiver target (R32F)
        // Both methods' cells are packed in one R32F texel (a seed's tag / index + 1).
        EXPECT_EQ(b.at("flood"), 3 * (light ? texels : pixels) * 4) << method;
    }
}

// Issue 28: a renderer whose frames do not ask for the shadow-map diagnostics holds no target of
// theirs (their RGBA32F output is 16 bytes a pixel): one that asks holds exactly two textures
// more (the output and the previous map's copy), and a resize reallocates the output at the new
// size rather than adding one.
TEST_F(RendererTest, DiagnosticsTargetsExistOnlyInFramesThatAskForThem) {
    const Scene scene = groundAndBox(4.0f, {-1, 1, -1}, {1, 2, 1}, {1, -1, 0});
    const gl::ShaderLibrary& shaders = fl::test::testShaders();
    const CameraView camera = makeCameraView(scene, {}, 64.0f / 48.0f);
    const auto textures = [] {
        return gl::countLiveObjects().live[std::size_t(gl::ObjectKind::Texture)];
    };
    RenderSettings settings;
    settings.shadow.size = 256;
    int without = 0;
    {
        Renderer r(shaders, scene, settings);
        r.resize(64, 48);
        r.render(camera);
        EXPECT_EQ(r.diagnostics(), nullptr);
        without = textures();
    }
    settings.diagnostics = true;
    Renderer r(shaders, scene, settings);
    r.resize(64, 48);
    r.render(camera);
    ASSERT_NE(r.diagnostics(), nullptr);
    EXPECT_EQ(textures(), without + 2); // the output and the copy of the map
    r.resize(80, 40);
    r.render(camera);
    ASSERT_NE(r.diagnostics(), nullptr);
    EXPECT_EQ(r.diagnostics()->width(), 80);
    EXPECT_EQ(r.diagnostics()->height(), 40);
    EXPECT_EQ(textures(), without + 2);
}

// A frame or shadow map beyond the driver's largest texture is one message naming both sizes,
// with the limit read from GL (llvmpipe: 16384; other drivers differ), before any allocation.
TEST_F(RendererTest, SizesBeyondTheDriversLargestTextureNameBothSizes) {
    const Scene scene = groundAndBox(2.0f, {-0.5f, 0.5f, -0.5f}, {0.5f, 1.0f, 0.5f}, {0, -1, 0});
    const int limit = gl::maxTextureSize();
    ASSERT_GT(limit, 0);
    const std::string max = std::to_string(limit) + "x" + std::to_string(limit);
    Renderer renderer(fl::test::testShaders(), scene, {});
    try {
        renderer.resize(limit + 1, 16);
        ADD_FAILURE() << "a frame wider than the largest texture was accepted";
    } catch (const std::invalid_argument& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("frame " + std::to_string(limit + 1) + "x16"), std::string::npos) << m;
        EXPECT_NE(m.find(max), std::string::npos) << m;
    }
    renderer.resize(16, 16); // the renderer is still usable
    RenderSettings s = renderer.settings();
    s.shadow.size = 2 * limit;
    renderer.setSettings(s);
    try {
        renderer.render(makeCameraView(scene, {}, 1.0f));
        ADD_FAILURE() << "a shadow map larger than the largest texture was accepted";
    } catch (const std::invalid_argument& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("shadow map " + std::to_string(2 * limit)), std::string::npos) << m;
        EXPECT_NE(m.find(max), std::string::npos) << m;
    }
}

} // namespace
} // namespace fl::test
