// The Voronoi playground: random (or clicked) sites in a square grid, the chosen JFA variant's
// diagram on the GPU, its errors against the exact diagram in red and their live count.

#include "OverlayState.h"

#include <renderer/overlays/SiteDiagram.h>

#include <jfa/Sites.h>

#include <algorithm>
#include <cstdio>

namespace fl::overlay {

namespace {
// The grid is the viewport's square, at most this many texels per side (keeps the exact
// reference and the read-back interactive on a software rasteriser).
constexpr int kMaxPlaygroundSide = 512;
constexpr int kMaxPlaygroundSites = 100000;
} // namespace

Lines drawPlayground(State& s, const Frame& f) {
    OverlayControls& c = f.controls;
    if (c.regenerate) {
        ++c.seed;
        c.clickedSites.clear();
        c.regenerate = false;
    }
    c.playgroundSites = std::clamp(c.playgroundSites, 0, kMaxPlaygroundSites);
    const glm::ivec4 vp = squareViewport(f.width, f.height);
    const int n = std::clamp(vp.z, 2, kMaxPlaygroundSide);
    std::vector<jfa::Site> sites =
        c.playgroundSites > 0
            ? jfa::randomIntegerSites(std::min(c.playgroundSites, n * n), n, n, c.seed)
            : std::vector<jfa::Site>{};
    // Clicks are window fractions (x right, y up); those outside the square are ignored.
    for (const glm::vec2 u : c.clickedSites) {
        const glm::vec2 p =
            (u * glm::vec2(f.width, f.height) - glm::vec2(vp.x, vp.y)) / float(vp.z) * float(n);
        if (p.x >= 0.0f && p.y >= 0.0f && p.x < float(n) && p.y < float(n))
            sites.push_back(
                {std::min(std::floor(p.x), float(n - 1)), std::min(std::floor(p.y), float(n - 1))});
    }
    if (sites.empty()) return {"playground: no sites (add some, or press regenerate)"};
    const jfa::SeedResult seeded = jfa::seedPoints(sites, n, n, true);
    const jfa::Plan plan = variantPlan(c.variant, n, n);
    SiteDiagram d = floodSites(s.siteKernel, plan, seeded.grid);
    const gl::Texture grid = jfa::uploadGrid(d.flooded);
    const gl::Texture mask = uploadMask(d.errors, n, n);
    f.bindTarget();
    s.canvas.drawGrid({GridMode::Voronoi, &grid, nullptr, &mask}, vp);
    s.result.grid = std::move(d.flooded);
    s.result.mask = std::move(d.errors);
    s.result.count = d.errorCount;
    s.result.viewport = vp;
    s.result.drawn = true;
    char timing[96];
    std::snprintf(timing, sizeof timing, "GL flood + read-back %.1f ms, exact (CPU) %.1f ms",
                  d.floodMs, d.exactMs);
    char text[128];
    std::snprintf(text, sizeof text, "errors (red): %lld of %d texels (%.3f%%)",
                  static_cast<long long>(d.errorCount), n * n,
                  100.0 * double(d.errorCount) / double(n * n));
    return {"playground " + std::to_string(n) + "^2, " + std::to_string(d.sites) + " sites (" +
                std::to_string(c.clickedSites.size()) + " clicked), seed " + std::to_string(c.seed),
            plan.describe(), timing, text};
}

} // namespace fl::overlay
