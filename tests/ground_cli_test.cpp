// A single model with no ground and no light, as most glTF files are (issue 15, item 4): `render`
// adds a ground (--ground auto) and places the default light so that the shadow falls on it in
// the first view; --ground off shows the model floating with its shadow on nothing. The light by
// hand: --light-dir and --light-position, one at a time.

#include "CliRun.h"
#include "TestPaths.h"
#include "TestScenes.h"

#include <io/ImageIO.h>
#include <scene/SceneGenerator.h>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace fl::test {
namespace {

namespace fs = std::filesystem;

// A 1 x 2 x 1 box standing at the origin, alone: no ground, no light, no camera.
const fs::path& model() {
    static const fs::path file = [] {
        Scene s;
        s.meshes.push_back(box(glm::vec3(0.0f), glm::vec3(1.0f, 2.0f, 1.0f)));
        s.instances.push_back(Instance{0, glm::mat4(1.0f), 1, "box"});
        s.computeBounds();
        const fs::path f = outputDir("ground_cli") / "box.glb";
        writeGlb(s, f);
        return f;
    }();
    return file;
}

struct Render {
    Outcome outcome;
    double shadowed = 0.0; // share of the image: receivers with visibility below 0.5
};

Render render(const std::string& name, const std::string& flags = {}) {
    const fs::path dir = outputDir("ground_cli");
    Render r;
    r.outcome = runCommand(std::string(FLOODLIGHT_BINARY) + " render --scene " + model().string() +
                           " --width 128 --height 128 --shadow-map-size 512 --out " + dir.string() +
                           " --name " + name + " " + flags);
    if (r.outcome.code != 0) return r;
    int w = 0, h = 0;
    std::vector<float> visibility, receiver;
    for (ExrChannel& c : readExr(dir / (name + ".exr"), w, h)) {
        if (c.name == "visibility") visibility = std::move(c.values);
        if (c.name == "receiver") receiver = std::move(c.values);
    }
    EXPECT_EQ(visibility.size(), std::size_t(w) * std::size_t(h));
    EXPECT_EQ(receiver.size(), visibility.size());
    std::size_t n = 0;
    for (std::size_t i = 0; i < visibility.size() && i < receiver.size(); ++i)
        n += receiver[i] > 0.5f && visibility[i] < 0.5f;
    r.shadowed = double(n) / double(std::max<std::size_t>(visibility.size(), 1));
    std::printf("%s: shadowed share %.4f\n", name.c_str(), r.shadowed);
    return r;
}

TEST(GroundCli, ASingleModelCastsAVisibleShadowOnTheGroundItIsGiven) {
    const Render withGround = render("auto");
    ASSERT_EQ(withGround.outcome.code, 0) << withGround.outcome.output;
    EXPECT_NE(withGround.outcome.output.find("ground: added"), std::string::npos)
        << withGround.outcome.output;
    // Measured: 11.6% of the 128² image is the box's shadow on the ground, the first view
    // framing the box and its shadow (issue 30 item 6; 3.0% when it framed the whole ground);
    // half of that fails, as does a shadow hidden behind the box or the whole ground framed.
    EXPECT_GT(withGround.shadowed, 0.058) << "shadowed share " << withGround.shadowed;

    // Without it, the shadow falls on nothing: no receiver is in shadow.
    const Render floating = render("off", "--ground off");
    ASSERT_EQ(floating.outcome.code, 0) << floating.outcome.output;
    EXPECT_EQ(floating.outcome.output.find("ground: added"), std::string::npos);
    EXPECT_LT(floating.shadowed, 0.001) << "shadowed share " << floating.shadowed;
}

TEST(GroundCli, TheLightByHand) {
    // From straight above, the shadow is the box's own footprint, hidden under the box but for
    // a rim (the light stands 2.5 scene radii up: its top's shadow is a little wider than the
    // box) and the penumbra: measured 3.3% of the image, the view framing the box closely; from
    // the side, 5.9%; from the default light, 11.6%.
    const Render above = render("above", "--light-dir 0,-1,0");
    ASSERT_EQ(above.outcome.code, 0) << above.outcome.output;
    const Render side = render("side", "--light-position -6,3,0");
    ASSERT_EQ(side.outcome.code, 0) << side.outcome.output;
    const Render automatic = render("auto");
    EXPECT_LT(above.shadowed, 0.5 * automatic.shadowed);
    EXPECT_GT(side.shadowed, 0.015);
    // Bad ones: one message, the option named.
    Outcome o = render("zero", "--light-dir 0,0,0").outcome;
    EXPECT_EQ(o.code, 1) << o.output;
    EXPECT_NE(o.output.find("--light-dir: the zero vector has no direction"), std::string::npos)
        << o.output;
    o = render("both", "--light-dir 0,-1,0 --light-position 1,2,3").outcome;
    EXPECT_EQ(o.code, 2) << o.output;
    o = render("nan", "--light-position 1,nan,3").outcome;
    EXPECT_EQ(o.code, 2) << o.output;
}

TEST(GroundCli, AModelWithNoSizeIsOneMessageNotAGroundAtNaN) {
    // The box scaled to a point by its node (issue 41, bad input).
    Scene s;
    s.meshes.push_back(box(glm::vec3(0.0f), glm::vec3(1.0f, 2.0f, 1.0f)));
    s.instances.push_back(Instance{0, glm::scale(glm::mat4(1.0f), glm::vec3(0.0f)), 1, "box"});
    s.computeBounds();
    const fs::path file = outputDir("ground_cli") / "point.glb";
    writeGlb(s, file);
    const Outcome o = runCommand(std::string(FLOODLIGHT_BINARY) + " render --scene " +
                                 file.string() + " --width 64 --height 64 --out " +
                                 outputDir("ground_cli").string() + " --name point");
    EXPECT_EQ(o.code, 1) << o.output;
    EXPECT_NE(o.output.find("error: point.glb: scene: every triangle has zero area"),
              std::string::npos)
        << o.output;
    EXPECT_EQ(o.output.find("ground: added"), std::string::npos) << o.output;
}

} // namespace
} // namespace fl::test
