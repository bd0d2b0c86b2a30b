#pragma once
// The thesis' Delaunay pipeline end to end (ch. 6): the GPU steps G1-G6 (DiscreteDelaunay.h;
// CPU backend here, a GL backend where a context exists) give T'(S'), and the CPU steps complete
// it into the exact Delaunay triangulation of the input points:
//   C1 complete the convex hull by the boundary walk;
//   C2 shift every site from its pixel to its continuous position (Fig. 6.9, cases 1a-4b);
//   C3 insert the missing sites near the site that took their pixel;
//   C4 flip edges until every edge is locally Delaunay (the flips of Triangulation.h's
//      legalize, run as one sweep over the edges).
// Every decision uses the exact predicates (Predicates.h), and every CPU step keeps a valid
// triangulation (geometry/detail/DelaunayMesh.h has the argument); with `check` the result is also
// verified by checkTriangulation(), and the pipeline throws if that fails.

#include <geometry/DiscreteDelaunay.h>
#include <geometry/Triangulation.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace fl::geom {

/// How delaunay() runs.
struct DelaunayOptions {
    DiscreteDelaunayOptions discrete; // texture size, flood plan, threads for G1-G6 and C3
    /// Runs G1-G6 instead of discreteDelaunay() (e.g. the GL backend); empty = CPU backend.
    std::function<DiscreteDelaunay(const std::vector<glm::dvec2>&, const DiscreteDelaunayOptions&)>
        discreteBackend;
    bool keepStages = false; // keep the mesh after each CPU step (for pictures), see stages
    bool check = false;      // run checkTriangulation() at the end (also counted in timings)
};

/// Wall-clock milliseconds of the CPU steps.
struct CpuTimings {
    double c1 = 0.0; // hull completion
    double c2 = 0.0; // site shifting
    double c3 = 0.0; // missing-site insertion
    double c4 = 0.0; // edge flips
    double check = 0.0;
    [[nodiscard]] double total() const { return c1 + c2 + c3 + c4; } // without the check
};

/// Counts the CPU steps report (what `floodlight delaunay` prints).
struct CpuCounts {
    std::size_t hullTriangles = 0;     // C1: triangles added to close the hull
    std::size_t goodShifts = 0;        // C2: sites moved without a local repair
    std::size_t badShifts = 0;         // C2: sites whose move needed a repair (cases of Fig. 6.9)
    std::size_t missingInserted = 0;   // C3
    std::size_t insertFlips = 0;       // C3: Lawson flips around the inserted sites
    std::size_t walkSteps = 0;         // C3: triangles its point-location walks visited
    std::size_t sequentialInserts = 0; // C3: sites inserted one by one (the rest by the threads'
                                       // strips: none with one thread or few sites)
    std::size_t duplicates = 0;        // input points equal to an earlier point (not inserted)
    std::size_t flips = 0;             // C4
    std::size_t rebuilds = 0; // 1 when T' + C1 was no triangulation of S' (too few or collinear
                              // pixels, a broken T'), or C2 would have emptied the mesh: the
                              // CPU steps then fell back to incremental Delaunay insertion
};

/// The pipeline's result: the triangulation of the input points (indices = input indices;
/// duplicates are left unused and listed), the GPU-step stages, and per-step numbers. G1-G6 run
/// on all input points (so `discrete` uses input indices too; duplicates are among its missing
/// sites); a bounding box too wide for doubles is mapped after halving the points.
struct DelaunayResult {
    Triangulation mesh;
    DiscreteDelaunay discrete;
    CpuTimings cpu;
    CpuCounts counts;
    std::vector<std::uint32_t> duplicateOf; // per input point: itself, or the earlier equal point
    /// With keepStages: the triangle lists after T' (on pixel positions), C1, C2, C3 and C4.
    std::vector<std::vector<std::uint32_t>> stages;
};

/// The CPU backend's default texture side (bench/delaunay_bench, docs/history/delaunay.md
/// "Two cores in C1-C4"). On the CPU a texel costs the G-steps about 1 us, and a site that keeps
/// its pixel costs G6, C1 and C2 more than C3 saves by not inserting it, so at 1M points the
/// smallest side was the fastest (or level) for uniform and Gaussian points alike, although 93 %
/// and 97 % of their sites lose their pixel there: on this backend the texture does not need to
/// follow the distribution. 256 still gives T' enough sites to certify and start from.
inline constexpr int kCpuDefaultTexture = 256;

/// Runs G1-G6 and C1-C4 on `points`. Throws std::invalid_argument for fewer than 3 distinct
/// points, all points collinear, a non-finite coordinate (the message names the point), more
/// than kMaxDiscreteSites points, or bad discrete options; std::runtime_error if `check` finds
/// the result wrong (a bug).
DelaunayResult delaunay(const std::vector<glm::dvec2>& points, const DelaunayOptions& options = {});

} // namespace fl::geom
