// Step C3 of the thesis (§6.3.3, "Insert Missing Sites"), and the incremental fallback.
//
// The thesis locates a missing site t from the site s that took its pixel, "similar to the
// category process in Step C2", and then: t in a triangle (cases 1, 2) -> split it; t outside the
// mesh (cases 3, 4) -> connect it to the hull edge(s) it sees and locally fix the hull. Here the
// walk starts in s's fan and the insertion handles all of these, plus t exactly on an edge
// (split the edge: two triangles become four, or one on the hull becomes two). No flips yet:
// C4 restores the Delaunay property for all of them at once.
#include "DelaunaySteps.h"

#include <stdexcept>
#include <string>

namespace fl::geom::detail {

void insertSites(WorkMesh& mesh, const std::vector<std::uint32_t>& sites,
                 const std::vector<std::uint32_t>& near) {
    for (std::size_t i = 0; i < sites.size(); ++i) {
        const std::uint32_t t = sites[i];
        const std::uint32_t s = near[i];
        const std::uint32_t start =
            s < mesh.points.size() && mesh.inMesh(s) ? mesh.vertexEdge[s] / 3 : mesh.anyTriangle();
        const Location where = mesh.locate(mesh.points[t], start);
        if (where.kind == Location::Kind::OnVertex)
            throw std::logic_error("delaunay: site " + std::to_string(t) + " coincides with site " +
                                   std::to_string(where.id) + " after deduplication");
        mesh.insert(t, where, false);
    }
}

void rebuild(WorkMesh& mesh, const std::vector<std::uint32_t>& sites) {
    // Seed with the first non-degenerate triple, then the incremental Delaunay algorithm: each
    // insertion is followed by Lawson flips, so the walks run in a Delaunay triangulation.
    const std::uint32_t a = sites.at(0), b = sites.at(1);
    std::size_t third = 2;
    while (third < sites.size() &&
           fastOrientSign(mesh.points[a], mesh.points[b], mesh.points[sites[third]]) == 0)
        ++third;
    if (third == sites.size()) throw std::logic_error("delaunay: the fallback got collinear sites");
    const std::uint32_t c = sites[third];
    if (fastOrientSign(mesh.points[a], mesh.points[b], mesh.points[c]) > 0)
        mesh.setTriangles({a, b, c});
    else
        mesh.setTriangles({b, a, c});
    for (std::size_t k = 2; k < sites.size(); ++k) {
        if (k == third) continue;
        const std::uint32_t v = sites[k];
        const Location where = mesh.locate(mesh.points[v], mesh.anyTriangle());
        if (where.kind == Location::Kind::OnVertex)
            throw std::logic_error("delaunay: the fallback got duplicate sites");
        mesh.insert(v, where, true);
    }
}

} // namespace fl::geom::detail
