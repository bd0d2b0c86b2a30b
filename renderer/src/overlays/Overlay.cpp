#include <renderer/overlays/Overlay.h>

#include "OverlayState.h"

#include <renderer/overlays/SiteDiagram.h>
#include <renderer/soft/EyeSoftShadow.h>
#include <renderer/soft/PenumbraCriterion.h>

#include <jfa/NearestSite.h>

#include <array>

namespace fl {

namespace {
constexpr std::array kModes{OverlayMode::None,
                            OverlayMode::ShadowMap,
                            OverlayMode::Seeds,
                            OverlayMode::PenumbraMap,
                            OverlayMode::FloodPasses,
                            OverlayMode::Voronoi,
                            OverlayMode::DistanceTransform,
                            OverlayMode::JfaVsFlood,
                            OverlayMode::Trapezoid,
                            OverlayMode::VoronoiPlayground,
                            OverlayMode::Delaunay};
constexpr std::array<std::string_view, kModes.size()> kNames{
    "none",    "shadow-map",         "seeds",        "penumbra-map", "flood-passes",
    "voronoi", "distance-transform", "jfa-vs-flood", "trapezoid",    "playground",
    "delaunay"};
// The overlays that draw the frame's seeds or flood at every texel (the seeds, soft->flooded,
// or a flood of the seeds), same order as kModes. The view region limits both seeds and flood
// to what the eye reads, so these frames flood the band.
constexpr std::array<bool, kModes.size()> kWholeFlood{false, false, true,  true,  true, true,
                                                      true,  true,  false, false, false};
// Display names of overlay::variantSpecs(), same order.
constexpr std::array<std::string_view, 6> kVariants{"JFA",   "JFA+1", "JFA+2",
                                                    "JFA^2", "1+JFA", "half-res JFA"};
constexpr std::array<std::string_view, 9> kStages{
    "sites",      "discrete-voronoi", "islands",          "voronoi-vertices", "mesh",
    "hull-fixed", "shifted",          "missing-inserted", "flipped"};
} // namespace

std::string_view overlayName(OverlayMode m) {
    return kNames[static_cast<std::size_t>(m)];
}
std::span<const OverlayMode> allOverlayModes() {
    return kModes;
}
bool overlayReadsWholeFlood(OverlayMode m) {
    return kWholeFlood[static_cast<std::size_t>(m)];
}
std::optional<OverlayMode> parseOverlay(std::string_view name) {
    for (std::size_t i = 0; i < kNames.size(); ++i)
        if (kNames[i] == name) return kModes[i];
    return std::nullopt;
}

struct OverlayRenderer::Impl {
    explicit Impl(const gl::ShaderLibrary& shaders) : state(shaders) {}
    overlay::State state;
};

namespace overlay {
State::State(const gl::ShaderLibrary& shaders)
    : canvas(shaders), siteKernel(shaders, jfa::GlKernelKind::Fragment) {}
} // namespace overlay

OverlayRenderer::OverlayRenderer(const gl::ShaderLibrary& shaders)
    : impl_(std::make_unique<Impl>(shaders)) {}
OverlayRenderer::~OverlayRenderer() = default;
OverlayRenderer::OverlayRenderer(OverlayRenderer&&) noexcept = default;
OverlayRenderer& OverlayRenderer::operator=(OverlayRenderer&&) noexcept = default;

std::vector<std::string> OverlayRenderer::draw(OverlayMode mode, const Renderer& renderer,
                                               const CameraView& camera, OverlayControls& controls,
                                               int w, int h) {
    overlay::State& s = impl_->state;
    s.result = OverlayResult{};
    s.result.mode = mode;
    if (mode == OverlayMode::None || w <= 0 || h <= 0) return {};
    // The kernels bind their own framebuffers and viewports and turn the depth test off:
    // restore the caller's state on every way out.
    struct Bindings {
        GLint draw = 0, read = 0;
        GLint viewport[4] = {0, 0, 0, 0};
        GLboolean depthTest = glIsEnabled(GL_DEPTH_TEST);
        Bindings() {
            glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw);
            glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read);
            glGetIntegerv(GL_VIEWPORT, viewport);
        }
        Bindings(const Bindings&) = delete;
        Bindings& operator=(const Bindings&) = delete;
        ~Bindings() {
            glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(draw));
            glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(read));
            glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
            if (depthTest)
                glEnable(GL_DEPTH_TEST);
            else
                glDisable(GL_DEPTH_TEST);
        }
    } bindings;
    const GLint fbo = bindings.draw;
    const overlay::Frame f{renderer, camera, controls, w, h, fbo};
    std::vector<std::string> lines{"overlay: " + std::string(overlayName(mode))};
    overlay::Lines more;
    switch (mode) {
    case OverlayMode::None:
        break;
    case OverlayMode::ShadowMap:
        more = overlay::drawShadowMap(s, f);
        break;
    case OverlayMode::Seeds:
        more = overlay::drawSeeds(s, f);
        break;
    case OverlayMode::PenumbraMap:
        more = overlay::drawPenumbraMap(s, f);
        break;
    case OverlayMode::FloodPasses:
        more = overlay::drawFloodPasses(s, f);
        break;
    case OverlayMode::Voronoi:
        more = overlay::drawSiteDiagram(s, f, false);
        break;
    case OverlayMode::DistanceTransform:
        more = overlay::drawSiteDiagram(s, f, true);
        break;
    case OverlayMode::JfaVsFlood:
        more = overlay::drawJfaVsFlood(s, f);
        break;
    case OverlayMode::Trapezoid:
        more = overlay::drawTrapezoid(s, f);
        break;
    case OverlayMode::VoronoiPlayground:
        more = overlay::drawPlayground(s, f);
        break;
    case OverlayMode::Delaunay:
        more = overlay::drawDelaunay(s, f);
        break;
    }
    lines.insert(lines.end(), more.begin(), more.end());
    gl::throwIfErrors("overlay");
    return lines;
}

const OverlayResult& OverlayRenderer::lastResult() const {
    return impl_->state.result;
}
std::span<const std::string_view> OverlayRenderer::variantNames() {
    return kVariants;
}
std::span<const std::string_view> OverlayRenderer::delaunayStageNames() {
    return kStages;
}

} // namespace fl
