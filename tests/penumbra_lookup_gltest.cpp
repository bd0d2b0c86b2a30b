// JFA-L's lookup with --penumbra both (light_visibility.frag.glsl with soft_penumbra.glsl, both
// passes: the occluder's point, then its edges where the first pass marked) against its CPU twin
// (renderer/soft/PenumbraLookup.h) on the frame the GPU drew.

#include "GlTest.h"
#include "TestMethods.h"
#include "TestScenes.h"

#include <gpu/ReadBack.h>
#include <renderer/Renderer.h>
#include <renderer/io/TextureImage.h>
#include <renderer/soft/OccluderEdge.h>
#include <renderer/soft/PenumbraLookup.h>

#include <cmath>
#include <cstdio>

namespace fl::test {
namespace {

class PenumbraLookupTest : public GlTest {};

// The CPU follows the GPU operation for operation, but GLSL's atan, cos, sin, acos and divisions
// are not correctly rounded and the normal offset's point is computed on either side in its own
// rounding: the edges' fits agree to ~1e-5 of a texel and the shares to 5e-4, and a map test (the
// hard test, a covered texel of the window, a fused sample) at a rounding boundary may decide the
// other way. We allow that on 1% of the penumbra pixels, as JfaETest.PhasesMatchTheCpuReference
// does (llvmpipe: none). Without the borrowed occluders the CPU differs on 11 of 254.
TEST_F(PenumbraLookupTest, BothPassesMatchTheCpuReference) {
    // A box on a ground plane under a large disk light: inner and outer penumbrae on the ground,
    // the box's own sides in its shadow (the self-shadowed rule).
    const SceneView s = spotLitBox();
    const gl::ShaderLibrary& shaders = fl::test::testShaders();
    struct Case {
        std::string_view method;
        int width, height; // not a power of two too: the pixel's texel from its position alone
    };
    for (const Case& k : {Case{"jfa-l", 64, 64}, Case{"flood-l", 64, 64}, Case{"jfa-l", 75, 61}}) {
        SCOPED_TRACE(std::string(k.method) + " " + std::to_string(k.width) + "x" +
                     std::to_string(k.height));
        RenderSettings settings;
        settings.shadow.size = 128;
        settings.method = std::string(k.method);
        settings.options.set("--penumbra", "both");
        Renderer r(shaders, s.scene, settings);
        r.resize(k.width, k.height);
        r.render(s.camera);
        ASSERT_NE(r.flood(), nullptr);
        ASSERT_NE(r.shadow(), nullptr);
        const FloatImage gpu = readTexture(r.visibility(), 1);
        const FloatImage cpu = penumbraLookupVisibility(
            readLookupSurfaces(r.surfaces()), readLineMap(*r.shadow(), r.disk()),
            gl::readTexels<float>(*r.flood()->flooded, GL_RED, GL_FLOAT),
            silhouetteThreshold(s.scene.bounds.radius()));
        ASSERT_EQ(gpu.data.size(), cpu.data.size());
        std::size_t receivers = 0, penumbra = 0, apart = 0;
        float worst = 0.0f;
        const FloatImage points = r.surfaces().positions().read();
        for (std::size_t i = 0; i < cpu.data.size(); ++i) {
            if (points.data[4 * i + 3] == 0.0f) {
                EXPECT_EQ(gpu.data[i], 1.0f) << "background pixel " << i;
                continue;
            }
            ++receivers;
            const float c = cpu.data[i];
            penumbra += c > 0.0f && c < 1.0f;
            const float d = std::abs(gpu.data[i] - c);
            worst = std::max(worst, d);
            apart += d > 5e-4f;
        }
        std::printf("%zu receivers, %zu penumbra, %zu beyond 5e-4, worst %.3g\n", receivers,
                    penumbra, apart, double(worst));
        EXPECT_GT(penumbra, 100u) << "the view must show penumbrae";
        EXPECT_LE(apart, penumbra / 100);
    }
}

} // namespace
} // namespace fl::test
