// delaunayReference: incremental Delaunay insertion (Lawson 1977; Guibas-Stolfi style flips)
// with exact predicates. Chosen for being easy to convince oneself of, not for speed: every
// insertion leaves a Delaunay triangulation of the points inserted so far, so the walk that
// locates the next point terminates and the result needs no repair.

#include <geometry/Predicates.h>
#include <geometry/Triangulation.h>

#include "TriangulationWalk.h"
#include <geometry/detail/TriangulationFlip.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

namespace fl::geom {
namespace {

using glm::dvec2;

// Position along a Hilbert curve over a 2^16 x 2^16 grid (the classic xy -> d conversion).
// Inserting in this order keeps consecutive points close, so walks are short.
std::uint64_t hilbertIndex(std::uint32_t x, std::uint32_t y) {
    constexpr std::uint32_t n = 1u << 16;
    std::uint64_t d = 0;
    for (std::uint32_t s = n / 2; s > 0; s /= 2) {
        const std::uint32_t rx = (x & s) ? 1 : 0;
        const std::uint32_t ry = (y & s) ? 1 : 0;
        d += std::uint64_t{s} * s * ((3 * rx) ^ ry);
        if (ry == 0) {
            if (rx == 1) {
                x = n - 1 - x;
                y = n - 1 - y;
            }
            std::swap(x, y);
        }
    }
    return d;
}

// Orders `ids` along the Hilbert curve of their bounding box. Only the order matters here, so
// rounding is harmless; halves keep extreme coordinates from overflowing the box size.
void hilbertSort(const std::vector<dvec2>& pts, std::vector<std::uint32_t>& ids) {
    dvec2 lo = pts[ids.front()], hi = lo;
    for (const std::uint32_t i : ids) {
        lo = glm::min(lo, pts[i]);
        hi = glm::max(hi, pts[i]);
    }
    const dvec2 halfSize = hi * 0.5 - lo * 0.5;
    const auto cell = [](double v, double lo2, double size2) {
        if (!(size2 > 0.0)) return std::uint32_t{0};
        const double t = (v * 0.5 - lo2) / size2 * 65536.0;
        return static_cast<std::uint32_t>(std::clamp(t, 0.0, 65535.0));
    };
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(ids.size());
    for (std::size_t k = 0; k < ids.size(); ++k) {
        const dvec2 p = pts[ids[k]];
        keyed[k] = {
            hilbertIndex(cell(p.x, lo.x * 0.5, halfSize.x), cell(p.y, lo.y * 0.5, halfSize.y)),
            ids[k]};
    }
    std::sort(keyed.begin(), keyed.end());
    for (std::size_t k = 0; k < ids.size(); ++k) ids[k] = keyed[k].second;
}

class Builder {
  public:
    explicit Builder(const std::vector<dvec2>& points)
        : pts_(points), hullNext_(points.size(), kNoHalfedge),
          hullPrev_(points.size(), kNoHalfedge), hullEdge_(points.size(), kNoHalfedge) {}

    void seed(std::uint32_t a, std::uint32_t b, std::uint32_t c); // counter-clockwise
    void insert(std::uint32_t x);

    std::vector<std::uint32_t> triangles;
    std::vector<std::uint32_t> halfedges;

  private:
    enum class Where { Inside, OnEdge, Outside };
    struct Location {
        Where where;
        std::uint32_t id; // triangle (Inside) or halfedge (OnEdge, Outside)
    };

    Location locate(dvec2 x);
    void insertInside(std::uint32_t t, std::uint32_t x);
    void insertOnEdge(std::uint32_t e, std::uint32_t x);
    void insertOutside(std::uint32_t e, std::uint32_t x);
    void restoreDelaunay();

    std::uint32_t addTriangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        const auto base = static_cast<std::uint32_t>(triangles.size());
        triangles.insert(triangles.end(), {a, b, c});
        halfedges.insert(halfedges.end(), {kNoHalfedge, kNoHalfedge, kNoHalfedge});
        return base;
    }
    // Links two halfedges; a boundary halfedge becomes its start vertex's hull edge.
    void link(std::uint32_t a, std::uint32_t b) {
        detail::link(halfedges, a, b, [this](std::uint32_t h) { hullEdge_[triangles[h]] = h; });
    }
    int orient(std::uint32_t i, std::uint32_t j, dvec2 x) const {
        return orient2dSign(pts_[i], pts_[j], x);
    }

    const std::vector<dvec2>& pts_;
    // The hull as a doubly linked cycle of vertices (counter-clockwise), and for each hull
    // vertex v the boundary halfedge v -> hullNext_[v]. kNoHalfedge off the hull.
    std::vector<std::uint32_t> hullNext_, hullPrev_, hullEdge_;
    std::vector<std::uint32_t> pending_; // halfedges to re-check for the Delaunay property
    std::uint32_t lastTriangle_ = 0;
    std::uint32_t random_ = 2463534242u; // xorshift32 state: which edge a walk tries first
};

void Builder::seed(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    addTriangle(a, b, c);
    const std::uint32_t v[3] = {a, b, c};
    for (std::uint32_t k = 0; k < 3; ++k) {
        hullNext_[v[k]] = v[(k + 1) % 3];
        hullPrev_[v[k]] = v[(k + 2) % 3];
        hullEdge_[v[k]] = k;
    }
}

// Visibility walk (TriangulationWalk.h): every insertion leaves a Delaunay triangulation, so it
// terminates; the step limit turns a bug into an exception instead of a hang.
Builder::Location Builder::locate(dvec2 x) {
    const detail::WalkEnd end = detail::visibilityWalk(
        triangles, halfedges, lastTriangle_, x, 4 * triangles.size() + 16, random_,
        [this](std::uint32_t i, std::uint32_t j, dvec2 p) { return orient(i, j, p); });
    switch (end.kind) {
    case detail::WalkEnd::Kind::Inside:
        return {Where::Inside, end.triangle};
    case detail::WalkEnd::Kind::OnEdge:
        return {Where::OnEdge, end.edge};
    case detail::WalkEnd::Kind::Outside:
        return {Where::Outside, end.edge};
    case detail::WalkEnd::Kind::OnCorner:
        throw std::logic_error(
            "delaunayReference: a point coincides with a vertex after deduplication");
    case detail::WalkEnd::Kind::TooLong:
    case detail::WalkEnd::Kind::Refused: // no `enter` given: every triangle is entered
        break;
    }
    throw std::logic_error("delaunayReference: point location did not terminate");
}

void Builder::insert(std::uint32_t x) {
    const Location loc = locate(pts_[x]);
    switch (loc.where) {
    case Where::Inside:
        insertInside(loc.id, x);
        break;
    case Where::OnEdge:
        insertOnEdge(loc.id, x);
        break;
    case Where::Outside:
        insertOutside(loc.id, x);
        break;
    }
    restoreDelaunay();
}

// Triangle (a, b, c) with x strictly inside becomes (a, b, x), (b, c, x), (c, a, x).
void Builder::insertInside(std::uint32_t t, std::uint32_t x) {
    const std::uint32_t e0 = 3 * t;
    const std::uint32_t a = triangles[e0], b = triangles[e0 + 1], c = triangles[e0 + 2];
    const std::uint32_t outerBc = halfedges[e0 + 1], outerCa = halfedges[e0 + 2];
    triangles[e0 + 2] = x;
    const std::uint32_t t1 = addTriangle(b, c, x);
    const std::uint32_t t2 = addTriangle(c, a, x);
    link(t1, outerBc);
    link(t2, outerCa);
    link(e0 + 1, t1 + 2); // b -> x  /  x -> b
    link(t1 + 1, t2 + 2); // c -> x  /  x -> c
    link(t2 + 1, e0 + 2); // a -> x  /  x -> a
    pending_.insert(pending_.end(), {e0, t1, t2});
    lastTriangle_ = t;
}

// x strictly inside edge e = p -> q: triangle (p, q, a) becomes (p, x, a), (x, q, a), and the
// triangle across, (q, p, b), becomes (q, x, b), (x, p, b); on the hull x joins it.
void Builder::insertOnEdge(std::uint32_t e, std::uint32_t x) {
    const std::uint32_t o = halfedges[e];
    const std::uint32_t eNext = nextHalfedge(e), ePrev = prevHalfedge(e);
    const std::uint32_t p = triangles[e], q = triangles[eNext], a = triangles[ePrev];
    const std::uint32_t outerQa = halfedges[eNext];
    triangles[eNext] = x;                         // e: p -> x, eNext: x -> a
    const std::uint32_t s = addTriangle(x, q, a); // s: x -> q, s + 1: q -> a, s + 2: a -> x
    link(s + 1, outerQa);
    link(eNext, s + 2);
    pending_.insert(pending_.end(), {ePrev, s + 1});
    if (o == kNoHalfedge) {
        link(e, kNoHalfedge);
        link(s, kNoHalfedge);
        hullNext_[p] = x;
        hullPrev_[x] = p;
        hullNext_[x] = q;
        hullPrev_[q] = x;
    } else {
        const std::uint32_t oNext = nextHalfedge(o), oPrev = prevHalfedge(o);
        const std::uint32_t b = triangles[oPrev];
        const std::uint32_t outerPb = halfedges[oNext];
        triangles[oNext] = x;                         // o: q -> x, oNext: x -> b
        const std::uint32_t r = addTriangle(x, p, b); // r: x -> p, r + 1: p -> b, r + 2: b -> x
        link(r + 1, outerPb);
        link(oNext, r + 2);
        link(e, r);
        link(o, s);
        pending_.insert(pending_.end(), {oPrev, r + 1});
    }
    lastTriangle_ = e / 3;
}

// x strictly outside the hull, beyond boundary edge e: join x to the whole chain of hull edges
// that see it (they are contiguous because the hull is convex), one triangle per edge.
void Builder::insertOutside(std::uint32_t e, std::uint32_t x) {
    const dvec2 px = pts_[x];
    std::uint32_t first = triangles[e], last = triangles[nextHalfedge(e)];
    while (orient(hullPrev_[first], first, px) < 0) first = hullPrev_[first];
    while (orient(last, hullNext_[last], px) < 0) last = hullNext_[last];

    std::uint32_t previous = kNoHalfedge; // slot x -> u of the previous new triangle
    std::uint32_t u = first;
    while (u != last) {
        const std::uint32_t w = hullNext_[u];
        const std::uint32_t hullEdge = hullEdge_[u];  // read before link() may overwrite it
        const std::uint32_t s = addTriangle(w, u, x); // s: w -> u, s + 1: u -> x, s + 2: x -> w
        link(s, hullEdge);
        link(s + 1, previous); // the first one (previous == none) becomes u's hull edge
        pending_.push_back(s);
        if (u != first) {
            hullNext_[u] = hullPrev_[u] = hullEdge_[u] = kNoHalfedge;
        }
        previous = s + 2;
        u = w;
    }
    link(previous, kNoHalfedge); // x -> last is x's hull edge
    hullNext_[first] = x;
    hullPrev_[x] = first;
    hullNext_[x] = last;
    hullPrev_[last] = x;
    lastTriangle_ = previous / 3;
}

void Builder::restoreDelaunay() {
    const auto trackBoundary = [this](std::uint32_t h) { hullEdge_[triangles[h]] = h; };
    while (!pending_.empty()) {
        const std::uint32_t e = pending_.back();
        pending_.pop_back();
        if (halfedges[e] == kNoHalfedge || !detail::shouldFlip(pts_, triangles, halfedges, e))
            continue;
        const std::uint32_t o = halfedges[e];
        detail::flip(triangles, halfedges, e, trackBoundary);
        pending_.insert(pending_.end(), {e, prevHalfedge(e), o, prevHalfedge(o)});
    }
}

} // namespace

Triangulation delaunayReference(const std::vector<dvec2>& points,
                                std::vector<DuplicatePoint>* duplicates) {
    // 2n - 5 triangles at most: their 6n - 15 halfedges must stay below kNoHalfedge.
    if (points.size() > 700'000'000)
        throw std::invalid_argument("delaunayReference: too many points for 32-bit indices (" +
                                    std::to_string(points.size()) + ")");
    for (std::size_t i = 0; i < points.size(); ++i)
        if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y))
            throw std::invalid_argument("delaunayReference: point " + std::to_string(i) +
                                        " has a non-finite coordinate");

    // Equal points: sort by position then index, keep the first (lowest index) of each group.
    std::vector<std::uint32_t> order(points.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](std::uint32_t i, std::uint32_t j) {
        const dvec2 a = points[i], b = points[j];
        if (a.x != b.x) return a.x < b.x;
        if (a.y != b.y) return a.y < b.y;
        return i < j;
    });
    std::vector<std::uint32_t> unique;
    if (duplicates) duplicates->clear();
    for (const std::uint32_t i : order) {
        if (!unique.empty() && points[unique.back()] == points[i]) {
            if (duplicates) duplicates->push_back({i, unique.back()});
            continue;
        }
        unique.push_back(i);
    }
    if (duplicates)
        std::sort(
            duplicates->begin(), duplicates->end(),
            [](const DuplicatePoint& a, const DuplicatePoint& b) { return a.index < b.index; });
    if (unique.size() < 3)
        throw std::invalid_argument("delaunayReference: needs at least 3 distinct points, got " +
                                    std::to_string(unique.size()));

    hilbertSort(points, unique);
    const std::uint32_t a = unique[0], b = unique[1];
    std::size_t third = 2;
    while (third < unique.size() && orient2dSign(points[a], points[b], points[unique[third]]) == 0)
        ++third;
    if (third == unique.size())
        throw std::invalid_argument("delaunayReference: all " + std::to_string(unique.size()) +
                                    " distinct points are collinear");

    Builder builder(points);
    const std::uint32_t c = unique[third];
    if (orient2dSign(points[a], points[b], points[c]) > 0)
        builder.seed(a, b, c);
    else
        builder.seed(b, a, c);
    for (std::size_t k = 2; k < unique.size(); ++k)
        if (k != third) builder.insert(unique[k]);

    Triangulation result;
    result.points = points;
    result.triangles = std::move(builder.triangles);
    result.halfedges = std::move(builder.halfedges);
    return result;
}

} // namespace fl::geom
