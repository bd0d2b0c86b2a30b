// The HUD pass on the GPU: the same pixels as its CPU reference (rasterizeHud), a golden, and
// the caller's GL state left as it was.

#include "GlTest.h"
#include "ImageCompare.h"

#include <renderer/io/TextureImage.h>
#include <renderer/passes/HudPass.h>

#include <cmath>

namespace fl::test {
namespace {

class HudTest : public GlTest {};

constexpr int kW = 128, kH = 64;

// A background with a gradient, so that blending is checked at many destination values.
ByteImage background() {
    ByteImage img{kW, kH, 4, std::vector<std::uint8_t>(size_t(kW) * kH * 4)};
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            std::uint8_t* p = &img.data[(size_t(y) * kW + x) * 4];
            p[0] = std::uint8_t(x * 2);
            p[1] = std::uint8_t(y * 4);
            p[2] = std::uint8_t(255 - x);
            p[3] = 255;
        }
    return img;
}

const std::vector<std::string> kLines{"jfa-l 1024^2 6 passes", "12.5 ms, 80.0 FPS",
                                      "! cannot open x.glb"};

ByteImage renderOnGpu(const ByteImage& bg) {
    gl::Texture target(GL_RGBA8, kW, kH);
    // Rows go bottom-up in GL; the image is top-down.
    for (int y = 0; y < kH; ++y)
        glTextureSubImage2D(target.id(), 0, 0, kH - 1 - y, kW, 1, GL_RGBA, GL_UNSIGNED_BYTE,
                            &bg.data[size_t(y) * kW * 4]);
    gl::Framebuffer fbo = gl::Framebuffer::create();
    fbo.attach(GL_COLOR_ATTACHMENT0, target);
    fbo.check("hud test");
    const gl::ShaderLibrary& shaders = fl::test::testShaders();
    HudPass hud(shaders);
    // The golden's lines unwrapped (the CPU reference lays them out so too); wrapping to the
    // window is layoutHud's, tested in hud_test.
    HudStyle unwrapped;
    unwrapped.maxWidth = -1;
    hud.draw(kLines, kW, kH, unwrapped, fbo.id());
    const FloatImage f = readTexture(target, 4);
    ByteImage out{kW, kH, 4, std::vector<std::uint8_t>(f.data.size())};
    for (size_t i = 0; i < f.data.size(); ++i)
        out.data[i] = std::uint8_t(std::lround(f.data[i] * 255.0f));
    return out;
}

TEST_F(HudTest, MatchesTheCpuReferenceAndTheGolden) {
    const ByteImage bg = background();
    const ByteImage gpu = renderOnGpu(bg);
    ByteImage cpu = bg;
    rasterizeHud(layoutHud(kLines), cpu);
    // Every edge is on a pixel boundary, so coverage is exact; the blend of an 8-bit target may
    // round the last bit differently from the CPU's float formula, nothing more.
    const Tolerance exact{
        .maxAbs = 1, .meanAbs = 0.5, .pixelThreshold = 0, .maxPercentOver = 100.0};
    const CompareResult c = compareImages(gpu, cpu, exact);
    EXPECT_TRUE(c.pass) << c.report;
    // Golden: the same bound (it was made by this pass on llvmpipe); it guards the font and
    // layout themselves, which the CPU reference shares with the pass.
    const CompareResult g = compareWithGolden(gpu, "hud_128x64", exact);
    EXPECT_TRUE(g.pass) << g.report;
    // The HUD is actually there: the box darkened the background somewhere and text is white.
    int white = 0;
    for (size_t i = 0; i < gpu.data.size(); i += 4)
        white += gpu.data[i] == 255 && gpu.data[i + 1] == 255;
    EXPECT_GT(white, 50);
}

TEST_F(HudTest, RestoresTheCallersState) {
    gl::Texture target(GL_RGBA8, kW, kH);
    gl::Framebuffer fbo = gl::Framebuffer::create();
    fbo.attach(GL_COLOR_ATTACHMENT0, target);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
    glViewport(3, 4, 50, 20);
    glEnable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ZERO);
    const gl::ShaderLibrary& shaders = fl::test::testShaders();
    HudPass hud(shaders);
    // The golden's lines unwrapped (the CPU reference lays them out so too); wrapping to the
    // window is layoutHud's, tested in hud_test.
    HudStyle unwrapped;
    unwrapped.maxWidth = -1;
    hud.draw(kLines, kW, kH, unwrapped, fbo.id());
    GLint viewport[4], fb = 0, src = 0, dst = 0;
    glGetIntegerv(GL_VIEWPORT, viewport);
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &fb);
    glGetIntegerv(GL_BLEND_SRC_RGB, &src);
    glGetIntegerv(GL_BLEND_DST_RGB, &dst);
    EXPECT_EQ(viewport[0], 3);
    EXPECT_EQ(viewport[1], 4);
    EXPECT_EQ(viewport[2], 50);
    EXPECT_EQ(viewport[3], 20);
    EXPECT_EQ(GLuint(fb), fbo.id());
    EXPECT_TRUE(glIsEnabled(GL_DEPTH_TEST));
    EXPECT_FALSE(glIsEnabled(GL_BLEND));
    EXPECT_EQ(src, GL_ONE);
    EXPECT_EQ(dst, GL_ZERO);
    glDisable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

} // namespace
} // namespace fl::test
