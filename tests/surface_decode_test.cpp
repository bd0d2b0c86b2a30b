// The packed surfaces pass's decoders (renderer/passes/SurfaceDecode.h, the CPU twin of
// shaders/surface_decode.glsl): normals, base colour and positions come back within the
// precision their formats hold.
#include <io/ImageIO.h>
#include <renderer/passes/SurfaceDecode.h>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <random>

namespace fl::test {
namespace {

// A 16-bit SNORM channel as GL stores it (round to nearest).
float snorm16(float v) {
    return std::round(glm::clamp(v, -1.0f, 1.0f) * 32767.0f) / 32767.0f;
}

TEST(SurfaceDecodeTest, OctahedralNormalsSurviveSixteenBitsWithinATenthOfAMilliradian) {
    std::mt19937 rng(7);
    std::normal_distribution<float> g;
    float worst = 0.0f;
    for (int i = 0; i < 20000; ++i) {
        const glm::vec3 n = glm::normalize(glm::vec3(g(rng), g(rng), g(rng)));
        const glm::vec2 e = surface::octEncode(n);
        const glm::vec3 back = surface::octDecode({snorm16(e.x), snorm16(e.y)});
        // The chord, not acos of the dot (which float resolves only to ~3e-4 near 1).
        worst = std::max(worst, glm::length(back - n));
    }
    // A 16-bit step is 3e-5 of the map's side; the octahedron stretches it by at most ~4.
    EXPECT_LT(worst, 1e-4f);
}

TEST(SurfaceDecodeTest, AxesAndTheFoldedHemisphereDecodeExactly) {
    for (const glm::vec3 n : {glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0), glm::vec3(0, 1, 0),
                              glm::vec3(0, -1, 0), glm::vec3(0, 0, 1), glm::vec3(0, 0, -1)}) {
        const glm::vec3 back = surface::octDecode(surface::octEncode(n));
        EXPECT_EQ(back, n) << n.x << " " << n.y << " " << n.z;
    }
}

TEST(SurfaceDecodeTest, SrgbRoundTripsAndMatchesTheImageWriter) {
    for (int i = 0; i <= 1000; ++i) {
        const float v = static_cast<float>(i) / 1000.0f;
        const float s = surface::linearToSrgb(glm::vec3(v)).x;
        EXPECT_NEAR(surface::srgbToLinear(glm::vec3(s)).x, v, 2e-6f);
        // One transfer function: the PNG writer's bytes are this curve's.
        EXPECT_EQ(static_cast<int>(linearToSrgb8(v)), static_cast<int>(std::lround(s * 255.0f)));
    }
}

// Positions rebuilt from a reversed-Z float depth, for points on pixel centres at every
// distance of a frustum 10^5 deep (near 0.01, far 1000): within 1e-6 of the point's distance
// from the eye plus the eye's from the origin (float world coordinates carry that much already).
// A [-1, 1] depth of the same projection misses by 5e-3 of the distance at the far end.
TEST(SurfaceDecodeTest, ReversedDepthGivesPositionsBackAtEveryDistance) {
    const glm::ivec2 size(256, 192);
    const glm::mat4 proj = glm::perspective(glm::radians(50.0f), 256.0f / 192.0f, 0.01f, 1000.0f);
    const glm::vec3 eye(3.0f, 2.0f, 5.0f);
    const glm::mat4 view = glm::lookAt(eye, glm::vec3(0.0f), glm::vec3(0, 1, 0));
    const glm::mat4 vp = surface::reversedViewProj(proj, view);
    const glm::mat4 inv = surface::inverseReversedViewProj(proj, view);
    const glm::dmat4 invD = glm::inverse(glm::dmat4(proj) * glm::dmat4(view));
    std::mt19937 rng(3);
    std::uniform_int_distribution<int> px(0, size.x - 1), py(0, size.y - 1);
    float worst = 0.0f;
    for (int i = 0; i < 5000; ++i) {
        const glm::ivec2 p(px(rng), py(rng));
        const double t = std::pow(10.0, -1.9 + 4.8 * (i / 5000.0)); // 0.0126 .. 790 along the ray
        // The pixel centre's ray, in double, and the point on it at eye distance t.
        const glm::dvec2 ndc = (glm::dvec2(p) + 0.5) / glm::dvec2(size) * 2.0 - 1.0;
        const glm::dvec4 far = invD * glm::dvec4(ndc, 1.0, 1.0);
        const glm::dvec3 dir = glm::normalize(glm::dvec3(far) / far.w - glm::dvec3(eye));
        const glm::vec3 world = glm::vec3(glm::dvec3(eye) + t * dir);
        // The depth the rasteriser stores: clip z / w in float.
        const glm::vec4 clip = vp * glm::vec4(world, 1.0f);
        const float depth = clip.z / clip.w;
        const glm::vec4 back = surface::position(depth, p, size, inv);
        ASSERT_EQ(back.w, 1.0f);
        const float scale = static_cast<float>(t) + glm::length(eye);
        worst = std::max(worst, glm::length(glm::vec3(back) - world) / scale);
    }
    EXPECT_LT(worst, 1e-6f);
    EXPECT_EQ(surface::position(surface::kBackgroundDepth, {0, 0}, size, inv), glm::vec4(0.0f));
}

} // namespace
} // namespace fl::test
