#pragma once
// Step 5 of a frame, with the HUD: the window's overlay modes. Pictures of the frame's
// intermediate data (shadow map, seeds, penumbra map, flood passes, Voronoi diagram / distance
// transform of the seeds, JFA vs standard flooding, the TSM trapezoid), a Voronoi playground and
// the Delaunay visualiser. Each is drawn over the current framebuffer by OverlayRenderer::draw.

#include <gpu/ShaderLibrary.h>
#include <renderer/Renderer.h>

#include <jfa/Grid.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fl {

enum class OverlayMode {
    None,
    ShadowMap,
    Seeds,
    PenumbraMap,
    FloodPasses,
    Voronoi,
    DistanceTransform,
    JfaVsFlood,
    Trapezoid,
    VoronoiPlayground,
    Delaunay
};
/// "none", "shadow-map", "seeds", "penumbra-map", "flood-passes", "voronoi",
/// "distance-transform", "jfa-vs-flood", "trapezoid", "playground", "delaunay".
std::string_view overlayName(OverlayMode m);
/// Every mode, in the order the window cycles through them.
std::span<const OverlayMode> allOverlayModes();
/// Parses an overlay name; nullopt if unknown.
std::optional<OverlayMode> parseOverlay(std::string_view name);
/// True for the overlays that show the frame's seeds or flood at every texel (seeds, penumbra
/// map, flood passes, Voronoi, distance transform, JFA vs flood): the frame they draw must
/// flood the band (RenderSettings::wholeFlood), since the default flood region, view, limits
/// seeds and flood to where the eye's pixels read.
bool overlayReadsWholeFlood(OverlayMode m);

/// What the window's keys/mouse set for the overlays.
struct OverlayControls {
    int floodPass = -1;   // FloodPasses: show the state after this many passes (-1 = all)
    int delaunayStep = 0; // Delaunay: index of the stage shown
    int variant = 0;      // Voronoi/DistanceTransform/Playground: index into the JFA variants
    int playgroundSites = 64;
    std::uint32_t seed = 1;                // playground random sites
    std::vector<glm::vec2> clickedSites;   // playground, in [0,1]^2 window coordinates
    bool regenerate = false;               // playground/Delaunay: new random points
    int delaunayPoints = 200;              // Delaunay: random points (when no file is given)
    std::vector<glm::dvec2> delaunayInput; // Delaunay: points to use instead (e.g. a file's)
};

/// What the last draw() computed, for tests and tools (grids row 0 at y = 0).
struct OverlayResult {
    OverlayMode mode = OverlayMode::None;
    jfa::Grid grid;      // the grid shown: flood after k passes, Voronoi diagram, playground
    jfa::Grid reference; // JfaVsFlood: the other method's flood of the same seeds
    std::vector<std::uint8_t> mask; // Voronoi / playground: errors; JfaVsFlood: differences
    std::int64_t count = 0;         // texels set in mask
    std::vector<glm::vec2> corners; // Trapezoid: the fit's corners in light NDC
    glm::ivec4 viewport{0};         // where the picture went ({x, y, w, h} in pixels)
    bool drawn = false;             // false when the mode had nothing to show (HUD says why)
};

class OverlayRenderer {
  public:
    /// Compiles the overlays' shaders (needs a current context).
    explicit OverlayRenderer(const gl::ShaderLibrary& shaders);
    ~OverlayRenderer();
    OverlayRenderer(OverlayRenderer&&) noexcept;
    OverlayRenderer& operator=(OverlayRenderer&&) noexcept;

    /// Draws `mode` for the renderer's last frame over the current framebuffer (w x h pixels);
    /// returns text lines for the HUD (e.g. the variant and the live error count).
    std::vector<std::string> draw(OverlayMode mode, const Renderer& renderer,
                                  const CameraView& camera, OverlayControls& controls, int w,
                                  int h);
    /// Names of the JFA variants `variant` indexes, and of the Delaunay stages.
    static std::span<const std::string_view> variantNames();
    static std::span<const std::string_view> delaunayStageNames();
    /// What the last draw() computed.
    [[nodiscard]] const OverlayResult& lastResult() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace fl
