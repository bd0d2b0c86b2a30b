// Step C3 of the thesis (§6.3.3, "Insert Missing Sites"), and the incremental fallback.
//
// The thesis locates a missing site t from the site s that took its pixel, "similar to the
// category process in Step C2", and then: t in a triangle (cases 1, 2) -> split it; t outside the
// mesh (cases 3, 4) -> connect it to the hull edge(s) it sees and locally fix the hull. Here the
// walk starts in s's fan and the insertion handles all of these, plus t exactly on an edge
// (split the edge: two triangles become four, or one on the hull becomes two). Unlike the
// thesis, each insertion is followed by Lawson flips around the new site, in a BRIO/Hilbert
// order (DelaunayOrder.cpp): inserting without flips and leaving them all to C4 was quadratic
// when many sites share few pixels (kuzmin, two-lines), as every walk then crossed a fan of
// ever thinner triangles and C4 had to undo them with cascades of flips.
#include <geometry/detail/DelaunaySteps.h>

#include <base/Parallel.h>

#include <stdexcept>
#include <string>

namespace fl::geom::detail {

namespace {

// The sequential insertion of sites[i] for i in `order`, each walk from the previously inserted
// site or from near[i] (the site that kept its pixel), whichever is nearer.
void insertInOrder(WorkMesh& mesh, const std::vector<std::uint32_t>& sites,
                   const std::vector<std::uint32_t>& near,
                   const std::vector<std::uint32_t>& order) {
    const auto distance2 = [](glm::dvec2 a, glm::dvec2 b) {
        const glm::dvec2 d = a - b;
        return d.x * d.x + d.y * d.y;
    };
    std::uint32_t previous = kNoHalfedge;
    for (const std::uint32_t i : order) {
        const std::uint32_t t = sites[i];
        const glm::dvec2 q = mesh.points[t];
        std::uint32_t from = previous;
        const std::uint32_t s = near[i];
        if (s < mesh.points.size() && mesh.inMesh(s) &&
            (from == kNoHalfedge || distance2(mesh.points[s], q) < distance2(mesh.points[from], q)))
            from = s;
        const std::uint32_t start =
            from != kNoHalfedge ? mesh.vertexEdge[from] / 3 : mesh.anyTriangle();
        const Location where = mesh.locate(q, start);
        if (where.kind == Location::Kind::OnVertex)
            throw std::logic_error("delaunay: site " + std::to_string(t) + " coincides with site " +
                                   std::to_string(where.id) + " after deduplication");
        // With flips: the mesh around each new site stays (nearly) Delaunay, so the walks stay
        // short and C4 has little left; without them clustered sites pile up in skinny fans.
        mesh.insert(t, where, true);
        previous = t;
    }
}

} // namespace

std::size_t insertSites(WorkMesh& mesh, const std::vector<std::uint32_t>& sites,
                        const std::vector<std::uint32_t>& near, int threads) {
    std::vector<std::uint32_t> order(sites.size());
    {
        std::vector<OrderItem> items(sites.size());
        for (std::uint32_t i = 0; i < items.size(); ++i) items[i] = {mesh.points[sites[i]], i};
        insertionOrder(items, threads);
        for (std::size_t k = 0; k < order.size(); ++k) order[k] = items[k].index;
    }
    // Below a few thousand sites a thread costs more than it saves.
    if (bandCount(int(sites.size()), threads) > 1 && sites.size() >= kMinParallelInsert)
        order = insertInStrips(mesh, sites, near, order, threads);
    insertInOrder(mesh, sites, near, order);
    return order.size();
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
