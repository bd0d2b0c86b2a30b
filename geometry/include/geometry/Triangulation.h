#pragma once
// Flat, index-based triangle meshes (Delaunator's layout) and the exact tools the CPU steps of
// the Delaunay pipeline (thesis ch. 6: C1-C4) build, repair and check them with: halfedge
// adjacency, Lawson edge flips (C4), an invariant checker, and a simple reference Delaunay
// triangulator to compare against and fall back on. Every geometric decision uses the exact
// predicates of Predicates.h, so results do not depend on rounding.
//
// Layout: triangle t has vertices triangles[3t], triangles[3t+1], triangles[3t+2], counter-
// clockwise. Halfedge e (0 <= e < triangles.size()) runs from triangles[e] to
// triangles[nextHalfedge(e)] inside triangle e / 3; halfedges[e] is the halfedge of the adjacent
// triangle running the other way, or kNoHalfedge where e lies on the boundary.

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace fl::geom {

/// Marks a boundary halfedge in Triangulation::halfedges.
inline constexpr std::uint32_t kNoHalfedge = 0xffffffffu;

/// A triangle mesh over a point set; see the file comment for the layout.
struct Triangulation {
    std::vector<glm::dvec2> points;
    std::vector<std::uint32_t> triangles; // 3 vertex indices per triangle, counter-clockwise
    std::vector<std::uint32_t> halfedges; // opposite halfedge, or kNoHalfedge on the boundary

    /// Number of triangles.
    [[nodiscard]] std::size_t triangleCount() const { return triangles.size() / 3; }
};

/// The next halfedge (counter-clockwise) within the same triangle.
[[nodiscard]] constexpr std::uint32_t nextHalfedge(std::uint32_t e) {
    return e % 3 == 2 ? e - 2 : e + 1;
}
/// The previous halfedge within the same triangle.
[[nodiscard]] constexpr std::uint32_t prevHalfedge(std::uint32_t e) {
    return e % 3 == 0 ? e + 2 : e - 1;
}

/// Recomputes halfedges from triangles. Throws std::invalid_argument naming the triangles when
/// an index is out of range, a triangle repeats a vertex, or a directed edge occurs twice (an
/// edge shared by more than two triangles, or two neighbours with opposite orientations).
void buildHalfedges(Triangulation& mesh);

/// Thesis step C4: flips edges until every interior edge is locally Delaunay under the exact
/// incircle test, and returns the number of flips. Builds halfedges first if their count does
/// not match the triangles. An edge is flipped only when the opposite vertex lies strictly
/// inside the circumcircle (and its quadrilateral is strictly convex, which then always holds
/// for a valid triangulation), so every flip lowers the lifted surface and at most
/// n(n-1)/2 flips happen; cocircular points (grids) therefore terminate too. Throws
/// std::runtime_error if that bound is exceeded, which only an invalid mesh can cause.
std::size_t legalize(Triangulation& mesh);

/// What checkTriangulation verifies beyond the always-checked structure.
struct TriangulationCheckOptions {
    bool requireDelaunay = true;      // every interior edge locally Delaunay (exact incircle <= 0)
    bool allowDuplicatePoints = true; // an unused point equal to a used one is not a problem
    std::size_t maxMessages = 32;     // problems listed in full; counts keep going beyond
};

/// checkTriangulation's findings: counts per kind of problem plus readable messages.
struct TriangulationReport {
    std::vector<std::string> problems; // at most maxMessages, most basic first
    std::size_t problemCount = 0;      // all problems, listed or not

    std::size_t badIndices = 0;              // vertex index out of range or repeated in a triangle
    std::size_t badOrientation = 0;          // clockwise or degenerate (zero-area) triangles
    std::size_t badHalfedges = 0;            // halfedges inconsistent with the triangles
    std::size_t nonManifoldEdges = 0;        // directed edge in two triangles
    std::size_t nonDelaunayEdges = 0;        // interior edges failing the exact incircle test
    std::size_t hullProblems = 0;            // boundary is not the convex hull of the points
    bool eulerMismatch = false;              // V - E + F != 1
    std::vector<std::uint32_t> unusedPoints; // in no triangle (duplicates excluded)
    std::vector<std::uint32_t> duplicatePoints; // unused, and equal to a used point

    std::size_t vertices = 0; // used points
    std::size_t edges = 0;    // undirected edges
    std::size_t boundaryEdges = 0;
    std::size_t triangles = 0;

    /// True when no problem was found.
    [[nodiscard]] bool ok() const { return problemCount == 0; }
    /// The counts and the listed problems as one multi-line string (for test failures, logs).
    [[nodiscard]] std::string summary() const;
};

/// Checks a mesh against every invariant of a triangulation of its point set: index ranges;
/// every triangle counter-clockwise and non-degenerate (exact orient2d); halfedges consistent
/// (and rebuilt independently, so missing or non-manifold adjacency shows); V - E + F = 1 over
/// used vertices; every point used (duplicates reported separately); the boundary one closed
/// convex cycle equal to the convex hull of all points (collinear points on hull edges allowed);
/// and, unless disabled, every interior edge locally Delaunay under exact incircle.
[[nodiscard]] TriangulationReport checkTriangulation(const Triangulation& mesh,
                                                     const TriangulationCheckOptions& options = {});

/// A point that delaunayReference left out because an earlier point has the same coordinates.
struct DuplicatePoint {
    std::uint32_t index; // the skipped point
    std::uint32_t kept;  // the lowest index with the same coordinates, which is triangulated
};

/// A simple, exact Delaunay triangulation for tests and fallbacks: incremental insertion in
/// Hilbert-curve order with a visibility walk and Lawson flips (expected ~O(n log n); 100k
/// uniform points take well under a second in Release). The result keeps all input points and
/// indices; of equal points only the lowest index is used, the others are listed in
/// `duplicates` when given. Cocircular points get an arbitrary valid Delaunay triangulation.
/// Throws std::invalid_argument for non-finite coordinates, fewer than 3 distinct points, all
/// points collinear, or more than 2^32 - 2 points.
[[nodiscard]] Triangulation delaunayReference(const std::vector<glm::dvec2>& points,
                                              std::vector<DuplicatePoint>* duplicates = nullptr);

} // namespace fl::geom
