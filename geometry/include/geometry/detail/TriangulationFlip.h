#pragma once
// The Lawson edge flip on the flat halfedge layout, shared by legalize(), the incremental
// reference triangulator (which must also track where its boundary halfedges move) and the
// pipeline's WorkMesh.

#include <geometry/Predicates.h>
#include <geometry/Triangulation.h>

#include <geometry/detail/DelaunayPredicates.h>

#include <cstdint>
#include <vector>

namespace fl::geom::detail {

/// True when the edge of halfedge e (which must have an opposite) should be flipped: the apex
/// of the opposite triangle lies strictly inside the circumcircle of e's triangle, and both new
/// triangles would be strictly counter-clockwise. For a valid triangulation the second condition
/// follows from the first; it keeps an invalid mesh from being folded further. Exact signs, by
/// the inline front ends of DelaunayPredicates.h.
inline bool shouldFlip(const std::vector<glm::dvec2>& points,
                       const std::vector<std::uint32_t>& triangles,
                       const std::vector<std::uint32_t>& halfedges, std::uint32_t e) {
    const std::uint32_t o = halfedges[e];
    const glm::dvec2 p0 = points[triangles[e]];
    const glm::dvec2 p1 = points[triangles[nextHalfedge(e)]];
    const glm::dvec2 a = points[triangles[prevHalfedge(e)]];
    const glm::dvec2 b = points[triangles[prevHalfedge(o)]];
    if (fastIncircleSign(p0, p1, a, b) <= 0) return false;
    return fastOrientSign(p0, b, a) > 0 && fastOrientSign(p1, a, b) > 0;
}

/// Makes halfedges a and b opposite; b may be kNoHalfedge, in which case onBoundary(a) is
/// called so the caller can note that a now carries a boundary edge.
template <class OnBoundary>
void link(std::vector<std::uint32_t>& halfedges, std::uint32_t a, std::uint32_t b,
          OnBoundary&& onBoundary) {
    halfedges[a] = b;
    if (b != kNoHalfedge) {
        halfedges[b] = a;
    } else {
        onBoundary(a);
    }
}

/// Flips the edge of halfedge e (opposite o): triangles (p0, p1, a) and (p1, p0, b) become
/// (p0, b, a) and (p1, a, b). Slots e and o keep their triangles; afterwards e runs p0 -> b,
/// o runs p1 -> a, and nextHalfedge(e) / nextHalfedge(o) are the new diagonal. The edges that
/// may need re-checking are e, prevHalfedge(e), o and prevHalfedge(o).
template <class OnBoundary>
void flip(std::vector<std::uint32_t>& triangles, std::vector<std::uint32_t>& halfedges,
          std::uint32_t e, OnBoundary&& onBoundary) {
    const std::uint32_t o = halfedges[e];
    const std::uint32_t eNext = nextHalfedge(e);
    const std::uint32_t oNext = nextHalfedge(o);
    const std::uint32_t a = triangles[prevHalfedge(e)];
    const std::uint32_t b = triangles[prevHalfedge(o)];
    const std::uint32_t outerOfENext = halfedges[eNext]; // opposite of p1 -> a
    const std::uint32_t outerOfONext = halfedges[oNext]; // opposite of p0 -> b
    triangles[eNext] = b;
    triangles[oNext] = a;
    link(halfedges, e, outerOfONext, onBoundary);
    link(halfedges, o, outerOfENext, onBoundary);
    link(halfedges, eNext, oNext, onBoundary);
}

} // namespace fl::geom::detail
