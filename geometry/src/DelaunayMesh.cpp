// WorkMesh: slots, navigation, point location and insertion (thesis §6.3.3, the operations
// steps C2 and C3 are made of). Removal is in DelaunayRemove.cpp, building and checking in
// DelaunayMeshCheck.cpp.
#include <geometry/detail/DelaunayMesh.h>

#include "TriangulationWalk.h"
#include <geometry/detail/TriangulationFlip.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace fl::geom::detail {

using glm::dvec2;

bool strictlyBetween(dvec2 a, dvec2 b, dvec2 c) {
    // Collinear points: b is between a and c iff it is on every axis (comparisons are exact).
    const auto inside = [](double lo, double x, double hi) {
        return (lo < x && x < hi) || (hi < x && x < lo) || (lo == x && x == hi);
    };
    return b != a && b != c && inside(a.x, b.x, c.x) && inside(a.y, b.y, c.y);
}

bool convexTurn(dvec2 a, dvec2 b, dvec2 c) {
    const int s = fastOrientSign(a, b, c);
    return s > 0 || (s == 0 && strictlyBetween(a, b, c));
}

WorkMesh::WorkMesh(std::vector<dvec2> pts, int threads)
    : points(std::move(pts)), vertexEdge(points.size(), kNoHalfedge), threads_(threads) {}

std::uint32_t WorkMesh::addTriangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    std::uint32_t t;
    if (!freeSlots_.empty()) {
        t = freeSlots_.back();
        freeSlots_.pop_back();
        triangles[3 * t] = a;
        triangles[3 * t + 1] = b;
        triangles[3 * t + 2] = c;
        halfedges[3 * t] = halfedges[3 * t + 1] = halfedges[3 * t + 2] = kNoHalfedge;
    } else {
        t = static_cast<std::uint32_t>(triangles.size() / 3);
        triangles.insert(triangles.end(), {a, b, c});
        halfedges.insert(halfedges.end(), {kNoHalfedge, kNoHalfedge, kNoHalfedge});
    }
    touch(t);
    lastTriangle_ = t;
    return 3 * t;
}

void WorkMesh::freeTriangle(std::uint32_t t) {
    triangles[3 * t] = kFreeSlot;
    freeSlots_.push_back(t);
}

void WorkMesh::link(std::uint32_t a, std::uint32_t b) {
    halfedges[a] = b;
    if (b != kNoHalfedge) halfedges[b] = a;
}

void WorkMesh::touch(std::uint32_t t) {
    for (std::uint32_t e = 3 * t; e < 3 * t + 3; ++e) vertexEdge[triangles[e]] = e;
}

bool WorkMesh::fan(std::uint32_t v, std::vector<std::uint32_t>& out) const {
    out.clear();
    const std::uint32_t e0 = vertexEdge[v];
    // Counterclockwise from vertexEdge (on the hull usually the boundary halfedge already).
    for (std::uint32_t e = e0;;) {
        out.push_back(e);
        const std::uint32_t twin = halfedges[prevHalfedge(e)];
        if (twin == e0) return false; // closed: an interior vertex
        if (twin == kNoHalfedge) break;
        e = twin;
    }
    // Open: the triangles clockwise of e0 go in front, the outermost first.
    const std::size_t ccwPart = out.size();
    for (std::uint32_t e = e0; halfedges[e] != kNoHalfedge;) {
        e = nextHalfedge(halfedges[e]);
        out.push_back(e);
    }
    std::reverse(out.begin() + std::ptrdiff_t(ccwPart), out.end());
    std::rotate(out.begin(), out.begin() + std::ptrdiff_t(ccwPart), out.end());
    return true;
}

std::uint32_t WorkMesh::nextBoundary(std::uint32_t e) const {
    std::uint32_t g = nextHalfedge(e);
    while (halfedges[g] != kNoHalfedge) g = nextHalfedge(halfedges[g]);
    return g;
}

std::uint32_t WorkMesh::prevBoundary(std::uint32_t e) const {
    std::uint32_t g = prevHalfedge(e);
    while (halfedges[g] != kNoHalfedge) g = prevHalfedge(halfedges[g]);
    return g;
}

Location WorkMesh::locate(dvec2 q, std::uint32_t start) {
    std::uint32_t t = start;
    if (3 * t >= triangles.size() || triangles[3 * t] == kFreeSlot) t = lastTriangle_;
    // A walk longer than a scan of everything is not worth continuing.
    const WalkEnd end = visibilityWalk(
        triangles, halfedges, t, q, 1024 + liveTriangles(), random_,
        [this](std::uint32_t a, std::uint32_t b, dvec2 p) { return orient(a, b, p); });
    walkSteps += end.steps;
    using Kind = WalkEnd::Kind;
    if (end.kind == Kind::TooLong) return scanLocate(q);
    if (end.kind == Kind::Outside) return {Location::Kind::Outside, end.edge};
    lastTriangle_ = end.triangle;
    if (end.kind == Kind::Inside) return {Location::Kind::Inside, end.triangle};
    if (end.kind == Kind::OnEdge) return {Location::Kind::OnEdge, end.edge};
    for (std::uint32_t e = 3 * end.triangle; e < 3 * end.triangle + 3; ++e)
        if (points[triangles[e]] == q) return {Location::Kind::OnVertex, triangles[e]};
    throw std::logic_error("delaunay: point location found a degenerate triangle");
}

// Exhaustive location: the safety net behind the walk (never reached in the tests).
Location WorkMesh::scanLocate(dvec2 q) const {
    for (std::uint32_t t = 0; 3 * t < triangles.size(); ++t) {
        if (triangles[3 * t] == kFreeSlot) continue;
        int zeros = 0;
        std::uint32_t onEdge = kNoHalfedge;
        bool inside = true;
        for (std::uint32_t e = 3 * t; e < 3 * t + 3 && inside; ++e) {
            const int s = orient(triangles[e], triangles[nextHalfedge(e)], q);
            inside = s >= 0;
            if (s == 0) {
                ++zeros;
                onEdge = e;
            }
        }
        if (!inside) continue;
        if (zeros == 0) return {Location::Kind::Inside, t};
        if (zeros == 1) return {Location::Kind::OnEdge, onEdge};
        for (std::uint32_t e = 3 * t; e < 3 * t + 3; ++e)
            if (points[triangles[e]] == q) return {Location::Kind::OnVertex, triangles[e]};
    }
    // Outside the convex hull: every boundary edge with q strictly beyond it sees q.
    for (std::uint32_t e = 0; e < halfedges.size(); ++e)
        if (triangles[3 * (e / 3)] != kFreeSlot && halfedges[e] == kNoHalfedge &&
            orient(triangles[e], triangles[nextHalfedge(e)], q) < 0)
            return {Location::Kind::Outside, e};
    throw std::logic_error("delaunay: point location failed (the mesh is not a triangulation)");
}

void WorkMesh::insert(std::uint32_t v, Location where, bool delaunay) {
    switch (where.kind) {
    case Location::Kind::Inside:
        insertInside(where.id, v);
        break;
    case Location::Kind::OnEdge:
        insertOnEdge(where.id, v);
        break;
    case Location::Kind::Outside:
        insertOutside(where.id, v);
        break;
    case Location::Kind::OnVertex:
        throw std::logic_error("delaunay: inserting a point onto an existing vertex");
    }
    if (delaunay)
        restoreDelaunay();
    else
        pending_.clear();
}

void WorkMesh::insertInside(std::uint32_t t, std::uint32_t v) {
    splitInside(
        t, v,
        [this](std::uint32_t a, std::uint32_t b, std::uint32_t c) { return addTriangle(a, b, c); },
        pending_);
    lastTriangle_ = t;
}

void WorkMesh::insertOnEdge(std::uint32_t e, std::uint32_t v) {
    splitOnEdge(
        e, v,
        [this](std::uint32_t a, std::uint32_t b, std::uint32_t c) { return addTriangle(a, b, c); },
        pending_);
    lastTriangle_ = e / 3;
}

// v strictly outside the hull, beyond boundary edge e: v is joined to the whole chain of hull
// edges that see it (contiguous, as the hull is convex), one triangle per edge. Edges with v on
// their line do not see it, so collinear hull points stay on the hull, passed straight on.
void WorkMesh::insertOutside(std::uint32_t e, std::uint32_t v) {
    const dvec2 pv = points[v];
    const auto sees = [&](std::uint32_t h) {
        return orient(triangles[h], triangles[nextHalfedge(h)], pv) < 0;
    };
    std::uint32_t first = e;
    for (std::uint32_t h = prevBoundary(first); h != e && sees(h); h = prevBoundary(h)) first = h;
    std::vector<std::uint32_t>& chain = poly_;
    chain.clear();
    chain.push_back(first);
    for (std::uint32_t h = first; h != e;) chain.push_back(h = nextBoundary(h));
    for (std::uint32_t h = nextBoundary(e); h != first && sees(h); h = nextBoundary(h))
        chain.push_back(h);

    std::uint32_t previous = kNoHalfedge; // v -> u of the previous new triangle
    for (const std::uint32_t h : chain) {
        const std::uint32_t u = triangles[h], w = triangles[nextHalfedge(h)];
        const std::uint32_t s = addTriangle(w, u, v); // s: w -> u, s+1: u -> v, s+2: v -> w
        link(s, h);
        link(s + 1, previous);
        pending_.push_back(s);
        previous = s + 2;
    }
}

void WorkMesh::restoreDelaunay() {
    const auto noBoundaryTracking = [](std::uint32_t) {};
    while (!pending_.empty()) {
        const std::uint32_t e = pending_.back();
        pending_.pop_back();
        if (halfedges[e] == kNoHalfedge || !needsFlip(e)) continue;
        const std::uint32_t o = halfedges[e];
        flip(triangles, halfedges, e, noBoundaryTracking);
        ++insertFlips;
        touch(e / 3);
        touch(o / 3);
        pending_.insert(pending_.end(), {e, prevHalfedge(e), o, prevHalfedge(o)});
    }
}

bool WorkMesh::needsFlip(std::uint32_t e) const {
    return halfedges[e] != kNoHalfedge && shouldFlip(points, triangles, halfedges, e);
}

std::size_t WorkMesh::flipLimit() const {
    // Each flip lowers the lifted surface for good, so a triangulation needs at most one flip
    // per pair of points; more means the mesh was broken.
    const std::size_t n = points.size();
    return n < 2 ? 0 : n * (n - 1) / 2;
}

std::size_t WorkMesh::legalize(std::uint32_t e, std::size_t flips) {
    const std::size_t limit = flipLimit();
    const auto noBoundaryTracking = [](std::uint32_t) {};
    std::vector<std::uint32_t>& stack = pending_;
    stack.push_back(e);
    while (!stack.empty()) {
        const std::uint32_t h = stack.back();
        stack.pop_back();
        if (!needsFlip(h)) continue;
        const std::uint32_t o = halfedges[h];
        flip(triangles, halfedges, h, noBoundaryTracking);
        if (++flips > limit)
            throw std::runtime_error("delaunay: more than n(n-1)/2 = " + std::to_string(limit) +
                                     " flips; the mesh is not a triangulation");
        stack.insert(stack.end(), {h, prevHalfedge(h), o, prevHalfedge(o)});
    }
    return flips;
}

std::size_t WorkMesh::makeDelaunay() {
    // Each edge once, from its lower slot. An edge that passes and is never touched by a flip
    // stays locally Delaunay; one that a flip touches is re-tested from the stack.
    pending_.clear();
    std::size_t flips = 0;
    for (std::uint32_t e = 0; e < halfedges.size(); ++e) {
        const std::uint32_t twin = halfedges[e];
        if (twin != kNoHalfedge && twin > e) flips = legalize(e, flips);
    }
    return flips;
}

std::size_t WorkMesh::flipFrom(const std::vector<std::uint32_t>& edges, std::size_t flips) {
    pending_.clear();
    for (const std::uint32_t e : edges) flips = legalize(e, flips);
    return flips;
}

void WorkMesh::compact() {
    if (freeSlots_.empty()) return;
    const std::size_t slots = triangles.size() / 3;
    std::vector<std::uint32_t> to(slots, kFreeSlot);
    std::uint32_t live = 0;
    for (std::size_t t = 0; t < slots; ++t)
        if (triangles[3 * t] != kFreeSlot) to[t] = live++;
    const auto map = [&](std::uint32_t e) {
        return e == kNoHalfedge ? kNoHalfedge : 3 * to[e / 3] + e % 3;
    };
    for (std::size_t t = 0; t < slots; ++t) {
        if (to[t] == kFreeSlot) continue;
        for (std::uint32_t k = 0; k < 3; ++k) {
            triangles[3 * to[t] + k] = triangles[3 * t + k];
            halfedges[3 * to[t] + k] = map(halfedges[3 * t + k]);
        }
    }
    triangles.resize(3 * std::size_t{live});
    halfedges.resize(3 * std::size_t{live});
    for (std::uint32_t& e : vertexEdge) e = map(e);
    lastTriangle_ = to[lastTriangle_] == kFreeSlot ? 0 : to[lastTriangle_];
    freeSlots_.clear();
}

} // namespace fl::geom::detail
