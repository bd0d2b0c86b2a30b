#pragma once
// The computing part of the Voronoi overlays: the JFA variants by index, plans cut after k
// passes (flood pass by pass), seeds turned into point sites, and a GL flood of those sites
// judged against the exact diagram (CPU, jfa/Reference.h).

#include <jfa/Grid.h>
#include <jfa/Plan.h>
#include <jfa_gl/GlKernel.h>

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace fl::overlay {

/// The JFA variants the overlays cycle through, as jfa::parsePlan specs: JFA, JFA+1, JFA+2,
/// JFA^2, 1+JFA, half resolution.
std::span<const std::string_view> variantSpecs();
/// The plan of variant `index` (wrapped into range) on a width x height grid.
jfa::Plan variantPlan(int index, int width, int height);

/// The first `passes` passes of a one-stage plan (the whole plan for passes < 0 or beyond its
/// count). Throws std::invalid_argument for a plan with several stages (a cut inside the
/// half-resolution stage would leave a smaller grid).
jfa::Plan truncatePlan(const jfa::Plan& plan, int passes);

/// Point sites from seed cells (any criterion's: a texel is a seed when w != 0): each seed texel
/// (x, y) becomes the NearestSite cell {x, y, y * W + x, 0}; other texels are empty.
jfa::Grid sitesFromSeeds(const jfa::Grid& seeds);

/// A flooded Voronoi diagram and its errors against the exact one.
struct SiteDiagram {
    jfa::Grid flooded;                // the kernel's result, read back
    std::vector<std::uint8_t> errors; // 1 where the texel misses its nearest site (ties count
                                      // as correct, jfa::errorMask)
    std::int64_t errorCount = 0;
    std::int64_t sites = 0;
    float maxDistance = 0.0f; // largest exact nearest distance (px), the DT's ramp top
    double floodMs = 0.0;     // upload, GL flood and read-back (wall clock, after glFinish)
    double exactMs = 0.0;     // exact diagram and error mask on the CPU
};

/// Floods integer `sites` (NearestSite cells) with `plan` on the GPU and judges the result.
SiteDiagram floodSites(jfa::GlFloodKernel<jfa::NearestSite>& kernel, const jfa::Plan& plan,
                       const jfa::Grid& sites);

} // namespace fl::overlay
