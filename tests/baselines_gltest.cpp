// The baselines on the GPU: PCF and PCSS against their CPU reference on both shadow-map
// providers, the ground truth against hard shadows (N = 1, radius 0) and against a CPU ray cast
// to the same disk samples, its sampling error shrinking with N, and the goldens.

#include "GlTest.h"
#include "ImageCompare.h"
#include "TestPaths.h"
#include "TestScenes.h"

#include <renderer/Renderer.h>
#include <renderer/io/TextureImage.h>
#include <renderer/passes/SurfaceDecode.h>
#include <renderer/passes/SurfacesPass.h>
#include <renderer/passes/TerminatorLift.h>
#include <renderer/run/Capture.h>
#include <renderer/run/ClosedFormRender.h>
#include <renderer/soft/FilteredShadow.h>
#include <renderer/soft/ReferenceShadow.h>
#include <scene/ClosedForm.h>
#include <scene/GltfLoader.h>

#include <cmath>
#include <cstdio>

namespace fl::test {
namespace {

class BaselinesTest : public GlTest {};

// As penumbra_gltest: the default light's own radius casts penumbrae under a texel.
constexpr float kTestRadius = 1.5f;

FrameImages renderDefault(std::string_view method, float radius, int mapSize,
                          const ReferenceSettings& reference = {}, int size = 256,
                          const MethodOptions& options = {}) {
    Scene scene = loadGltf(defaultAsset());
    scene.light->radius = radius;
    const gl::ShaderLibrary& shaders = fl::test::testShaders();
    RenderSettings settings;
    settings.shadow.size = mapSize;
    settings.method = std::string(method);
    settings.options = options;
    settings.options.set("--reference-samples", reference.samples);
    settings.options.set("--reference-map-size", reference.mapSize);
    Renderer r(shaders, scene, settings);
    r.resize(size, size);
    r.render(makeCameraView(scene, {}, 1.0f));
    return readFrame(r);
}

// PCF / PCSS on the GPU against filteredVisibility() on the CPU, per pixel, from the read-back
// shadow map and the pass' own per-pixel inputs (the surfaces' position and receiver plane). The
// CPU rounds differently (no fused multiply-add, its own matrix products), which can flip a tap
// whose reference depth is within rounding of the stored depth or whose coordinate is within
// rounding of a texel edge: one flipped PCF tap moves a pixel by 1/taps, a flipped PCSS blocker
// moves the filter radius too. So: at most 0.5% of surface pixels may differ by more than 1e-5, and
// the mean difference must stay under 1e-3.
void compareFilterWithCpu(ShadowMapProvider provider, bool pcss) {
    Scene scene = loadGltf(defaultAsset());
    scene.light->radius = kTestRadius;
    const gl::ShaderLibrary& shaders = fl::test::testShaders();
    const GpuScene gpu(scene);
    const Light light = sceneLight(scene);
    const DiskLight disk = makeDiskLight(light, scene.bounds);
    const geom::ViewVolume volume = lightVolume(scene, light);
    const CameraView camera = makeCameraView(scene, {}, 1.0f);
    ShadowMapSettings ss;
    ss.size = 512;
    ss.provider = provider;
    ShadowMapPass shadowPass(shaders);
    const ShadowMapPass::Outputs shadow =
        shadowPass.execute({gpu, volume, ss, camera.view, camera.proj, scene.bounds, false});
    FilteredShadowSettings fs;
    fs.pcfKernel = 5;
    fs.pcss = PcssPreset{16, 24};
    const int size = 128;
    SurfacesPass surfacesPass(shaders);
    surfacesPass.resize(size, size);
    const SurfacesPass::Outputs surfaces = surfacesPass.execute({gpu, camera, light});
    FilteredShadowPass pass(shaders);
    const FilteredShadowPass::Inputs in{surfaces, shadow, volume, disk, fs, pcss};
    const FilteredShadowPass::Outputs out = pass.execute(in);
    FilterFrame f = pass.frame(in);
    f.depth = readDepthMap(shadow.depth);
    const FloatImage vis = readTexture(out.visibility, 1);
    const FloatImage points = surfaces.positions().read();
    const FloatImage normals = surfaces.readNormals(SurfacesPass::Outputs::Normal::Plane);
    // Every lookup starts from the lifted point, against the smooth tangent plane where lifted
    // (surfaceLookupPoint, surfaceLookupPlane in surface_lookup.glsl).
    const FloatImage shading = surfaces.readNormals(SurfacesPass::Outputs::Normal::Shading);
    const FloatImage lift = readTexture(surfaces.lift, 1);
    std::size_t lifted = 0;
    std::size_t surface = 0, differ = 0, partial = 0;
    double sumAbs = 0.0, maxAbs = 0.0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            if (points.at(x, y, 3) == 0.0f) continue;
            ++surface;
            const glm::vec3 ns(shading.at(x, y, 0), shading.at(x, y, 1), shading.at(x, y, 2));
            const float h = lift.at(x, y, 0);
            lifted += h > 0.0f;
            const glm::vec3 n =
                h > 0.0f ? ns
                         : glm::vec3(normals.at(x, y, 0), normals.at(x, y, 1), normals.at(x, y, 2));
            glm::vec3 p = surface::lookupPoint(
                {points.at(x, y, 0), points.at(x, y, 1), points.at(x, y, 2)}, h, ns);
            p = surface::normalOffset(p, n, glm::normalize(f.disk.center - p),
                                      f.warp * f.lightProj * f.lightView, float(f.size));
            const float cpu = filteredVisibility(f, p, n);
            const float gpuV = vis.at(x, y, 0);
            const double d = std::abs(static_cast<double>(cpu) - gpuV);
            sumAbs += d;
            maxAbs = std::max(maxAbs, d);
            differ += d > 1e-5;
            partial += gpuV > 0.0f && gpuV < 1.0f;
        }
    std::printf("%s %s: %zu surface pixels (%zu lifted), %zu partial, %zu differ > 1e-5, mean "
                "%.2e max %.3f\n",
                std::string(providerName(provider)).c_str(), pcss ? "pcss" : "pcf", surface, lifted,
                partial, differ, sumAbs / static_cast<double>(surface), maxAbs);
    ASSERT_GT(surface, 5000u);
    ASSERT_GT(partial, 200u) << "the view must show filtered edges";
    EXPECT_LE(static_cast<double>(differ), 0.005 * static_cast<double>(surface));
    EXPECT_LT(sumAbs / static_cast<double>(surface), 1e-3);
}

TEST_F(BaselinesTest, PcfMatchesCpuReferenceUniform) {
    compareFilterWithCpu(ShadowMapProvider::Uniform, false);
}
TEST_F(BaselinesTest, PcfMatchesCpuReferenceTsm) {
    compareFilterWithCpu(ShadowMapProvider::Tsm, false);
}
TEST_F(BaselinesTest, PcssMatchesCpuReferenceUniform) {
    compareFilterWithCpu(ShadowMapProvider::Uniform, true);
}
TEST_F(BaselinesTest, PcssMatchesCpuReferenceTsm) {
    compareFilterWithCpu(ShadowMapProvider::Tsm, true);
}

TEST_F(BaselinesTest, ReferenceWithOneSampleIsTheHardShadow) {
    ReferenceSettings rs;
    rs.samples = 1;
    rs.mapSize = 512; // the hard method's map size: the same map
    const FrameImages hard = renderDefault("hard", kTestRadius, 512, {}, 128);
    const FrameImages ref = renderDefault("reference", kTestRadius, 512, rs, 128);
    EXPECT_EQ(hard.visibility.data, ref.visibility.data);
}

TEST_F(BaselinesTest, ReferenceWithZeroRadiusIsTheHardShadow) {
    ReferenceSettings rs;
    rs.samples = 9;
    rs.mapSize = 512;
    const FrameImages hard = renderDefault("hard", 0.0f, 512, {}, 128);
    const FrameImages ref = renderDefault("reference", 0.0f, 512, rs, 128);
    EXPECT_EQ(hard.visibility.data, ref.visibility.data);
    std::size_t shadowed = 0;
    for (float v : hard.visibility.data) shadowed += v == 0.0f;
    EXPECT_GT(shadowed, 100u);
}

// A box on a ground plane under a point light of radius 1: the ground truth per pixel against
// a CPU ray cast from the pixel's surface point to the same disk samples. Each sample's map
// decides a point within about a texel (and the depth bias) of a shadow edge differently from
// the exact ray, so a pixel can be off by a few 1/N; pixels elsewhere must agree exactly.
struct BoxScene {
    Scene scene;
    DiskLight disk;
    CameraView camera;
};
// The frame's surfaces (step 2), which the ground truth shades: positions per pixel.
struct Surfaces {
    Surfaces(const gl::ShaderLibrary& shaders, const GpuScene& gpu, const BoxScene& b, int size)
        : pass(shaders) {
        pass.resize(size, size);
        (void)pass.execute({gpu, b.camera, sceneLight(b.scene)});
    }
    SurfacesPass pass;
    [[nodiscard]] SurfacePositions positions() const { return pass.outputs().positions(); }
};
BoxScene boxScene() {
    BoxScene b;
    b.scene = groundAndBox(3.0f, {-0.5f, 0.0f, -0.5f}, {0.5f, 1.0f, 0.5f}, {0.3f, -1, 0.2f});
    b.scene.light->type = Light::Type::Point;
    b.scene.light->position = {-1.0f, 5.0f, -0.6f};
    b.scene.light->radius = 1.0f;
    b.disk = makeDiskLight(*b.scene.light, b.scene.bounds);
    CameraSpec spec;
    spec.kind = CameraSpec::Kind::LookAt;
    spec.eye = {3.0f, 4.0f, 4.5f};
    b.camera = makeCameraView(b.scene, spec, 1.0f);
    return b;
}

// The ground truth's pass and boxScene's surfaces at size x size pixels, the shadow maps at their
// default settings.
struct ReferenceSetup {
    explicit ReferenceSetup(int size) : surfaces(shaders, gpu, b, size) {}
    [[nodiscard]] ReferenceShadowPass::Inputs inputs(const ReferenceSettings& rs) const {
        const SurfacesPass::Outputs o = surfaces.pass.outputs();
        return {
            gpu,      surfaces.positions(), b.scene.bounds, b.scene.bounds, b.disk, ss, rs, o.lift,
            o.normals};
    }
    const BoxScene b = boxScene();
    const gl::ShaderLibrary& shaders = fl::test::testShaders();
    const GpuScene gpu{b.scene};
    const ShadowMapSettings ss{};
    ReferenceShadowPass pass{shaders};
    const Surfaces surfaces;
};

TEST_F(BaselinesTest, ReferenceMatchesCpuRayCastToTheSameSamples) {
    const int size = 96;
    ReferenceSetup setup(size);
    const BoxScene& b = setup.b;
    ReferenceSettings rs;
    rs.samples = 16;
    rs.mapSize = 2048;
    const Surfaces& surfaces = setup.surfaces;
    const ReferenceShadowPass::Outputs out = setup.pass.execute(setup.inputs(rs));
    const FloatImage vis = readTexture(out.visibility, 1);
    const FloatImage points = surfaces.positions().read();
    const std::vector<glm::vec3> samples = referenceDiskSamples(b.disk, rs.samples, rs.pattern);
    std::size_t surface = 0, partial = 0, exact = 0, within = 0;
    double sumAbs = 0.0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            if (points.at(x, y, 3) == 0.0f) continue;
            ++surface;
            const glm::vec3 p(points.at(x, y, 0), points.at(x, y, 1), points.at(x, y, 2));
            float lit = 0.0f;
            for (const glm::vec3& q : samples) {
                Light l = *b.scene.light;
                l.position = q;
                lit += rayCastVisibility(b.scene, l, p);
            }
            const float cpu = lit / static_cast<float>(samples.size());
            const float d = std::abs(cpu - vis.at(x, y, 0));
            partial += cpu > 0.0f && cpu < 1.0f;
            exact += d == 0.0f;
            within += d <= 2.0f / static_cast<float>(rs.samples) + 1e-6f;
            sumAbs += d;
        }
    std::printf("%zu surface pixels, %zu partial, %zu exact, %zu within 2/N, mean |d| %.4f\n",
                surface, partial, exact, within, sumAbs / static_cast<double>(surface));
    ASSERT_GT(partial, 100u) << "the view must show penumbrae";
    EXPECT_GE(static_cast<double>(exact), 0.95 * static_cast<double>(surface));
    EXPECT_GE(static_cast<double>(within), 0.995 * static_cast<double>(surface));
    EXPECT_LT(sumAbs / static_cast<double>(surface), 0.005);
}

// The estimate converges: N against 2N differs less at N = 16 than at N = 2.
TEST_F(BaselinesTest, ReferenceSamplingErrorShrinksWithN) {
    ReferenceSetup setup(64);
    ReferenceSettings rs;
    rs.mapSize = 1024;
    const ReferenceShadowPass::Inputs in = setup.inputs(rs);
    const VisibilityDifference coarse = referenceSamplingError(setup.pass, in, 2);
    const VisibilityDifference fine = referenceSamplingError(setup.pass, in, 16);
    std::printf("N=2 vs 4: rmse %.4f max %.3f; N=16 vs 32: rmse %.4f max %.3f\n", coarse.rmse,
                coarse.maxAbs, fine.rmse, fine.maxAbs);
    EXPECT_GT(coarse.rmse, 0.0);
    EXPECT_LT(fine.rmse, 0.5 * coarse.rmse);
}

TEST_F(BaselinesTest, BadSettingsAreRejected) {
    ReferenceSetup setup(16);
    ReferenceSettings rs;
    rs.samples = 0;
    EXPECT_THROW((void)setup.pass.execute(setup.inputs(rs)), std::invalid_argument);
    RenderSettings settings;
    settings.method = "pcf";
    settings.options.set("--pcf-kernel", 0);
    Renderer r(setup.shaders, setup.b.scene, settings);
    r.resize(16, 16);
    EXPECT_THROW(r.render(setup.b.camera), std::invalid_argument);
}

// Image regression at 256² with a 512² map, light radius 1.5 (the penumbra goldens' set-up);
// tolerances as for those goldens: another driver may round shading and flip comparisons at
// float precision. The ground truth uses 64 samples and 1024² maps to stay a few seconds.
// PCSS at its default preset on closed-form case `c`, 128² with a 1024² map; a failure of
// `rmse < limit` writes the difference picture NAME.
ClosedFormError expectPcssCloseTo(const ClosedFormCase& c, double limit, const char* name) {
    RenderSettings settings;
    settings.shadow.size = 1024;
    settings.method = "pcss";
    const ClosedFormFrame f = renderClosedForm(gl::ShaderLibrary{}, c, settings, 128);
    EXPECT_LT(f.error.rmse, limit) << name;
    if (f.error.rmse >= limit)
        ADD_FAILURE() << writeVisibilityDiff(f.visibility, f.error.exact, name);
    return f.error;
}

// The bug (found on the closed-form cases, bench/closed_form_bench.cpp): under a spot light over
// a scene that extends far to one side, the map was aimed at the bounds' centre with corners
// behind the light, so its near plane sat at 1/1000 of the scene; PCSS's blocker search looks
// through that plane, its taps all left the map, and the umbra came out lit (RMSE 0.46 against
// the exact answer, 0.036 with the edge turned 30 degrees back). Now the map looks along the
// spot (geom::fitPerspectiveLight).
TEST_F(BaselinesTest, PcssFindsBlockersUnderASpotOverASceneToOneSide) {
    // PCSS's own error on this edge is about 0.04 (its filter is a fixed kernel of the blocker
    // depth's disk); the bug's was 0.46. 0.1 separates the two with room for drivers.
    const ClosedFormError e =
        expectPcssCloseTo(straightEdgeCase(1.0f, 5.0f, 1.0f, 30.0f), 0.1, "pcss_spot_side");
    EXPECT_GT(e.penumbra, 200u);
}

// The bug (closed-form cases, docs/history/truth-and-raytrace.md "PCSS where the map is aimed off
// the spot's axis"): PCSS took its similar triangles across the map, with depths along the map's
// axis, while the disk lies across the spot's axis. Where the map is tilted from the spot (the
// edge at height 0.5, the map aimed at the bounds' centre), PCSS equalled the hard shadow: RMSE
// 0.072 against the exact answer at 256², 0.013 now with the triangles taken across the disk.
TEST_F(BaselinesTest, PcssTakesItsTrianglesAcrossTheDiskNotTheMap) {
    // Between the two: at this size 0.0748 with the old construction (verified to fail), 0.0145
    // now.
    const ClosedFormError e =
        expectPcssCloseTo(straightEdgeCase(0.5f, 6.0f, 1.0f, 20.0f), 0.04, "pcss_tilted_map");
    std::printf("pcss, low edge under a tilted map: RMSE %.4f over %zu ground pixels\n", e.rmse,
                e.ground);
    EXPECT_GT(e.penumbra, 50u);
}

TEST_F(BaselinesTest, Goldens) {
    ReferenceSettings rs;
    rs.samples = 64;
    rs.mapSize = 1024;
    // The goldens were made with PCSS 16/16 (the renderer's default before the method table,
    // whose default is 16/24): the preset is set, not left to the default.
    MethodOptions options;
    options.set("--pcss-preset", "16/16");
    for (std::string_view m : {"pcf", "pcss", "reference"}) {
        const FrameImages f = renderDefault(m, kTestRadius, 512, rs, 256, options);
        expectFrameMatchesGoldens(f, "default_256_" + std::string(m));
    }
}

} // namespace
} // namespace fl::test
