// G1-G6 in a row, timed (thesis §6.3.2).
#include <geometry/DiscreteDelaunay.h>

#include "Stopwatch.h"

#include <jfa/CpuKernel.h>
#include <jfa/Plan.h>

namespace fl::geom {

using detail::Stopwatch;

DiscreteDelaunay discreteDelaunay(const std::vector<glm::dvec2>& sites,
                                  const DiscreteDelaunayOptions& options) {
    // Bad options fail before any work: the thread count, the size (checked by the mapping of no
    // sites) and the plan spec.
    jfa::resolveThreads(options.threads);
    fitTextureMapping({}, options.size);
    const jfa::Plan plan = jfa::parsePlan(options.plan, options.size, options.size);

    DiscreteDelaunay r;
    Stopwatch clock;
    r.snapped = snapSites(sites, options.size);
    r.timings.g1 = clock.lap();

    r.voronoi = floodVoronoi(r.snapped, plan, options.threads);
    r.timings.g2 = clock.lap();

    if (options.countIslands) r.islandsBefore = countIslandComponents(r.voronoi, r.snapped.pixels);
    r.cleaned = r.voronoi; // kept for the step pictures
    clock.lap();
    r.islands = removeIslands(r.cleaned, r.snapped.pixels, options.threads);
    r.timings.g3 = clock.lap();

    r.corners = classifyCorners(r.cleaned, options.threads);
    r.timings.g4 = clock.lap();

    r.chain = chainRows(r.corners, options.threads);
    r.timings.g5 = clock.lap();

    r.mesh = buildTriangles(r.cleaned, r.corners, r.chain, r.snapped.pixels, options.threads);
    r.timings.g6 = clock.lap();
    return r;
}

} // namespace fl::geom
