#pragma once
// Private to the Delaunay pipeline (Delaunay*.cpp): the triangulation that the CPU steps C1-C3
// edit in place, with the few local operations they are made of. Layout as Triangulation.h
// (three vertices per slot, counterclockwise, halfedges opposite), plus:
//   - vertexEdge: per point one outgoing halfedge, so a site's fan is found in O(degree);
//   - free slots: a removed triangle leaves its slot for the next added one, so nothing
//     allocates per triangle; compact() squeezes them out before C4.
//
// Validity argument used throughout (the "degree argument"): a mesh that is a combinatorial
// disk (edge- and vertex-manifold, connected, one boundary cycle, V - E + F = 1), whose triangles
// are all strictly counterclockwise, and whose boundary cycle is a convex polygon turning once
// around, is a triangulation of its vertices: every point off the edges is covered by as many
// triangles as the boundary winds around it, i.e. exactly once inside the hull and never outside.
// isTriangulation() checks exactly these conditions in O(n); every local edit below keeps them.

#include <geometry/Predicates.h>

#include <geometry/Triangulation.h>
#include <geometry/detail/DelaunayPredicates.h>

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace fl::geom::detail {

/// Marks a free slot (its first vertex) in WorkMesh::triangles.
inline constexpr std::uint32_t kFreeSlot = 0xffffffffu;

/// Where point location ended.
struct Location {
    enum class Kind : std::uint8_t {
        Inside,   // strictly inside triangle `id`
        OnEdge,   // strictly inside the edge of halfedge `id`
        OnVertex, // on vertex `id` (the mesh already has a vertex at that position)
        Outside,  // outside the hull, strictly beyond the boundary halfedge `id`
    };
    Kind kind = Kind::Inside;
    std::uint32_t id = 0;
};

/// b lies strictly between a and c on their common line (caller knows they are collinear).
[[nodiscard]] bool strictlyBetween(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c);
/// The boundary turn a -> b -> c is allowed on a convex hull: left, or straight on.
[[nodiscard]] bool convexTurn(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c);

class WorkMesh {
  public:
    /// A mesh without triangles over `pts` (positions may change later: C2 moves sites).
    /// `threads` (0 = all hardware threads) run the per-vertex and read-only passes of
    /// setTriangles and isTriangulation; results never depend on it.
    explicit WorkMesh(std::vector<glm::dvec2> pts, int threads = 1);

    std::vector<glm::dvec2> points;
    std::vector<std::uint32_t> triangles;
    std::vector<std::uint32_t> halfedges;
    std::vector<std::uint32_t> vertexEdge; // an outgoing halfedge per point, or kNoHalfedge
    std::size_t walkSteps = 0;             // triangles visited by locate() so far (work counter)
    std::size_t insertFlips = 0;           // flips made by insert(..., delaunay = true) so far

    /// Replaces the triangles (no free slots) and derives halfedges and vertexEdge (a hull
    /// vertex gets its outgoing boundary halfedge). False, leaving the mesh unusable, unless the
    /// triangles form an edge- and vertex-manifold surface: no directed edge twice, no edge in
    /// three triangles, each vertex's triangles one fan.
    bool setTriangles(std::vector<std::uint32_t> tris);
    /// Flips away zero-area triangles (G6 may make one at a four-colour corner, §6.4): the edge
    /// with the flat triangle's third vertex strictly inside it is flipped, which gives two
    /// counterclockwise triangles whenever the triangle across lies strictly on its other side.
    /// False if some flat triangle cannot be fixed that way (it lies on the hull, or its
    /// neighbour is flat too in the wrong way).
    bool flipFlatTriangles();
    /// The rest of the degree argument on the current positions, for a manifold mesh without
    /// free slots: triangles strictly counterclockwise, V - E + F = 1, one boundary cycle that
    /// is convex and turns once; and points 0 .. required - 1 all used.
    [[nodiscard]] bool isTriangulation(std::size_t required) const;

    [[nodiscard]] bool inMesh(std::uint32_t v) const { return vertexEdge[v] != kNoHalfedge; }
    [[nodiscard]] glm::dvec2 at(std::uint32_t v) const { return points[v]; }
    /// A live triangle, for walks that have no better start.
    [[nodiscard]] std::uint32_t anyTriangle() const { return lastTriangle_; }
    /// Number of live triangles.
    [[nodiscard]] std::size_t liveTriangles() const {
        return triangles.size() / 3 - freeSlots_.size();
    }

    /// Room for `count` more triangles beyond the current slots, so adding them never moves
    /// the arrays (a doubling copy holds both, and may leave them twice the size needed).
    void reserveCapacity(std::size_t count) {
        triangles.reserve(triangles.size() + 3 * count);
        halfedges.reserve(halfedges.size() + 3 * count);
    }

    /// v's outgoing halfedges counterclockwise around v; on the hull the first one is v's
    /// outgoing boundary halfedge (v -> next hull vertex). Returns whether v is on the hull.
    bool fan(std::uint32_t v, std::vector<std::uint32_t>& out) const;
    /// The boundary halfedge that follows boundary halfedge e (starts where e ends).
    [[nodiscard]] std::uint32_t nextBoundary(std::uint32_t e) const;
    /// The boundary halfedge that precedes boundary halfedge e (ends where e starts).
    [[nodiscard]] std::uint32_t prevBoundary(std::uint32_t e) const;

    /// Locates q by a stochastic visibility walk from `start` (exact orientations; the random
    /// choice of the first edge keeps it from cycling in non-Delaunay meshes), falling back to a
    /// scan of all triangles if it takes unreasonably long.
    Location locate(glm::dvec2 q, std::uint32_t start);
    /// Inserts point v at points[v] where `where` says (not OnVertex): splits the triangle or
    /// the edge, or joins v to the hull edges that see it. With `delaunay`, restores the
    /// Delaunay property around v by flips (the incremental algorithm; used by the fallback).
    void insert(std::uint32_t v, Location where, bool delaunay);
    /// Removes vertex v and re-triangulates its star: interior -> ear clipping of its link
    /// polygon (star-shaped around v's position); on the hull -> a Graham scan over its link
    /// chain restores the convex hull. Returns false, changing nothing, if no triangle would
    /// be left around some neighbour (only tiny meshes with collinear remainders).
    bool removeVertex(std::uint32_t v);
    /// Moves the live triangles to the front, dropping free slots (before C4 and at the end).
    void compact();
    /// Step C4: Lawson flips (TriangulationFlip.h, as legalize()) until every edge is locally
    /// Delaunay; returns the number of flips. One sweep over the halfedges tests each edge, and
    /// a flip's four outer edges are re-tested at once from a small stack, so no list of all
    /// edges is built. Needs compact() first; leaves vertexEdge stale (the last edit).
    std::size_t makeDelaunay();
    /// makeDelaunay() from `edges` only, for a mesh whose other edges are known to be locally
    /// Delaunay (C4's parallel tests find the rest); `flips` already made count toward the
    /// n(n-1)/2 limit. Returns the flips in all.
    std::size_t flipFrom(const std::vector<std::uint32_t>& edges, std::size_t flips);

  private:
    // C3's parallel batches edit the arrays directly, each thread in its own region
    // (DelaunayInsertParallel.cpp): they need the slot list and the counters.
    friend class RegionInserter;

    std::uint32_t addTriangle(std::uint32_t a, std::uint32_t b, std::uint32_t c);
    void freeTriangle(std::uint32_t t);
    void link(std::uint32_t a, std::uint32_t b);
    void touch(std::uint32_t t); // vertexEdge of t's three vertices := their halfedges in t
    void insertInside(std::uint32_t t, std::uint32_t v);
    void insertOnEdge(std::uint32_t e, std::uint32_t v);
    // The splits of an insertion, shared with C3's strips, which take new triangles from their
    // own reserved slots: `add(a, b, c)` makes a triangle and returns its first halfedge, and the
    // halfedges to re-check for the Delaunay property go to `pending`.
    template <class Add>
    void splitInside(std::uint32_t t, std::uint32_t v, Add&& add,
                     std::vector<std::uint32_t>& pending);
    template <class Add>
    std::uint32_t splitAtEdge(std::uint32_t e, std::uint32_t v, Add&& add,
                              std::vector<std::uint32_t>& pending);
    template <class Add>
    void splitOnEdge(std::uint32_t e, std::uint32_t v, Add&& add,
                     std::vector<std::uint32_t>& pending);
    void insertOutside(std::uint32_t e, std::uint32_t v);
    void restoreDelaunay();
    std::size_t legalize(std::uint32_t e, std::size_t flips); // C4's flips from edge e
    // At most this many flips turn a triangulation of the points into the Delaunay one.
    [[nodiscard]] std::size_t flipLimit() const;
    bool needsFlip(std::uint32_t e) const; // has an opposite and shouldFlip()
    void removeInterior(std::uint32_t v, glm::dvec2 pv);
    bool removeOnHull(std::uint32_t v);
    Location scanLocate(glm::dvec2 q) const;
    int orient(std::uint32_t a, std::uint32_t b, glm::dvec2 q) const {
        return fastOrientSign(points[a], points[b], q);
    }

    int threads_ = 1;
    std::vector<std::uint32_t> freeSlots_;
    std::vector<std::uint32_t> pending_; // halfedges to re-check (delaunay insertion)
    std::uint32_t lastTriangle_ = 0;
    std::uint32_t random_ = 2463534242u; // xorshift32: deterministic "random" walk choices
    // Scratch for fan() and removeVertex(), kept to avoid allocations per site.
    std::vector<std::uint32_t> star_, poly_, outer_, prevIdx_, nextIdx_;
    std::vector<std::uint8_t> covered_;
};

// Triangle (a, b, c) with v strictly inside becomes (a, b, v), (b, c, v), (c, a, v).
template <class Add>
void WorkMesh::splitInside(std::uint32_t t, std::uint32_t v, Add&& add,
                           std::vector<std::uint32_t>& pending) {
    const std::uint32_t e0 = 3 * t;
    const std::uint32_t a = triangles[e0], b = triangles[e0 + 1], c = triangles[e0 + 2];
    const std::uint32_t outerBc = halfedges[e0 + 1], outerCa = halfedges[e0 + 2];
    triangles[e0 + 2] = v; // slot t becomes (a, b, v)
    const std::uint32_t t1 = add(b, c, v);
    const std::uint32_t t2 = add(c, a, v);
    link(t1, outerBc);
    link(t2, outerCa);
    link(e0 + 1, t1 + 2);
    link(t1 + 1, t2 + 2);
    link(t2 + 1, e0 + 2);
    touch(t);
    pending.insert(pending.end(), {e0, t1, t2});
}

// One side of an edge split: the triangle of e = p -> q, (p, q, a), keeps its slot as (p, v, a)
// and (v, q, a) is added; returns the new triangle's halfedge v -> q. e and that halfedge are
// left for the caller to link (to the other side's halves, or to nothing on the hull).
template <class Add>
std::uint32_t WorkMesh::splitAtEdge(std::uint32_t e, std::uint32_t v, Add&& add,
                                    std::vector<std::uint32_t>& pending) {
    const std::uint32_t eNext = nextHalfedge(e), ePrev = prevHalfedge(e);
    const std::uint32_t q = triangles[eNext], a = triangles[ePrev];
    const std::uint32_t outerQa = halfedges[eNext];
    triangles[eNext] = v;
    const std::uint32_t s = add(v, q, a);
    link(s + 1, outerQa);
    link(eNext, s + 2);
    touch(e / 3);
    pending.insert(pending.end(), {ePrev, s + 1});
    return s;
}

// v strictly inside the edge e = p -> q: triangle (p, q, a) becomes (p, v, a), (v, q, a), and
// the triangle across, (q, p, b), becomes (q, v, b), (v, p, b); on the hull v joins it.
template <class Add>
void WorkMesh::splitOnEdge(std::uint32_t e, std::uint32_t v, Add&& add,
                           std::vector<std::uint32_t>& pending) {
    const std::uint32_t o = halfedges[e];
    const std::uint32_t s = splitAtEdge(e, v, add, pending);
    if (o == kNoHalfedge) {
        link(e, kNoHalfedge);
        link(s, kNoHalfedge);
    } else {
        const std::uint32_t r = splitAtEdge(o, v, add, pending);
        link(e, r);
        link(o, s);
    }
}

} // namespace fl::geom::detail
