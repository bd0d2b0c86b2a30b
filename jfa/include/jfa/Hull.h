#pragma once
// Planar convex hulls (Andrew's monotone chain) with exact orientation tests, used by the JFA
// error analysis to count Delaunay triangles (2m - 2 - b, b = sites on the hull boundary).
//
// Exactness: integer points use 64-bit arithmetic and are exact for |coordinate| <= 2^29 (the
// functions throw std::invalid_argument beyond that). Real points use expansion arithmetic
// (exact products and sums of doubles, Shewchuk-style) and are exact for any finite coordinates
// whose pairwise products neither overflow nor underflow: |v| in [2^-400, 2^500] or 0, which
// covers every float site position; other coordinates throw std::invalid_argument.

#include <cstdint>
#include <span>
#include <vector>

namespace fl::jfa {

/// A point with integer coordinates.
struct IntPoint {
    std::int64_t x = 0;
    std::int64_t y = 0;
    friend bool operator==(const IntPoint&, const IntPoint&) = default;
};

/// A point with real coordinates (e.g. float site positions widened without rounding).
struct RealPoint {
    double x = 0.0;
    double y = 0.0;
    friend bool operator==(const RealPoint&, const RealPoint&) = default;
};

/// What a hull keeps of the points lying on its boundary.
enum class HullBoundary {
    Vertices,      // strictly convex corners only (collinear boundary points dropped)
    KeepCollinear, // every distinct input point on the boundary, corners and edge points
};

/// Sign of the turn a -> b -> c: +1 counter-clockwise, -1 clockwise, 0 collinear (exact).
int orientation(IntPoint a, IntPoint b, IntPoint c);
/// Sign of the turn a -> b -> c for real points (exact within the range in the header comment).
int orientation(RealPoint a, RealPoint b, RealPoint c);

/// Convex hull counter-clockwise from the lowest-x (then lowest-y) point; duplicates removed.
/// Degenerate inputs: none -> {}, one distinct point -> {p}, all collinear -> the two extreme
/// points (Vertices) or every distinct point sorted along the line (KeepCollinear).
std::vector<IntPoint> convexHull(std::span<const IntPoint> points,
                                 HullBoundary keep = HullBoundary::Vertices);
/// Same for real points.
std::vector<RealPoint> convexHull(std::span<const RealPoint> points,
                                  HullBoundary keep = HullBoundary::Vertices);

/// Number of triangles of any triangulation of the points (Delaunay included): 2m - 2 - b with m
/// distinct points and b of them on the hull boundary; 0 when m < 3 or all points are collinear.
std::int64_t triangulationTriangleCount(std::span<const IntPoint> points);
/// Same for real points.
std::int64_t triangulationTriangleCount(std::span<const RealPoint> points);

} // namespace fl::jfa
