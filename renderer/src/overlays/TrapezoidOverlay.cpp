// The TSM overlay: the shadow map shown in the light's NDC (un-warping TSM's N_T per fragment),
// with the eye frustum's hull, the trapezoid and the focus line drawn over it. With the uniform
// provider there is no fit: the map is shown alone.

#include "OverlayState.h"

#include <geometry/Trapezoid.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cstdio>

namespace fl::overlay {

namespace {
constexpr glm::vec4 kHullColour{0.2f, 0.9f, 1.0f, 1.0f};
constexpr glm::vec4 kTrapezoidColour{1.0f, 0.9f, 0.1f, 1.0f};
constexpr glm::vec4 kCentreColour{1.0f, 1.0f, 1.0f, 1.0f};
constexpr glm::vec4 kFocusColour{1.0f, 0.3f, 0.8f, 1.0f};
} // namespace

Lines drawTrapezoid(State& s, const Frame& f) {
    const ShadowMapPass::Outputs* sh = f.renderer.shadow();
    if (!sh) return {"no frame rendered yet"};
    const glm::ivec4 vp = squareViewport(f.width, f.height);
    if (!sh->trapezoid) {
        // The fit needs the eye frustum clamped to the scene's depth range, which only the
        // shadow pass knows; without TSM show the map alone.
        f.bindTarget();
        GridDraw g{GridMode::Depth, &sh->depth};
        g.lightSpace = true;
        s.canvas.drawGrid(g, vp);
        s.result.viewport = vp;
        s.result.drawn = true;
        return {"uniform shadow map in light NDC; the trapezoid needs the tsm provider "
                "(--shadow-map tsm)"};
    }
    const geom::TrapezoidFit& fit = *sh->trapezoid;
    f.bindTarget();
    GridDraw g{GridMode::Depth, &sh->depth};
    g.lightSpace = true;
    g.warp = sh->warp;
    s.canvas.drawGrid(g, vp);

    std::vector<Vertex> loops;
    for (const glm::vec2 p : fit.hull) loops.push_back({p, kHullColour});
    s.canvas.drawVertices(loops, GL_LINE_LOOP, vp);
    std::vector<Vertex> trapezoid;
    for (const glm::vec2 p : fit.corners) trapezoid.push_back({p, kTrapezoidColour});
    s.canvas.drawVertices(trapezoid, GL_LINE_LOOP, vp);
    s.canvas.drawVertices(trapezoid, GL_POINTS, vp, 5.0f);
    // The centre line (near to far centre) and the focus line: through the focus point,
    // perpendicular to the centre line, across the whole view.
    const glm::vec2 axis = fit.farCenter - fit.nearCenter;
    const float len = glm::length(axis);
    std::vector<Vertex> lines{{fit.nearCenter, kCentreColour}, {fit.farCenter, kCentreColour}};
    if (len > 0.0f) {
        const glm::vec2 across = glm::vec2(-axis.y, axis.x) / len * 3.0f;
        lines.push_back({fit.focusPoint - across, kFocusColour});
        lines.push_back({fit.focusPoint + across, kFocusColour});
    }
    s.canvas.drawVertices(lines, GL_LINES, vp);

    s.result.corners.assign(fit.corners.begin(), fit.corners.end());
    s.result.viewport = vp;
    s.result.drawn = true;
    char text[160];
    std::snprintf(text, sizeof text, "weight %.2f (1 = pure trapezoid), r = %.3f, focus %.0f%%",
                  double(fit.weight), double(fit.centerLineRatio),
                  double(f.renderer.settings().shadow.tsm.focusFraction) * 100.0);
    return {std::string("light NDC, ") + (sh->provider == ShadowMapProvider::Tsm
                                              ? "TSM map un-warped"
                                              : "uniform map; the trapezoid TSM would fit"),
            "cyan: eye frustum hull, yellow: trapezoid, white: centre line, pink: focus line",
            text};
}

} // namespace fl::overlay
