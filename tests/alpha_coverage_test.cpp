// The CPU side of alpha cut-outs (scene/AlphaCoverage.h): GL's level-0 bilinear sample,
// the per-mode decision, and the ray-traced truth seeing the same checker as the ray caster.

#include "TestScenes.h"

#include <raytrace/ShadowRays.h>
#include <renderer/soft/ShadowRayInputs.h>
#include <scene/AlphaCoverage.h>

#include <gtest/gtest.h>

namespace fl::test {
namespace {

// A 2 x 1 image: alpha 0 on the left texel, 255 on the right.
Image twoTexels() {
    Image img;
    img.width = 2;
    img.height = 1;
    img.rgba = {0, 0, 0, 0, 0, 0, 0, 255};
    return img;
}

TEST(AlphaCoverage, SampleIsGlsBilinearLevelZeroWithRepeat) {
    const Image img = twoTexels();
    EXPECT_FLOAT_EQ(sampleAlpha(img, {0.25f, 0.5f}), 0.0f) << "the left texel's centre";
    EXPECT_FLOAT_EQ(sampleAlpha(img, {0.75f, 0.5f}), 1.0f) << "the right texel's centre";
    EXPECT_FLOAT_EQ(sampleAlpha(img, {0.5f, 0.5f}), 0.5f) << "halfway between the centres";
    // REPEAT: u = 0 lies halfway between the right texel (wrapped) and the left one.
    EXPECT_FLOAT_EQ(sampleAlpha(img, {0.0f, 0.5f}), 0.5f);
    EXPECT_FLOAT_EQ(sampleAlpha(img, {1.25f, -3.5f}), 0.0f);
}

TEST(AlphaCoverage, EachModeDecidesAsTheSpecSays) {
    Scene s = checkerCardOverGround(AlphaMode::Mask, 2);
    // Card triangle 0 is (-1,1,1) (1,1,1) (1,1,-1) with uv (0,1) (1,1) (1,0), so the point
    // (u, v) of it has uv (u + v, 1 - v). u = 0.5, v = 0.25 is the centre of texel (1, 1):
    // solid ((1 + 1) % 2 == 0); u = 0, v = 0.75 the centre of texel (1, 0): transparent.
    {
        const AlphaCoverage c(s);
        EXPECT_TRUE(c.any());
        EXPECT_FALSE(c.cutsOut(0)) << "the opaque ground";
        EXPECT_TRUE(c.blocks(0, 0, 0.3f, 0.3f));
        EXPECT_TRUE(c.blocks(1, 0, 0.5f, 0.25f));
        EXPECT_FALSE(c.blocks(1, 0, 0.0f, 0.75f));
    }
    s.materials[1].alphaCutoff = 0.0f; // everything with alpha >= 0 stays
    EXPECT_TRUE(AlphaCoverage(s).blocks(1, 0, 0.0f, 0.75f));
    s.materials[1].alphaCutoff = 0.5f;
    s.materials[1].alphaMode = AlphaMode::Opaque;
    EXPECT_TRUE(AlphaCoverage(s).blocks(1, 0, 0.0f, 0.75f)) << "OPAQUE ignores alpha";
    EXPECT_FALSE(AlphaCoverage(s).any());
    // BLEND casts where alpha >= 0.5; the factor and the vertex colours multiply in.
    s.materials[1].alphaMode = AlphaMode::Blend;
    s.materials[1].baseColorFactor.a = 0.6f;
    EXPECT_TRUE(AlphaCoverage(s).blocks(1, 0, 0.5f, 0.25f));
    EXPECT_FALSE(AlphaCoverage(s).blocks(1, 0, 0.0f, 0.75f));
    s.meshes[1].colors.assign(4, glm::vec4(1, 1, 1, 0.8f));
    EXPECT_FALSE(AlphaCoverage(s).blocks(1, 0, 0.5f, 0.25f)) << "0.6 x 0.8 < 0.5";
}

// Embree through worldTriangles against the brute-force ray caster, on the checker card's
// shadow: the same cells are lit.
TEST(AlphaCoverage, RayTracedTruthSeesTheCheckerTheRayCasterSees) {
    const Scene s = checkerCardOverGround(AlphaMode::Mask, 4);
    const rt::RayScene scene(worldTriangles(s));
    int compared = 0, lit = 0;
    for (float x = -1.0f; x <= 2.7f; x += 0.05f)
        for (float z = -1.2f; z <= 1.8f; z += 0.05f) {
            const glm::vec3 p{x, 0.0f, z};
            const float ref = rayCastVisibility(s, *s.light, p);
            // Rays through a cell's edge (alpha exactly 0.5 there) may round either way.
            bool edge = false;
            for (glm::vec3 d : {glm::vec3(0.01f, 0, 0), glm::vec3(-0.01f, 0, 0),
                                glm::vec3(0, 0, 0.01f), glm::vec3(0, 0, -0.01f)})
                edge = edge || rayCastVisibility(s, *s.light, p + d) != ref;
            if (edge) continue;
            const bool blocked = scene.occluded(p + glm::vec3(0, 1e-3f, 0), s.light->position);
            EXPECT_EQ(blocked, ref == 0.0f) << x << ", " << z;
            ++compared;
            lit += ref == 1.0f ? 1 : 0;
        }
    EXPECT_GT(lit, 100);
    EXPECT_LT(lit, compared - 100) << "the card must shadow some of the points";
}

} // namespace
} // namespace fl::test
