#pragma once
// Private to the Delaunay pipeline: the CPU steps C1-C4 of the thesis (§6.3.3) and the fallback,
// each in its own file (DelaunayHull.cpp, DelaunayShift.cpp, DelaunayInsert.cpp with
// DelaunayInsertParallel.cpp, DelaunayFlipParallel.cpp); the driver (Delaunay.cpp) runs them in
// order, times them and keeps the stages.

#include <geometry/detail/DelaunayMesh.h>

#include <geometry/DiscreteDelaunay.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace fl::geom::detail {

/// C1: walks the border of the G3 texture counterclockwise from the lowest site and, Graham-
/// style, appends a triangle to `tris` for every clockwise turn of three consecutive border
/// sites (pixel positions, exact integers). Returns the number added, or nothing when the
/// discrete result carries no texture to walk.
std::optional<std::size_t> completeHull(const DiscreteDelaunay& discrete,
                                        std::vector<std::uint32_t>& tris);

/// What C2 did.
struct ShiftStats {
    std::size_t good = 0;                // moved in place (cases 1a, 4a)
    std::size_t bad = 0;                 // removed and re-inserted (1b-3, 4b), deferred included
    std::vector<std::uint32_t> deferred; // landed on a not yet shifted site: C3 inserts them
    bool stuck = false;                  // a removal would have emptied the mesh (fallback)
};

/// C2: moves every site in `order` from its current position in `mesh` to targets[v].
ShiftStats shiftSites(WorkMesh& mesh, const std::vector<glm::dvec2>& targets,
                      const std::vector<std::uint32_t>& order);

/// C3: inserts each site of `sites` at mesh.points[site] by the incremental Delaunay algorithm
/// (Lawson flips around each new site), in insertionOrder(); each locate walk starts at the
/// previously inserted site or at `near[i]` (the site that kept its pixel), whichever is nearer.
/// With more than one of `threads` (0 = all) and at least kMinParallelInsert sites, the strips of
/// insertInStrips() go first and the sites they leave follow one by one. Returns the number of
/// sites inserted one by one.
std::size_t insertSites(WorkMesh& mesh, const std::vector<std::uint32_t>& sites,
                        const std::vector<std::uint32_t>& near, int threads = 1);

/// Fewest sites for which C3 uses threads.
inline constexpr std::size_t kMinParallelInsert = 4096;

/// C3's parallel part (DelaunayInsertParallel.cpp): one strip of the sites per thread, each
/// inserted by its thread as insertSites does, as long as it needs only triangles whose vertices
/// all lie in its strip. Returns the indices (into sites) left for the sequential pass, in the
/// order of `order` (an insertionOrder() of all indices). The mesh stays a triangulation, locally
/// Delaunay except maybe along the strips' borders.
std::vector<std::uint32_t> insertInStrips(WorkMesh& mesh, const std::vector<std::uint32_t>& sites,
                                          const std::vector<std::uint32_t>& near,
                                          const std::vector<std::uint32_t>& order, int threads);

/// C4: Lawson flips until every edge of `mesh` (compacted) is locally Delaunay; returns the
/// number of flips. With more than one of `threads` (0 = all) and at least kMinParallelFlip
/// triangles, failingEdges() tests every edge on the threads first and the flips start from
/// the edges that failed; otherwise WorkMesh::makeDelaunay().
std::size_t flipToDelaunay(WorkMesh& mesh, int threads);

/// Fewest triangles for which C4 uses threads.
inline constexpr std::size_t kMinParallelFlip = 65536;

/// C4's parallel part (DelaunayFlipParallel.cpp): every interior edge of `mesh` (compacted)
/// that is not locally Delaunay, once each (its lower halfedge), in ascending order; read-only,
/// on `threads` threads (0 = all).
std::vector<std::uint32_t> failingEdges(const WorkMesh& mesh, int threads);

/// A point to order and the index it stands for.
struct OrderItem {
    glm::dvec2 p;
    std::uint32_t index;
};

/// Reorders `items` (distinct positions) into a biased randomized insertion order whose rounds
/// follow a Hilbert curve: short walks, linear expected work. Deterministic: the same order on
/// any number of `threads` (0 = all), which sort the largest rounds' Hilbert quadrants side by
/// side.
void insertionOrder(std::vector<OrderItem>& items, int threads = 1);

/// The fallback when the discrete result cannot be completed (too few or collinear pixels, a
/// T' that fails the degree argument, a removal with nothing left): the incremental Delaunay
/// algorithm over `sites` (distinct, not all collinear) at mesh.points, in the order given.
void rebuild(WorkMesh& mesh, const std::vector<std::uint32_t>& sites);

} // namespace fl::geom::detail
