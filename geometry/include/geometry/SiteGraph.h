#pragma once
// The graph the exact Voronoi repair walks on (jfa/ExactRepair.h, `voronoi --exact`): a Delaunay
// triangulation of the sites that can be nearest to a pixel that is not a site.
//
// Which sites. For integer sites, one per pixel, a nearest site q of a non-site pixel p always
// has a 4-neighbour pixel that is not a site: step from q one pixel towards p along the axis
// where they differ most; that pixel lies in the grid (between q and p) and is strictly nearer
// to p ((|d| - 1)^2 < d^2 for |d| >= 1), so it cannot be a site. Only such "boundary" sites
// become vertices; a solid mask keeps its outline, not its inside. A site's own pixel is its own
// answer (distance 0), so it needs no walk.

#include <jfa/ExactRepair.h>
#include <jfa/Grid.h>

#include <vector>

namespace fl::geom {

/// Builds the graph of `seeds` (integer sites, each at its own pixel, as seedPoints(..., true)
/// and seedMask write them) and tags the seeds for the repair: a boundary site's w becomes its
/// vertex; another site's w the vertex of a boundary site in its row (or vertex 0), where a walk
/// from it may start (such a site is never the answer of a non-site pixel). Edges: the exact
/// Delaunay triangulation (delaunayReference) of the boundary sites, or their chain in order
/// along the line when they are collinear or fewer than 3. Throws std::invalid_argument for a
/// cell that does not hold a site at its own integer position.
jfa::SiteGraph buildSiteGraph(jfa::Grid& seeds);
/// The same with the seeds' sites given (jfa::siteCells(seeds): row-major order), so that only
/// the sites and their 4-neighbours are read, not every cell of the grid (throws
/// std::invalid_argument if a site is not at its own pixel of `seeds` or out of order).
jfa::SiteGraph buildSiteGraph(jfa::Grid& seeds, const std::vector<jfa::Cell>& sites);

} // namespace fl::geom
