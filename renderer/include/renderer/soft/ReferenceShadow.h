#pragma once
// Ground truth for the soft-shadow methods: the disk light's visibility estimated by N point
// lights on the disk. For each of N stratified disk samples a depth map is rendered from that
// point (a perspective volume fitted to the scene, as for the scene's own point light, with the
// same depth bias) and every eye pixel adds its hard visibility from that map; the sum / N is the
// visible fraction of the disk. The samples follow a geom::DiskPattern: by default Vogel's
// golden-angle spiral, which a straight edge splits evenly at every angle; `grid` is the centres
// of an a x b grid (a the largest divisor of N not above sqrt(N)) mapped onto the disk by
// Shirley-Chiu's concentric map, which bands along edges parallel to its rows
// (docs/history/truth-and-raytrace.md, "The maps reference's sample pattern"). N = 1 is the disk
// centre for every pattern and the result equals the hard method there (point and spot lights;
// a directional light's disk is sampled with perspective maps from the disk, so N = 1 is not its
// hard shadow). The estimate's error: shadow-map discretisation per sample (texel size at the
// map resolution) plus sampling error, measured by comparing N with 2N (referenceSamplingError).

#include <gpu/Gl.h>
#include <gpu/PassTimer.h>
#include <gpu/Program.h>
#include <gpu/ShaderLibrary.h>
#include <io/ImageIO.h>
#include <renderer/passes/ShadowMapPass.h>
#include <renderer/passes/SurfacesPass.h>
#include <renderer/scene/GpuScene.h>
#include <scene/DiskLight.h>

#include <base/Aabb.h>
#include <geometry/DiskSampling.h>

#include <vector>

namespace fl {

struct ReferenceSettings {
    int samples = 256;  // N point lights on the disk (>= 1)
    int mapSize = 2048; // texels per side of each point light's depth map
    geom::DiskPattern pattern = geom::DiskPattern::Spiral; // where the N point lights sit
};

/// The N sample points on the disk (world space), in the order they are rendered.
std::vector<glm::vec3> referenceDiskSamples(const DiskLight& disk, int samples,
                                            geom::DiskPattern pattern = geom::DiskPattern::Spiral);

/// Difference between two visibility images of one frame (e.g. N and 2N samples), over the
/// pixels where `mask` (same size) is > 0.5, or all pixels with an empty mask.
struct VisibilityDifference {
    double rmse = 0.0;
    double maxAbs = 0.0;
    std::size_t pixels = 0;
};
VisibilityDifference visibilityDifference(const FloatImage& a, const FloatImage& b,
                                          const FloatImage& mask = {});

class ReferenceShadowPass {
  public:
    explicit ReferenceShadowPass(const gl::ShaderLibrary& shaders);

    struct Inputs {
        const GpuScene& scene;          // drawn into each sample's map
        SurfacePositions positions;     // the frame's surfaces (SurfacesPass)
        const geom::Aabb& sceneBounds;  // each sample's volume holds these in depth
        const geom::Aabb& casterBounds; // and is aimed at these (Renderer's lightVolume())
        const DiskLight& light;
        const ShadowMapSettings& shadowSettings; // depth bias
        const ReferenceSettings& settings;
        /// The surfaces pass's lift and normals: where every lookup starts (surface_lookup.glsl).
        const gl::Texture& lift;
        const gl::Texture& normals;
    };
    struct Outputs {
        const gl::Texture& visibility; // R32F: lit samples / N
    };
    /// Renders the N maps and accumulates over the frame's surfaces; `timer` times "reference
    /// maps" and "reference resolve". Throws std::invalid_argument for samples < 1 or a bad map
    /// size.
    Outputs execute(const Inputs& in, gl::PassTimer* timer = nullptr);

  private:
    void resize(int width, int height, int mapSize);

    gl::Program depth_, accumulate_, resolve_;
    gl::VertexArray emptyVao_;
    gl::Texture sum_, visibility_, map_;
    gl::Framebuffer sumFbo_, visibilityFbo_, mapFbo_;
};

/// Renders the frame's reference visibility with `samples` and with 2 x `samples` and returns
/// their difference over surface pixels: the reference's own sampling error at `samples`.
VisibilityDifference referenceSamplingError(ReferenceShadowPass& pass,
                                            ReferenceShadowPass::Inputs in, int samples);

} // namespace fl
