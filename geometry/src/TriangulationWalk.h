#pragma once
// Point location by a stochastic visibility walk on the flat halfedge layout, shared by the
// incremental reference triangulator (DelaunayReference.cpp) and the pipeline's WorkMesh.

#include <geometry/Triangulation.h>

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace fl::geom::detail {

/// Where a visibility walk stopped.
struct WalkEnd {
    enum class Kind : std::uint8_t {
        Inside,   // strictly inside `triangle`
        OnEdge,   // strictly inside the edge of halfedge `edge` (of `triangle`)
        OnCorner, // on two edge lines of `triangle`: on one of its vertices (or it is flat)
        Outside,  // outside the hull, strictly beyond the boundary halfedge `edge`
        TooLong,  // no answer within the step limit
        Refused,  // the walk reached `triangle`, which the caller's `enter` refused
    };
    Kind kind = Kind::Inside;
    std::uint32_t triangle = 0; // the triangle the walk stopped in
    std::uint32_t edge = 0;     // OnEdge, Outside
    std::size_t steps = 0;      // triangles visited
};

/// visibilityWalk's default `enter`: every triangle.
struct EnterAny {
    constexpr bool operator()(std::uint32_t) const { return true; }
};

/// Walks from triangle t toward q, stepping into the neighbour across any edge that has q
/// strictly on its far side (orient(a, b, q) < 0 for the edge a -> b; exact signs). In a
/// Delaunay triangulation this cannot cycle; starting each test at a pseudo-random edge (xorshift32
/// state `random`) makes that hold for any triangulation with probability 1, and `stepLimit`
/// lets the caller turn a broken mesh into a fallback or an exception instead of a hang.
/// `enter(t)` is asked before each triangle is visited (C3's strips refuse the triangles of
/// other threads); a refused triangle ends the walk, not counted as a step.
template <class Orient, class Enter = EnterAny>
WalkEnd visibilityWalk(const std::vector<std::uint32_t>& triangles,
                       const std::vector<std::uint32_t>& halfedges, std::uint32_t t, glm::dvec2 q,
                       std::size_t stepLimit, std::uint32_t& random, const Orient& orient,
                       const Enter& enter = {}) {
    using Kind = WalkEnd::Kind;
    for (std::size_t step = 1; step <= stepLimit; ++step) {
        if (!enter(t)) return {Kind::Refused, t, kNoHalfedge, step - 1};
        random ^= random << 13;
        random ^= random >> 17;
        random ^= random << 5;
        const std::uint32_t first = random % 3;
        std::uint32_t onEdge = kNoHalfedge;
        int zeros = 0;
        bool moved = false;
        for (std::uint32_t k = 0; k < 3 && !moved; ++k) {
            const std::uint32_t e = 3 * t + (first + k) % 3;
            const int s = orient(triangles[e], triangles[nextHalfedge(e)], q);
            if (s < 0) {
                if (halfedges[e] == kNoHalfedge) return {Kind::Outside, t, e, step};
                t = halfedges[e] / 3;
                moved = true;
            } else if (s == 0) {
                ++zeros;
                onEdge = e;
            }
        }
        if (moved) continue;
        if (zeros == 0) return {Kind::Inside, t, kNoHalfedge, step};
        if (zeros == 1) return {Kind::OnEdge, t, onEdge, step};
        return {Kind::OnCorner, t, kNoHalfedge, step};
    }
    return {Kind::TooLong, t, kNoHalfedge, stepLimit};
}

} // namespace fl::geom::detail
