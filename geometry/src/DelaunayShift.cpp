// Step C2 of the thesis (§6.3.3, "Shift Sites", Fig. 6.9): every site moves from its pixel to
// its own continuous position, the mesh staying a triangulation after every single move.
//
// The thesis sorts a site s' with target s into four cases by where s lies relative to the fan
// of triangles around s':
//   1  s in a triangle of the fan: 1a the plain move creates no crossing ("good", > 90% of the
//      sites); 1b (s' inside the mesh) / 1c (s' on the hull) it does;
//   2  s in a triangle outside the fan: 2a s' inside, 2b s' on the hull;
//   3  s outside the mesh, s' inside (the walk from s' leaves the hull);
//   4  s outside the mesh, s' on the hull: 4a the plain move creates no crossing (then "locally
//      fix the convex hull"), 4b it does.
// Its repairs: insert s into the triangle (or edge) holding it, delete the fan of s', and
// re-triangulate the hole (interior s') or the polygonal line (hull s', "locally fix the convex
// hull"); for 3 and 4b connect s to the hull edge the walk crossed and fix the hull around s.
//
// How that maps to the code, with every step provably keeping a triangulation (DelaunayMesh.h,
// the degree argument: a disk of strictly counterclockwise triangles bounded by a convex polygon
// turning once is a triangulation):
//   - The good test, exact: every fan triangle (s, a_i, a_{i+1}) strictly counterclockwise, and,
//     for a hull site with hull neighbours w, x (and their neighbours w', x'), the boundary stays
//     convex: convex turns w' -> w -> s, w -> s -> x and s -> x -> x'. Then the mesh's topology is
//     unchanged, all triangles are positive, and the boundary is convex and still turns once (the
//     set of such s is convex, contains s', and the turning number is constant on it), so the
//     move is valid. This is case 1a, and case 4a when s lies outside the old hull but inside
//     the region where no neighbour becomes reflex.
//   - Every other site (1b, 1c, 2a, 2b, 3, 4b, and the rest of 4a, where a neighbour would become
//     reflex) is a bad shift: its fan is deleted first and the hole re-triangulated (ear
//     clipping around the old position, or a Graham scan restoring the hull: removeVertex), then
//     s is located by a walk from the hole and inserted: split triangle (1b, 2a), split edge, or
//     joined to every hull edge that sees it (3, 4b) - the thesis' "connect to the last edge
//     passed, then locally fix the convex hull", done in one step. Deleting before inserting is
//     the thesis' order reversed; it needs no temporary vertex and gives the same kind of mesh.
//   - Not covered by the thesis: s may coincide with the pixel position of a site not shifted
//     yet (in world coordinates). Such a site is left out and inserted by C3 once every site
//     stands on its own position (counted as bad).
//   - A removal that would leave no triangle (a mesh of one strip) reports `stuck`; the driver
//     then falls back to rebuild().
#include <geometry/detail/DelaunaySteps.h>

namespace fl::geom::detail {

using glm::dvec2;

namespace {

enum class Quick { Good, Bad, Open };

// The good-shift test's common case without building the fan: walk counterclockwise around an
// interior site testing its triangles at q. Open: v is on the hull (and every triangle seen so
// far passed), so the full test has to decide.
Quick quickShiftTest(const WorkMesh& mesh, std::uint32_t v, dvec2 q) {
    const auto& tris = mesh.triangles;
    const auto& half = mesh.halfedges;
    const std::uint32_t e0 = mesh.vertexEdge[v];
    std::uint32_t e = e0;
    do {
        const std::uint32_t p = prevHalfedge(e);
        if (fastOrientSign(q, mesh.at(tris[nextHalfedge(e)]), mesh.at(tris[p])) <= 0)
            return Quick::Bad;
        e = half[p];
        if (e == kNoHalfedge) return Quick::Open;
    } while (e != e0);
    return Quick::Good;
}

// The exact good-shift test for site v moving to q (see the file comment).
bool isGoodShift(const WorkMesh& mesh, dvec2 q, bool hull, const std::vector<std::uint32_t>& fan) {
    const auto& tris = mesh.triangles;
    for (const std::uint32_t e : fan) {
        const std::uint32_t a = tris[nextHalfedge(e)], b = tris[prevHalfedge(e)];
        if (fastOrientSign(q, mesh.at(a), mesh.at(b)) <= 0) return false;
    }
    if (!hull) return true;
    const std::uint32_t out = fan.front();             // v -> x, on the boundary
    const std::uint32_t in = prevHalfedge(fan.back()); // w -> v, on the boundary
    const std::uint32_t x = tris[nextHalfedge(out)], w = tris[in];
    const std::uint32_t xNext = tris[nextHalfedge(mesh.nextBoundary(out))];
    const std::uint32_t wPrev = tris[mesh.prevBoundary(in)];
    return convexTurn(mesh.at(w), q, mesh.at(x)) && convexTurn(mesh.at(wPrev), mesh.at(w), q) &&
           convexTurn(q, mesh.at(x), mesh.at(xNext));
}

} // namespace

ShiftStats shiftSites(WorkMesh& mesh, const std::vector<dvec2>& targets,
                      const std::vector<std::uint32_t>& order) {
    ShiftStats stats;
    std::vector<std::uint32_t> fan;
    for (const std::uint32_t v : order) {
        const dvec2 q = targets[v];
        if (mesh.points[v] == q) {
            ++stats.good;
            continue;
        }
        Quick quick = quickShiftTest(mesh, v, q);
        if (quick == Quick::Open) {
            const bool hull = mesh.fan(v, fan);
            quick = isGoodShift(mesh, q, hull, fan) ? Quick::Good : Quick::Bad;
        }
        if (quick == Quick::Good) {
            mesh.points[v] = q;
            ++stats.good;
            continue;
        }
        ++stats.bad;
        if (!mesh.removeVertex(v)) {
            stats.stuck = true;
            return stats;
        }
        mesh.points[v] = q;
        const Location where = mesh.locate(q, mesh.anyTriangle());
        if (where.kind == Location::Kind::OnVertex)
            stats.deferred.push_back(v);
        else
            mesh.insert(v, where, false);
    }
    return stats;
}

} // namespace fl::geom::detail
