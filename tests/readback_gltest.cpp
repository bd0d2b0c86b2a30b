// Read-back through pixel buffers (gpu/ReadBack.h, FrameReadBack): the same floats as the
// synchronous glGetTextureImage path, the frame's rows flipped alike, the motion target's y too;
// and the frame loop's frame-behind mode hands every frame over with the same images.

#include "GlTest.h"
#include "TestScenes.h"

#include <gpu/ReadBack.h>
#include <renderer/Renderer.h>
#include <renderer/io/TextureImage.h>
#include <renderer/run/Capture.h>
#include <renderer/run/FrameRunner.h>

namespace fl::test {
namespace {

class ReadBackTest : public GlTest {};

// Exact equality is right here: both paths copy the same texels as floats, with no conversion.
void expectSame(const FloatImage& a, const FloatImage& b, const char* what) {
    EXPECT_EQ(a.width, b.width) << what;
    EXPECT_EQ(a.height, b.height) << what;
    EXPECT_EQ(a.channels, b.channels) << what;
    EXPECT_TRUE(a.data == b.data) << what << ": the pixel-buffer read-back differs";
}

TEST_F(ReadBackTest, TextureReadBackIsTheSynchronousReadInGlRowOrder) {
    // A texture whose every texel differs (a row-order or channel mix-up shows).
    const int w = 37, h = 19;
    std::vector<float> texels(static_cast<std::size_t>(w) * h * 4);
    for (std::size_t i = 0; i < texels.size(); ++i) texels[i] = static_cast<float>(i) * 0.25f;
    gl::Texture tex(GL_RGBA32F, w, h);
    glTextureSubImage2D(tex.id(), 0, 0, 0, w, h, GL_RGBA, GL_FLOAT, texels.data());
    for (const int channels : {1, 4}) {
        gl::TextureReadBack read;
        EXPECT_FALSE(read.pending());
        read.start(tex, channels);
        EXPECT_TRUE(read.pending());
        const FloatImage sync = readTexture(tex, channels);
        FloatImage async;
        {
            const gl::TextureReadBack::Mapped m = read.finish();
            EXPECT_EQ(m.width(), w);
            EXPECT_EQ(m.height(), h);
            // GL's row 0 (the bottom) first: texel (0, 0) is the first value uploaded.
            EXPECT_EQ(m.data()[0], 0.0f);
            async = fromGlRows(m.data(), m.width(), m.height(), m.channels());
        }
        EXPECT_FALSE(read.pending());
        expectSame(async, sync, channels == 1 ? "red" : "rgba");
    }
    gl::TextureReadBack unused;
    EXPECT_THROW((void)unused.finish(), std::logic_error);
    EXPECT_THROW(unused.start(tex, 3), std::invalid_argument);
}

TEST_F(ReadBackTest, FrameReadBackIsReadFrameWithTheMotionTarget) {
    const Scene scene =
        groundAndBox(3.0f, {-0.5f, 0.0f, -0.5f}, {0.5f, 1.0f, 0.5f}, {0.3f, -1.0f, 0.2f});
    Renderer renderer(testShaders(), scene, {});
    renderer.resize(64, 48);
    CameraSpec spec;
    spec.kind = CameraSpec::Kind::LookAt;
    spec.eye = {0.0f, 6.0f, 6.0f};
    spec.target = {0.0f, 0.0f, 0.0f};
    const CameraView cam = makeCameraView(scene, spec, 64.0f / 48.0f);
    spec.eye = {0.3f, 6.0f, 6.0f};
    renderer.render(cam, makeCameraView(scene, spec, 64.0f / 48.0f)); // writes the motion too
    FrameReadBack read;
    read.start(renderer);
    const FrameImages sync = readFrame(renderer);
    ASSERT_FALSE(sync.motion.data.empty());
    const FrameImages async = read.finish();
    expectSame(async.color, sync.color, "colour");
    expectSame(async.visibility, sync.visibility, "visibility");
    expectSame(async.receivers, sync.receivers, "receivers");
    expectSame(async.motion, sync.motion, "motion");
}

TEST_F(ReadBackTest, AFrameBehindHandsOverEveryFrameWithTheSameImages) {
    const Scene scene =
        groundAndBox(3.0f, {-0.5f, 0.0f, -0.5f}, {0.5f, 1.0f, 0.5f}, {0.3f, -1.0f, 0.2f});
    std::vector<std::vector<FloatImage>> seen[2]; // [readBehind][frame]: lanes' visibility
    CameraSpec spec;
    spec.kind = CameraSpec::Kind::LookAt;
    spec.eye = {0.0f, 6.0f, 6.0f};
    spec.target = {0.0f, 0.0f, 0.0f};
    const CameraView start = makeCameraView(scene, spec, 1.0f);
    for (const bool behind : {false, true}) {
        Renderer a(testShaders(), scene, {}), b(testShaders(), scene, {});
        a.resize(32, 32);
        b.resize(32, 32);
        std::vector<Lane> lanes{{"a", &a, {}}, {"b", &b, {}}};
        FramePlan plan{.scene = &scene,
                       .camera = defaultWalkthrough(start, scene.bounds),
                       .frames = 4,
                       .width = 32,
                       .height = 32,
                       .readBehind = behind,
                       .motionLane = 0};
        std::vector<int> order;
        FrameRunner runner(plan.frames);
        runner.run(plan, lanes, [&](int i, std::vector<FrameImages>& images) {
            order.push_back(i);
            EXPECT_FALSE(images[0].motion.data.empty()) << "frame " << i;
            seen[behind].push_back({images[0].visibility, images[1].visibility});
        });
        EXPECT_EQ(order, (std::vector<int>{0, 1, 2, 3}));
        EXPECT_EQ(lanes[0].times.frames(), 4u);
    }
    ASSERT_EQ(seen[0].size(), seen[1].size());
    for (std::size_t i = 0; i < seen[0].size(); ++i)
        for (std::size_t l = 0; l < 2; ++l)
            expectSame(seen[1][i][l], seen[0][i][l], "frame-behind visibility");
}

} // namespace
} // namespace fl::test
