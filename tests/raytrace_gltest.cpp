// The `raytrace` method through the renderer: the frame's surfaces in, visibility out, against
// the closed form of a straight edge under a disk light (TestScenes.h).

#include "GlTest.h"
#include "ImageCompare.h"

#include <io/ImageIO.h>
#include <renderer/Renderer.h>
#include <renderer/run/Capture.h>
#include <renderer/run/ClosedFormRender.h>
#include <scene/ClosedForm.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <stdexcept>

#include <cmath>

namespace fl::test {
namespace {

class RayTraceMethodTest : public GlTest {};

// One frame of a closed-form case with `method` at 128², the shadow map at mapSize².
ClosedFormFrame renderCase(const ClosedFormCase& c, const std::string& method, int mapSize) {
    RenderSettings settings;
    settings.shadow.size = mapSize;
    settings.method = method;
    return renderClosedForm(gl::ShaderLibrary{}, c, settings, 128);
}

TEST_F(RayTraceMethodTest, EveryClosedFormCaseMatchesThroughTheRenderer) {
    // N = 256 jittered strata: sigma <= sqrt(2 sqrt(N) / 4) / N = 0.011 per pixel (see
    // raytrace_test.cpp); RMSE within one sigma, every pixel within 4.5.
    const double sigma = std::sqrt(2.0 * 16.0 / 4.0) / 256.0;
    int i = 0;
    for (const ClosedFormCase& c : closedFormCases()) {
        SCOPED_TRACE(c.name);
        const ClosedFormFrame f = renderCase(c, "raytrace", 256);
        const ClosedFormError& e = f.error;
        ASSERT_GT(e.penumbra, 200u) << "the view must hold the penumbra";
        ASSERT_GT(e.ground - e.penumbra, 200u) << "and lit and shadowed ground";
        EXPECT_LT(e.rmse, sigma);
        EXPECT_LT(e.maxAbs, 4.5 * sigma);
        if (!(e.rmse < sigma && e.maxAbs < 4.5 * sigma))
            ADD_FAILURE() << writeVisibilityDiff(f.visibility, e.exact,
                                                 "raytrace_case" + std::to_string(i));
        ++i;
    }
}

TEST_F(RayTraceMethodTest, TheTerminatorOffsetLeavesTheClosedFormCasesAsTheyWere) {
    // Their ground and occluders are flat (every vertex normal the face's): the rays leave the
    // same points with the offset on (the default) as off, bit for bit.
    for (const ClosedFormCase& c : closedFormCases()) {
        SCOPED_TRACE(c.name);
        RenderSettings settings;
        settings.shadow.size = 256;
        settings.method = "raytrace";
        settings.options.set("--raytrace-samples", 16);
        const ClosedFormFrame on = renderClosedForm(gl::ShaderLibrary{}, c, settings, 64);
        settings.options.set("--terminator-offset", "off");
        const ClosedFormFrame off = renderClosedForm(gl::ShaderLibrary{}, c, settings, 64);
        ASSERT_GT(on.error.penumbra, 20u);
        EXPECT_EQ(on.visibility.data, off.visibility.data);
    }
}

TEST_F(RayTraceMethodTest, AVertexBeyondEmbreesRangeIsRefusedNamingTheNode) {
    ClosedFormCase v = straightEdgeCase(1.0f, 5.0f, 1.0f, 0.0f);
    // The box's node scaled so far that its vertices leave float's useful range for a BVH (the
    // GPU draws it; Embree would build a tree of infinities).
    v.scene.instances[1].world = glm::scale(glm::mat4(1.0f), glm::vec3(1e20f));
    v.scene.instances[1].nodeName = "giant";
    try {
        (void)renderFrame(v.scene, makeCameraView(v.scene, v.camera, 1.0f), "raytrace", 64, 16);
        ADD_FAILURE() << "accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("node 'giant'"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace fl::test
