// The shadow map's receiver target (R32F unbiased light depth) and its two decoders: the GPU's
// (shaders/shadow_map_decode.glsl, via ShadowMapPass::decodedReceivers) and the CPU twin
// (renderer/passes/ShadowMapDecode.h, via MapPositions::read). Positions are checked against
// the scene they came from, not against either decoder.

#include "GlTest.h"
#include "TestScenes.h"

#include <renderer/Renderer.h>
#include <renderer/passes/ShadowMapDecode.h>
#include <renderer/soft/PenumbraReach.h>

#include <jfa_gl/GlKernel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace fl::test {
namespace {

class ShadowMapDecodeTest : public GlTest {};

// Distance from p to the scene of spotLitBox(): the ground plane y = 0 (|x|, |z| <= 3) and the
// unit box [-0.5, 0.5] x [0, 1] x [-0.5, 0.5] on it.
float distanceToGroundAndBox(glm::vec3 p) {
    const float ground = std::abs(p.y);
    const glm::vec3 lo(-0.5f, 0.0f, -0.5f), hi(0.5f, 1.0f, 0.5f);
    const glm::vec3 outside = glm::max(glm::max(lo - p, p - hi), glm::vec3(0.0f));
    const glm::vec3 in = glm::min(p - lo, hi - p); // > 0 on every axis inside the box
    const float box =
        glm::length(outside) > 0.0f ? glm::length(outside) : std::min({in.x, in.y, in.z});
    return std::min(ground, box);
}

TEST_F(ShadowMapDecodeTest, BothDecodersGiveTheSurfaceEachTexelSeesOnEitherProvider) {
    const SceneView s = spotLitBox();
    for (ShadowMapProvider provider : {ShadowMapProvider::Uniform, ShadowMapProvider::Tsm}) {
        SCOPED_TRACE(std::string(providerName(provider)));
        RenderSettings settings;
        settings.shadow.size = 128;
        settings.shadow.provider = provider;
        settings.method = "jfa-l";
        Renderer r(fl::test::testShaders(), s.scene, settings);
        r.resize(64, 64);
        r.render(s.camera);
        const ShadowMapPass::Outputs& sm = *r.shadow();
        ASSERT_NE(sm.receivers, nullptr);
        EXPECT_EQ(sm.receivers->depth->format(), GLenum(GL_R32F)); // 4 bytes a texel
        const jfa::Grid gpu = jfa::readGrid(r.decodedShadowReceivers());
        const std::vector<glm::vec4> cpu = sm.receivers->read();
        ASSERT_EQ(gpu.cells.size(), cpu.size());
        const glm::mat4 mapViewProj = sm.mapViewProj();
        std::size_t seen = 0;
        float worstTwin = 0.0f, worstSurface = 0.0f, worstTexel = 0.0f;
        for (int y = 0; y < 128; ++y)
            for (int x = 0; x < 128; ++x) {
                const std::size_t i = std::size_t(y) * 128 + std::size_t(x);
                const jfa::Cell& g = gpu.cells[i];
                ASSERT_EQ(g.w, cpu[i].w) << "texel " << x << ", " << y; // same coverage
                if (g.w == 0.0f) continue;
                ++seen;
                const glm::vec3 p(g.x, g.y, g.z);
                worstTwin = std::max(worstTwin, glm::length(p - glm::vec3(cpu[i])));
                worstSurface = std::max(worstSurface, distanceToGroundAndBox(p));
                // Back through the map's own matrix: the centre of the texel it came from.
                const glm::vec4 c = mapViewProj * glm::vec4(p, 1.0f);
                const glm::vec2 texel = (glm::vec2(c) / c.w * 0.5f + 0.5f) * 128.0f;
                worstTexel = std::max(worstTexel, glm::length(texel - (glm::vec2(x, y) + 0.5f)));
            }
        std::printf("%s: %zu texels see the scene; twin %.3g, surface %.3g, texel %.3g\n",
                    std::string(providerName(provider)).c_str(), seen, worstTwin, worstSurface,
                    worstTexel);
        EXPECT_GT(seen, 2000u); // the ground and box cover most of the light's frustum
        // Float decoders of the same depth: a few ulps of coordinates of size ~3.
        EXPECT_LT(worstTwin, 1e-5f);
        // The stored depth is unbiased: every texel lies on the surface, not behind it (the
        // map's own depth is biased by 2 slopes + 2 ulps, which would miss by far more).
        EXPECT_LT(worstSurface, 1e-4f);
        EXPECT_LT(worstTexel, 1e-3f);
    }
}

TEST_F(ShadowMapDecodeTest, AWarpThatMixesDepthIntoXyOrWIsRefused) {
    glm::mat4 warp(1.0f);
    EXPECT_NO_THROW((void)shadowmap::unwarp(warp));
    warp[2][3] = 0.5f; // w takes z: the texel would not say where on the light's ray
    EXPECT_THROW((void)shadowmap::unwarp(warp), std::invalid_argument);
    EXPECT_THROW((void)shadowmap::unwarp(glm::mat4(0.0f)), std::invalid_argument);
}

TEST_F(ShadowMapDecodeTest, SeedTagsAreDistinctNonZeroNormalFloatsUpToTheLargestMap) {
    const int width = 8192; // --shadow-map-size's limit
    for (auto [x, y] : {std::pair{0, 0}, {1, 0}, {0, 1}, {8191, 8191}, {4095, 17}}) {
        const float t = shadowmap::seedTag(x, y, width);
        EXPECT_TRUE(std::isnormal(t)) << x << ", " << y;
        EXPECT_GE(t, 1.0f);
        EXPECT_LT(t, 256.0f);
    }
    EXPECT_NE(shadowmap::seedTag(1, 0, width), shadowmap::seedTag(0, 1, width));
    EXPECT_NE(shadowmap::seedTag(8190, 8191, width), shadowmap::seedTag(8191, 8191, width));
}

// The reach bounds pyramid built straight from the receiver target (MAP_RECEIVERS, JFA-L's
// path) equals the one built from the decoded positions (the eye path's shader): the same boxes
// to the decoders' last bit.
TEST_F(ShadowMapDecodeTest, BoundsPyramidFromTheTargetEqualsTheOneFromDecodedPositions) {
    const SceneView s = spotLitBox();
    RenderSettings settings;
    settings.shadow.size = 128;
    settings.shadow.provider = ShadowMapProvider::Tsm;
    settings.method = "jfa-l";
    Renderer r(fl::test::testShaders(), s.scene, settings);
    r.resize(64, 64);
    r.render(s.camera);
    const MapPositions& map = *r.shadow()->receivers;
    ReceiverBoundsPyramid fromTarget(fl::test::testShaders());
    ReceiverBoundsPyramid fromDecoded(fl::test::testShaders());
    std::array<PenumbraReach, 2> reach{};
    fromTarget.build(map, r.disk(), reach[0]);
    fromDecoded.build(r.decodedShadowReceivers(), 0.5f, r.disk(), reach[1]);
    ASSERT_EQ(reach[0].boundsLevels, reach[1].boundsLevels);
    ASSERT_GT(reach[0].boundsLevels, 1);
    float worst = 0.0f;
    std::size_t boxes = 0;
    for (int level = 0, side = 16; level < reach[0].boundsLevels;
         ++level, side = std::max(1, side / 2))
        for (GLuint PenumbraReach::*tex : {&PenumbraReach::boundsLo, &PenumbraReach::boundsHi}) {
            std::array<std::vector<float>, 2> v;
            for (int i = 0; i < 2; ++i) {
                v[std::size_t(i)].resize(std::size_t(side * side * 4));
                glGetTextureImage(reach[std::size_t(i)].*tex, level, GL_RGBA, GL_FLOAT,
                                  GLsizei(v[std::size_t(i)].size() * sizeof(float)),
                                  v[std::size_t(i)].data());
            }
            for (std::size_t k = 0; k < v[0].size(); ++k) {
                boxes += std::abs(v[0][k]) < 1e29f;
                worst = std::max(worst, std::abs(v[0][k] - v[1][k]));
            }
        }
    EXPECT_GT(boxes, 100u);
    EXPECT_LT(worst, 1e-5f);
}

} // namespace
} // namespace fl::test
