#pragma once
// The exact repair behind `voronoi --exact`: a flood's answer per texel is
// corrected to a truly nearest site by a greedy walk on a graph of the sites, on the CPU here and
// by a GL compute twin (GlExactRepair, jfa_gl/GlExactRepair.h) that does the same texel for texel.
//
// The walk. Texel p starts at the graph vertex its flooded cell names (cell.w, see SiteGraph),
// or at vertex 0 if the cell is empty, and moves to the best neighbour under NearestSite::better
// (distance, then id, y, x) while that neighbour is strictly better than where it stands. Every
// move is strictly better under a strict total order, so the walk ends, after at most
// vertices.size() - 1 moves; its end is the same whatever order neighbours are read in. A texel
// whose flooded cell lies at distance 0 is a site's own pixel and is kept as it is.
//
// Why the end is a nearest site (the graph's contract). The graph of geom::buildSiteGraph
// (geometry/SiteGraph.h) is a Delaunay triangulation of the sites that can be nearest to a
// non-site pixel (or, when those are collinear, their chain in order along the line); the
// Voronoi diagram below is that of the graph's sites. Let s be a vertex and p a point with a
// strictly nearer vertex. Walk from s towards p: the segment leaves the closed Voronoi cell of s
// at a point x != p, and the sites nearest to x lie on an empty circle C centred at x, through s
// and at least one other site. Every point of C other than s is strictly nearer to p than s is
// (s is the point of C farthest from p, since p lies on the ray from s through the centre x). If
// s shares C with one site u, su is a Delaunay edge; if with several, they form a convex polygon
// whose sides are Delaunay edges in every Delaunay triangulation (each side has an empty circle
// through its two ends only), and the two sides at s give s a neighbour on C. Either way s has a
// neighbour strictly nearer to p, so a walk stops only at a vertex nearest to p. On a line,
// distance along the chain is strictly convex: the same conclusion. Hence the repaired grid has
// 0 error pixels (jfa::countErrors) whatever the flood left elsewhere, provided each site's own
// pixel holds that site, as every flood of the seeds does (distance 0 is never beaten); a good
// flood only makes the walks short (most texels stop after reading their start's neighbours).

#include <jfa/Grid.h>
#include <jfa/NearestSite.h>

#include <cstdint>
#include <vector>

namespace fl::jfa {

/// A graph on (some of) the sites that a greedy walk finds nearest sites on (see the file
/// comment for the property it must have). Vertex v is the site vertices[v], whose cell's w
/// holds v; seeds tagged for a repair hold in w the vertex a walk from them starts at.
struct SiteGraph {
    std::vector<Cell> vertices;
    /// Compressed rows: the neighbours of v are neighbours[offsets[v] .. offsets[v + 1]).
    std::vector<std::uint32_t> offsets{0};
    std::vector<std::uint32_t> neighbours;
};

/// The walk's end for grid point (px, py) starting from flooded cell `start` (file comment):
/// the cell of a nearest site. Integer sites only (NearestSite{true}).
Cell walkToNearest(const SiteGraph& graph, int px, int py, const Cell& start);

/// How repairNearest finds each texel's walk end (the same result either way; tests check it).
enum class RepairMethod {
    Walks,        // walkToNearest for every texel (the definition)
    RowIntervals, // per row and start vertex, the texels inside its graph Voronoi cell (one
                  // integer interval, computed once per run of texels) take it without a walk
};

/// Repairs a flooded grid in place: every texel becomes walkToNearest of its cell. Rows are
/// split among `threads` (0 = all cores). Throws std::invalid_argument if a cell names a vertex
/// the graph does not have.
void repairNearest(Grid& flooded, const SiteGraph& graph, int threads = 0,
                   RepairMethod method = RepairMethod::RowIntervals);

} // namespace fl::jfa
