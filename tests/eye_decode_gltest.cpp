// JFA-E's packed eye cells (renderer/soft/EyeDecode.h, shaders/eye_decode.glsl): the packing
// round-trips every field, and the GLSL decode matches its CPU twin on rendered frames.

#include "GlTest.h"
#include "TestPaths.h"

#include <renderer/Renderer.h>
#include <renderer/soft/EyeDecode.h>
#include <renderer/soft/EyeSoftShadow.h>
#include <renderer/soft/OccluderEdge.h>
#include <scene/GltfLoader.h>

#include <jfa_gl/GlKernel.h>

#include <cmath>
#include <cstdio>

namespace fl::test {
namespace {

using eyecell::State;

constexpr State kStates[] = {State::Background, State::Shadowed, State::Lit, State::OutsideMap};

TEST(EyeCellPacking, RoundTripsEveryField) {
    const glm::ivec2 texels[] = {{0, 0}, {8191, 8191}, {1, 8190}, {4097, 3}, {8191, 0}};
    for (State s : kStates)
        for (glm::ivec2 t : texels)
            for (std::uint32_t code = 0; code < 16; ++code) {
                const std::uint32_t cell = eyecell::pack(s, t, code);
                ASSERT_EQ(eyecell::state(cell), s);
                ASSERT_EQ(eyecell::texel(cell), t);
                ASSERT_EQ(eyecell::edgeCode(cell), code);
            }
}

// A 3x3 map: a near occluder texel in the middle, the ground around it.
ReceiverGrid smallMap() {
    ReceiverGrid g{3, 3, {}};
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 3; ++x)
            g.points.emplace_back(float(x), x == 1 && y == 1 ? 2.0f : 0.0f, float(y), 1.0f);
    return g;
}

TEST(EyeCellPacking, PointAndOccluderFollowTheState) {
    const glm::vec4 surface(1.0f, 2.0f, 3.0f, 1.0f);
    const float flags[] = {-1.0f, 1.0f, 0.0f, 2.0f}; // EyeImage::points' w per state
    const ReceiverGrid map = smallMap();
    const std::vector<float> ids(9, 7.0f);
    for (std::size_t i = 0; i < 4; ++i) {
        const std::uint32_t cell = eyecell::pack(kStates[i], {1, 1}, 1u | (2u << 2));
        const glm::vec4 p = eyecell::point(cell, surface);
        EXPECT_EQ(p.w, flags[i]);
        EXPECT_EQ(glm::vec3(p),
                  kStates[i] == State::Background ? glm::vec3(0.0f) : glm::vec3(surface));
        const glm::vec4 o = eyecell::occluder(cell, map, &ids);
        const bool inMap = kStates[i] == State::Shadowed || kStates[i] == State::Lit;
        EXPECT_EQ(o.w, inMap ? 7.0f : -1.0f);
        // Code x = 1: away from the low x neighbour; y = 2: away from the high y neighbour.
        const glm::vec3 expected = inMap ? glm::vec3(1.5f, 4.0f, 0.5f) : glm::vec3(0.0f);
        EXPECT_EQ(glm::vec3(o), expected);
        EXPECT_EQ(glm::vec3(o), inMap ? occluderEdgeApply(map, 1, 1, 1u | (2u << 2)) : expected);
        EXPECT_EQ(eyecell::occluder(cell, map, nullptr).w, -1.0f);
    }
}

class EyeDecodeTest : public GlTest {};

// Per pixel of a 128² frame of the default scene the GPU's decode (EyeCells::decoded, the bits
// the phases read) against the CPU twin (EyeCells::read): states and object ids exactly, world
// positions to float rounding (the two evaluate the same operations; GLSL's division and the
// matrix products may round differently, a few ulps of the ~10-unit coordinates, far under the
// 1e-4 allowed).
TEST_F(EyeDecodeTest, GpuDecodeMatchesTheCpuTwin) {
    Scene scene = loadGltf(defaultAsset());
    scene.light->radius = 1.5f;
    for (const ShadowMapProvider provider : {ShadowMapProvider::Uniform, ShadowMapProvider::Tsm})
        for (const bool ids : {true, false})
            for (const char* points : {"edge", "centre"}) {
                SCOPED_TRACE(std::string(providerName(provider)) + (ids ? ", ids" : ", no ids") +
                             ", " + points);
                RenderSettings settings;
                settings.shadow.size = 256;
                settings.shadow.provider = provider;
                settings.method = "jfa-e";
                settings.options.set("--no-object-id-fix", !ids);
                settings.options.set("--occluder-points", std::string(points));
                Renderer r(testShaders(), scene, settings);
                r.resize(128, 128);
                r.render(makeCameraView(scene, {}, 1.0f));
                const FloodFrame* flood = r.flood();
                ASSERT_TRUE(flood && flood->eyeCells);
                const auto [gpuPoints, gpuOccluders] = flood->eyeCells->decoded();
                const jfa::Grid gp = jfa::readGrid(gpuPoints), go = jfa::readGrid(gpuOccluders);
                const EyeImage cpu = flood->eyeCells->read();
                ASSERT_EQ(gp.cells.size(), cpu.points.size());
                std::size_t shadowed = 0, background = 0, withId = 0, worst = 0;
                float worstError = 0.0f;
                for (std::size_t i = 0; i < cpu.points.size(); ++i) {
                    const glm::vec4 p(gp.cells[i].x, gp.cells[i].y, gp.cells[i].z, gp.cells[i].w);
                    const glm::vec4 o(go.cells[i].x, go.cells[i].y, go.cells[i].z, go.cells[i].w);
                    ASSERT_EQ(p.w, cpu.points[i].w) << "state of pixel " << i;
                    ASSERT_EQ(o.w, cpu.occluders[i].w) << "object id of pixel " << i;
                    shadowed += p.w == 1.0f;
                    background += p.w == -1.0f;
                    withId += o.w >= 0.0f;
                    const float e =
                        std::max(glm::length(glm::vec3(p) - glm::vec3(cpu.points[i])),
                                 glm::length(glm::vec3(o) - glm::vec3(cpu.occluders[i])));
                    if (e > worstError) worstError = e, worst = i;
                }
                EXPECT_LE(worstError, 1e-4f) << "worst at pixel " << worst;
                EXPECT_GT(shadowed, 200u) << "the view must show hard shadows";
                EXPECT_GT(background, 0u);
                EXPECT_EQ(withId > 0, ids) << "ids are decoded exactly when the fix is on";
                std::printf("%s: %zu shadowed, %zu background, worst position error %g\n", points,
                            shadowed, background, double(worstError));
            }
}

} // namespace
} // namespace fl::test
