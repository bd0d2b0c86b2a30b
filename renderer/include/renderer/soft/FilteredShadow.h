#pragma once
// Baselines that filter the shadow map: PCF (a k x k grid of depth comparisons, one
// uniform-map texel apart) and PCSS (Fernando 2005: blocker search, penumbra estimate, PCF).
//
// Both work in the light's own (unwarped) post-perspective plane and take each tap through the
// provider's warp, so they work with the uniform map and with TSM alike:
//  - a tap is a point (x, y) of the light's NDC plane; its texel is warp * (x, y) (NEAREST);
//  - its reference depth is where the light's ray through (x, y) meets the receiver's plane
//    (the pixel's world position and geometric normal): a receiver-plane depth, so that a wide
//    filter on a receiver sloped to the light does not shadow itself;
//  - a tap is lit when reference depth <= stored depth (the hard test's GL_LEQUAL); taps off the
//    map count as lit, as in hardShadow().
// PCSS measures in the light's view space (depth d along its axis): the disk (radius R, centre
// at depth dC) seen from the receiver (depth dR) through the plane at depth d is a disk of
// radius R (dR - d) / (dR - dC) around the point of the segment receiver -> disk centre at that
// depth (similar triangles). The blocker search uses that disk at the light volume's near plane
// (no occluder is nearer); the filter uses it at the mean blocker depth.
// Taps: a fixed golden-angle (Vogel) disk per count, not rotated per pixel: noise-free and
// temporally stable, at the price of banding where counts are low.
// filteredVisibility() is the CPU reference of shaders/filtered_shadow.frag.glsl.

#include <gpu/Gl.h>
#include <gpu/PassTimer.h>
#include <gpu/Program.h>
#include <gpu/ShaderLibrary.h>
#include <renderer/passes/ShadowMapPass.h>
#include <renderer/passes/SurfacesPass.h>
#include <renderer/scene/GpuScene.h>
#include <scene/DiskLight.h>

#include <base/Framing.h>

#include <optional>
#include <string_view>
#include <vector>

namespace fl {

/// PCSS sample counts: blocker-search taps / filter taps.
struct PcssPreset {
    int blockerSamples = 16;
    int filterSamples = 16;
};
/// Parses "16/16", "16/24" or "32/64"; nullopt for anything else.
std::optional<PcssPreset> parsePcssPreset(std::string_view text);

/// Largest PCF kernel side (taps per side) accepted.
inline constexpr int kMaxPcfKernel = 15;

struct FilteredShadowSettings {
    int pcfKernel = 3; // PCF: kernel x kernel taps, one uniform-map texel apart (1 .. 15)
    PcssPreset pcss;   // PCSS sample counts
};

/// `count` points of a golden-angle spiral filling the unit disk (equal area per point).
std::vector<glm::vec2> vogelDisk(int count);
/// PCF tap offsets in shadow-map texels: a kernel x kernel grid centred on 0.
std::vector<glm::vec2> pcfOffsets(int kernel);

/// Everything the filter reads, on the CPU side (the CPU reference's input).
struct FilterFrame {
    enum class Mode { Pcf, Pcss };
    Mode mode = Mode::Pcf;
    int size = 0;              // map texels per side
    std::vector<float> depth;  // size*size stored depths, row 0 = bottom (GL order)
    glm::mat4 lightView{1.0f}; // the light volume (the map's lightViewProj = proj * view)
    glm::mat4 lightProj{1.0f};
    glm::mat4 warp{1.0f};
    float searchDepth = 0.0f; // PCSS: light-view depth of the blocker-search plane
    DiskLight disk;
    // PCSS: the disk's normal (toward the scene) and two tangents, in light-view space. The
    // filter's similar triangles are taken across the disk, not across the map: the two differ
    // where the map is not aimed along the spot (docs/history/truth-and-raytrace.md, "PCSS
    // across the disk").
    glm::vec3 diskNormalView{0.0f, 0.0f, -1.0f}, diskTangentView{1.0f, 0.0f, 0.0f},
        diskBitangentView{0.0f, 1.0f, 0.0f};
    std::vector<glm::vec2> taps;        // PCF: NDC offsets; PCSS: filter taps (unit disk)
    std::vector<glm::vec2> blockerTaps; // PCSS: unit disk
};

/// Reads a DEPTH_COMPONENT32F map back, row 0 = bottom (FilterFrame::depth).
std::vector<float> readDepthMap(const gl::Texture& depth);

/// CPU reference of the filter at world point p with receiver normal n.
float filteredVisibility(const FilterFrame& f, glm::vec3 p, glm::vec3 n);

/// Per-eye-pixel PCF or PCSS visibility; the result is the method's visibility (step 3).
class FilteredShadowPass {
  public:
    explicit FilteredShadowPass(const gl::ShaderLibrary& shaders);

    struct Inputs {
        const SurfacesPass::Outputs& surfaces; // positions and receiver planes per pixel
        const ShadowMapPass::Outputs& shadow;
        const geom::ViewVolume& lightVolume; // the volume the shadow map was made with
        const DiskLight& light;
        const FilteredShadowSettings& settings;
        bool pcss; // false: PCF
    };
    struct Outputs {
        const gl::Texture& visibility; // R32F (1 on background)
    };
    /// Filters per pixel of the frame's surfaces; `timer` times it as "pcf filter" or
    /// "blocker search+filter".
    Outputs execute(const Inputs& in, gl::PassTimer* timer = nullptr);
    /// The CPU-side description of execute(in), without the depths (see readDepthMap).
    [[nodiscard]] FilterFrame frame(const Inputs& in) const;

  private:
    void resize(int width, int height);

    gl::Program program_;
    gl::Handle<gl::detail::SamplerDeleter> rawDepth_; // no comparison: PCSS reads depths
    gl::VertexArray emptyVao_;
    gl::Texture visibility_;
    gl::Framebuffer fbo_;
};

} // namespace fl
