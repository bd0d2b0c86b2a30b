// Image regression: the default scene rendered headless (EGL) at 256², compared with goldens.
// Regenerate after an intended change with:
//   FLOODLIGHT_UPDATE_GOLDENS=1 ./build/release/tests/golden_gltest   (see tests/golden/README.md)

#include "GlTest.h"
#include "ImageCompare.h"
#include "TestPaths.h"

#include <renderer/Renderer.h>
#include <renderer/run/Capture.h>
#include <scene/GltfLoader.h>
#include <scene/SceneGenerator.h>

#include <fstream>

namespace fl::test {
namespace {

class GoldenTest : public GlTest {};

FrameImages renderDefault(int size, int shadowMap,
                          ShadowMapProvider provider = ShadowMapProvider::Uniform) {
    const Scene scene = loadGltf(defaultAsset());
    const gl::ShaderLibrary& shaders = fl::test::testShaders();
    RenderSettings settings;
    settings.shadow.size = shadowMap;
    settings.shadow.provider = provider;
    Renderer r(shaders, scene, settings);
    r.resize(size, size);
    r.render(makeCameraView(scene, {}, 1.0f));
    return readFrame(r);
}

// Tolerances of the visibility goldens; the reasons are given at DefaultSceneVisibility.
Tolerance visibilityTolerance() {
    return {.maxAbs = 255, .meanAbs = 255 * 0.01, .pixelThreshold = 127, .maxPercentOver = 1.0};
}

void expectMatchesGolden(const ByteImage& image, const std::string& name, const Tolerance& tol) {
    const CompareResult c = compareWithGolden(image, name, tol);
    std::printf("%s: %s\n", name.c_str(), c.report.c_str());
    EXPECT_TRUE(c.pass) << c.report;
}

// The committed asset must be exactly what assets/README.md says made it.
TEST(DefaultAsset, IsTheGeneratorOutput) {
    const auto fresh = outputDir("asset") / "default.glb";
    writeGlb(generateScene({6320, 1}), fresh);
    EXPECT_TRUE(fileContents(fresh) == fileContents(defaultAsset()))
        << "assets/default.glb differs from `floodlight make-scene --triangles 6320 --seed 1`; "
           "regenerate it (assets/README.md) and the goldens (tests/golden/README.md)";
}

TEST_F(GoldenTest, DefaultSceneColour) {
    const FrameImages f = renderDefault(256, 1024);
    // Tolerances: on the machine that made the golden (Mesa llvmpipe) the render is bit-exact.
    // Another driver or Mesa version rounds shading maths differently (a few 8-bit steps) and
    // may flip shadow-map comparisons that are within float precision of the surface, each flip
    // a full light/shadow difference at one pixel. So: any single pixel may differ completely,
    // but the mean difference stays under 1.5 steps and under 1% of pixels differ by more
    // than 16 steps. A moved shadow, camera or light breaks both limits by far.
    expectMatchesGolden(toSrgb8(f.color), "default_256_colour", frameTolerance());
}

TEST_F(GoldenTest, DefaultSceneVisibility) {
    const FrameImages f = renderDefault(256, 1024);
    // Hard-shadow visibility is 0 or 1 per pixel, so any difference is a whole step; allow the
    // same 1% of pixels (comparisons at float precision on another driver) and nothing more.
    expectMatchesGolden(visibilityToGrey(f.visibility), "default_256_visibility",
                        visibilityTolerance());
    // The picture must actually contain shadow and light, or the golden proves nothing.
    size_t shadowed = 0;
    for (float v : f.visibility.data) shadowed += v < 0.5f;
    const double share = double(shadowed) / double(f.visibility.data.size());
    EXPECT_GT(share, 0.03);
    EXPECT_LT(share, 0.6);
}

// TSM hard shadows, same view and tolerances as the uniform goldens above (the same reasons
// apply). A 512² map keeps the difference from the uniform map visible near the viewer.
TEST_F(GoldenTest, DefaultSceneTsmColour) {
    const FrameImages f = renderDefault(256, 512, ShadowMapProvider::Tsm);
    expectMatchesGolden(toSrgb8(f.color), "default_256_tsm_colour", frameTolerance());
}

TEST_F(GoldenTest, DefaultSceneTsmVisibility) {
    const FrameImages f = renderDefault(256, 512, ShadowMapProvider::Tsm);
    expectMatchesGolden(visibilityToGrey(f.visibility), "default_256_tsm_visibility",
                        visibilityTolerance());
    // TSM must differ from the uniform map at the same resolution, or the provider is not in use.
    const FrameImages u = renderDefault(256, 512, ShadowMapProvider::Uniform);
    std::size_t differing = 0;
    for (std::size_t i = 0; i < f.visibility.data.size(); ++i)
        differing += (f.visibility.data[i] < 0.5f) != (u.visibility.data[i] < 0.5f);
    EXPECT_GT(differing, 100u);
}

} // namespace
} // namespace fl::test
