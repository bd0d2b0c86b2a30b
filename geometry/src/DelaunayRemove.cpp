// WorkMesh::removeVertex: deleting a site's triangle fan and re-triangulating what it leaves, the
// repair behind every "bad" shift of step C2 (thesis §6.3.3: "delete all the triangles around s'
// ... this hole is triangulated", or "we get a polygonal line ... and locally fix the convex
// hull").
#include <geometry/detail/DelaunayMesh.h>

#include <stdexcept>

namespace fl::geom::detail {

using glm::dvec2;

bool WorkMesh::removeVertex(std::uint32_t v) {
    const dvec2 pv = points[v];
    if (!fan(v, star_)) {
        removeInterior(v, pv);
        return true;
    }
    return removeOnHull(v);
}

// The link polygon a_0 .. a_{k-1} of an interior vertex at pv is strictly star-shaped around pv
// (its triangles (pv, a_i, a_{i+1}) are counterclockwise). Ear (a, b, c) is cut when b is convex
// (orient(a, b, c) > 0) and pv lies strictly on the other side of the chord (orient(pv, a, c) >
// 0): then the ear lies in the wedge a-pv-c, which holds no other polygon vertex, and the rest is
// again strictly star-shaped around pv. Such an ear exists while k >= 5 (of Meisters' two
// interior-disjoint ears at most one can have pv in its closure, and an ear without it has pv
// strictly beyond its chord, or pv could not see its tip); with k = 4 pv may lie on both
// diagonals' lines only when it is their crossing, and then either diagonal splits the hole.
void WorkMesh::removeInterior(std::uint32_t v, dvec2 pv) {
    const std::size_t k = star_.size();
    poly_.resize(k);
    outer_.resize(k);
    prevIdx_.resize(k);
    nextIdx_.resize(k);
    for (std::size_t i = 0; i < k; ++i) {
        const std::uint32_t linkEdge = nextHalfedge(star_[i]); // a_i -> a_{i+1}
        poly_[i] = triangles[linkEdge];
        outer_[i] = halfedges[linkEdge];
        prevIdx_[i] = static_cast<std::uint32_t>(i == 0 ? k - 1 : i - 1);
        nextIdx_[i] = static_cast<std::uint32_t>(i + 1 == k ? 0 : i + 1);
    }
    for (const std::uint32_t e : star_) freeTriangle(e / 3);
    vertexEdge[v] = kNoHalfedge;

    // Cuts the ear at polygon index i: triangle (a, b, c) takes the outer halfedges of a -> b and
    // b -> c, and its c -> a becomes the outer halfedge of the new polygon edge a -> c.
    const auto cut = [&](std::uint32_t i) {
        const std::uint32_t p = prevIdx_[i], n = nextIdx_[i];
        const std::uint32_t s = addTriangle(poly_[p], poly_[i], poly_[n]);
        link(s, outer_[p]);
        link(s + 1, outer_[i]);
        outer_[p] = s + 2;
        nextIdx_[p] = n;
        prevIdx_[n] = p;
    };
    const auto pos = [&](std::uint32_t i) { return points[poly_[i]]; };

    std::size_t remaining = k;
    std::uint32_t i = 0;
    std::size_t misses = 0;
    while (remaining > 3 && misses < remaining) {
        const std::uint32_t p = prevIdx_[i], n = nextIdx_[i];
        if (fastOrientSign(pos(p), pos(i), pos(n)) > 0 && fastOrientSign(pv, pos(p), pos(n)) > 0) {
            cut(i);
            --remaining;
            misses = 0;
            i = p; // the neighbours' ears changed
        } else {
            i = n;
            ++misses;
        }
    }
    if (remaining == 4) {
        // pv on both diagonals: split along whichever gives two counterclockwise triangles.
        const std::uint32_t j = nextIdx_[i], m = nextIdx_[j], l = prevIdx_[i];
        if (fastOrientSign(pos(i), pos(j), pos(m)) > 0 &&
            fastOrientSign(pos(i), pos(m), pos(l)) > 0) {
            cut(j); // (i, j, m), leaving (m, l, i)
        } else if (fastOrientSign(pos(l), pos(i), pos(j)) > 0 &&
                   fastOrientSign(pos(j), pos(m), pos(l)) > 0) {
            cut(i); // (l, i, j), leaving (j, m, l)
            i = j;
        } else {
            throw std::logic_error("delaunay: a quadrilateral hole has no diagonal");
        }
        remaining = 3;
    }
    if (remaining != 3)
        throw std::logic_error("delaunay: no ear in a star-shaped hole (the mesh is invalid)");
    const std::uint32_t p = prevIdx_[i], n = nextIdx_[i];
    const std::uint32_t s = addTriangle(poly_[p], poly_[i], poly_[n]);
    link(s, outer_[p]);
    link(s + 1, outer_[i]);
    link(s + 2, outer_[n]);
}

// A hull vertex's link is a chain x = a_0, ..., a_m = w (x, w its hull neighbours), sorted by
// angle around pv. Without the fan the mesh boundary runs w = a_m -> ... -> a_0 = x; a Graham
// scan along it with pivot pv (outside the remaining hull) fills every reflex turn with a
// triangle and leaves the convex hull of the remaining points, collinear points kept on it.
// A dry run first checks that every edge of the final boundary has a triangle: it fails only
// when the fan was (part of) a strip with nothing behind it, and then nothing is changed.
bool WorkMesh::removeOnHull(std::uint32_t v) {
    const std::size_t m = star_.size();
    poly_.resize(m + 1);
    outer_.resize(m);
    for (std::size_t i = 0; i < m; ++i) {
        const std::uint32_t linkEdge = nextHalfedge(star_[i]); // a_i -> a_{i+1}
        poly_[i] = triangles[linkEdge];
        outer_[i] = halfedges[linkEdge]; // a_{i+1} -> a_i in the triangle beyond, if any
    }
    poly_[m] = triangles[prevHalfedge(star_[m - 1])];

    // Dry run: which boundary edges end up with a triangle behind them.
    std::vector<std::uint32_t>& stack = prevIdx_;
    std::vector<std::uint32_t>& backed = nextIdx_; // per stack entry: its incoming edge has one
    const auto turnsRight = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        return fastOrientSign(points[a], points[b], points[c]) < 0;
    };
    stack.assign(1, poly_[m]);
    backed.assign(1, 1);
    for (std::size_t j = m; j-- > 0;) {
        const std::uint32_t c = poly_[j];
        std::uint32_t has = outer_[j] != kNoHalfedge ? 1 : 0;
        while (stack.size() >= 2 && turnsRight(stack[stack.size() - 2], stack.back(), c)) {
            stack.pop_back();
            backed.pop_back();
            has = 1;
        }
        stack.push_back(c);
        backed.push_back(has);
    }
    for (const std::uint32_t b : backed)
        if (!b) return false;

    // The real run. Vertices first get an outgoing halfedge in a triangle beyond the fan (if
    // they have one); the scan's triangles then claim theirs.
    for (const std::uint32_t e : star_) freeTriangle(e / 3);
    vertexEdge[v] = kNoHalfedge;
    for (std::size_t i = 0; i <= m; ++i) {
        if (i < m && outer_[i] != kNoHalfedge)
            vertexEdge[poly_[i]] = nextHalfedge(outer_[i]);
        else if (i > 0 && outer_[i - 1] != kNoHalfedge)
            vertexEdge[poly_[i]] = outer_[i - 1];
    }
    for (const std::uint32_t h : outer_) {
        if (h == kNoHalfedge) continue;
        halfedges[h] = kNoHalfedge; // boundary unless a scan triangle claims it below
        lastTriangle_ = h / 3;
    }
    // stack: vertices; backed: the mesh-side halfedge of the boundary edge into each vertex.
    stack.assign(1, poly_[m]);
    backed.assign(1, kNoHalfedge);
    for (std::size_t j = m; j-- > 0;) {
        const std::uint32_t c = poly_[j];
        std::uint32_t into = outer_[j];
        while (stack.size() >= 2 && turnsRight(stack[stack.size() - 2], stack.back(), c)) {
            const std::uint32_t a = stack[stack.size() - 2], b = stack.back();
            const std::uint32_t s = addTriangle(a, c, b); // s: a -> c, s+1: c -> b, s+2: b -> a
            link(s + 1, into);
            link(s + 2, backed.back());
            stack.pop_back();
            backed.pop_back();
            into = s;
        }
        stack.push_back(c);
        backed.push_back(into);
    }
    return true;
}

} // namespace fl::geom::detail
