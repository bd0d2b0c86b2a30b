#pragma once
// Error analysis of JFA Voronoi diagrams (thesis §4.4 "Analysis of Errors", §4.5): which grid
// points a flood got wrong, how they cluster, whether single errors sit at Voronoi vertices
// (Property 4.1), and the estimate E of the number of errors (Properties 4.2, 4.3).
//
// Inputs are plain data, so the analysis works on any kernel's output: a flooded Grid (cell x, y
// = the site a grid point recorded, z = its id, z < 0 = empty) and the exact diagram (the sites
// and, per grid point, the exact nearest squared distance; jfa/Reference.h's siteCells() and
// ExactField::distSq provide them). Which site an exact field records on ties never matters here:
// everything below is defined through distances and nearest-site sets.
//
// Definitions (the ones the code implements):
//  * Error pixel: the grid point's squared distance to the site it recorded (cell x, y) is larger
//    than the exact nearest squared distance, in NearestSite's arithmetic (exact int64 for
//    integer sites, float without FMA otherwise). Ties count as correct: a grid point equidistant
//    from several sites may record any of them. An empty cell is an error (when sites exist).
//  * Clusters: 8-connected components of error pixels; a single error is a cluster of size 1
//    (the thesis' "all its neighbouring grid points are correct", neighbours = NB8).
//  * T(q), the nearest-site set of grid point q: every site (distinct position) at the exact
//    nearest squared distance of q, ties included, found exactly (no tolerance).
//  * Discrete Voronoi vertex: grid point p such that the union of T(q) over q in {p} and its
//    8-neighbours (those inside the grid) holds >= 3 distinct sites. This is §4.1's "itself and
//    all its neighbours belong to three or more discrete Voronoi regions" with NB8, made
//    independent of how ties are broken. NB8 (not NB4) because the proof of Property 4.1 ends
//    with type-d paths, whose last step comes from the diagonal neighbours.
//    Property 4.1 ("a single error is a Voronoi vertex") is measured here, not assumed. Its proof
//    says the nearest site r of p was killed at both predecessors p', p'' (the grid points all
//    of r's paths reach p from, Property 3.3) by two different sites. At the grid border one
//    predecessor can lie outside the grid; r is then "killed by the boundary" (the thesis' own
//    caveat after E) and the single error need not be a vertex, so the report counts border and
//    interior singles apart. Measured (JFA, 512x512, integer sites, seeds 1..200 per count):
//    every single error off a vertex lay on the grid border (0 interior exceptions in 600 runs,
//    none either in 480 runs of JFA+1, JFA+2, 1+JFA, JFA^2); the share of all singles at vertices
//    was 65% (100 sites), 88% (1000), 97% (10000), rising with m as §4.4 says.
//  * Estimate E (Properties 4.2, 4.3 and the formula after them): see estimateErrors(). R is
//    taken from the area per Delaunay triangle, A = W*H / T with T = 2m - 2 - b (m distinct
//    sites, b of them on the hull boundary, collinear ones included), as the circumradius of the
//    equilateral triangle of area A: R = sqrt(4A / (3*sqrt(3))). See circumradiusFromArea().

#include <jfa/Grid.h>
#include <jfa/Hull.h>

#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

namespace fl::jfa {

/// The exact diagram a flood is judged against (views; the caller owns the data).
struct ExactDiagramView {
    int width = 0;
    int height = 0;
    std::span<const Cell> sites;     // x, y = position, z = id (>= 0, unique); any order
    std::span<const double> squared; // width*height, row-major: exact nearest squared distance
                                     // (int64 and float values are exact in a double)
    bool integerSites = true;        // distance arithmetic as in NearestSite::integerSites
};

/// Whether cell `c` recorded at grid point (x, y) is an error given the exact nearest squared
/// distance there (empty cells are errors; ties are correct).
bool isErrorPixel(const Cell& c, int x, int y, double exactSquared, bool integerSites);

/// Error mask of a flood (1 = error), row-major; throws std::invalid_argument on size mismatch.
std::vector<std::uint8_t> errorPixelMask(const Grid& flooded, const ExactDiagramView& exact);

/// 8-connected components of a 0/1 mask.
struct ClusterStats {
    std::int64_t errorPixels = 0;
    std::int64_t clusters = 0;
    std::int64_t singles = 0;                           // clusters of size 1
    std::map<std::int64_t, std::int64_t> sizeHistogram; // cluster size -> number of clusters
    std::vector<std::int64_t> singleIndices;            // row-major index of every single error
};

/// Labels the 8-connected clusters of `mask` (width x height, row-major, nonzero = set).
ClusterStats errorClusters(std::span<const std::uint8_t> mask, int width, int height);

/// Exact lookup of the sites at a given squared distance from a grid point (bucketed sites).
class SiteIndex {
  public:
    /// Indexes `sites` (x, y = position) for queries in the given distance arithmetic.
    SiteIndex(std::span<const Cell> sites, bool integerSites);
    /// Sites whose squared distance to (x, y), in NearestSite arithmetic, equals `squared`
    /// exactly; one per distinct position (the smallest id).
    [[nodiscard]] std::vector<Cell> sitesAt(int x, int y, double squared) const;
    /// The indexed sites, one per distinct position (the smallest id), in bucket order.
    [[nodiscard]] std::span<const Cell> distinctSites() const { return sites_; }

  private:
    std::vector<Cell> sites_; // sorted by bucket, duplicates (same position) removed
    std::vector<std::int32_t> bucketStart_;
    double minX_ = 0.0, minY_ = 0.0, bucketSize_ = 1.0;
    int bucketsX_ = 0, bucketsY_ = 0;
    bool integerSites_ = true;
};

/// Whether (x, y) is a discrete Voronoi vertex (definition in the header comment).
bool isDiscreteVoronoiVertex(const ExactDiagramView& exact, const SiteIndex& index, int x, int y);

/// Number of JFA passes on a grid of extent n (log2 n for powers of two; 0 for n <= 1): the
/// thesis' "log n" in the sum of Properties 4.2 and 4.3.
int jfaPassCount(int n);

/// The estimate of Properties 4.2 and 4.3 for one configuration.
struct ErrorEstimate {
    double e1 = 0.0;       // Property 4.2: error probability per vertex, type-v or type-h paths
    double e2 = 0.0;       // Property 4.3: error probability per vertex, type-d paths
    double vertices = 0.0; // 2m - h - 2 Voronoi vertices (0 when m < 3)
    double e = 0.0;        // E = vertices * (e1 + e2)
};

/// E for m distinct sites, h boundary regions, circumradius R (px) on an n x n grid; clamps as
/// documented in the definition (never negative, never NaN).
ErrorEstimate estimateErrors(std::int64_t m, std::int64_t h, double r, int n);

/// Circumradius of the equilateral triangle of area `area`: sqrt(4A / (3 sqrt 3)); 0 if A <= 0.
double circumradiusFromArea(double area);

/// R for m sites on a width x height grid: circumradiusFromArea(W*H / triangles), 0 if none.
double estimateCircumradius(int width, int height, std::int64_t delaunayTriangles);

/// The thesis' h: number of (closed) Voronoi regions reaching the grid boundary, i.e. distinct
/// sites in the union of T(q) over the boundary grid points q.
std::int64_t boundaryRegionCount(const ExactDiagramView& exact, const SiteIndex& index);

/// Everything measured about one flood, beside the estimate.
struct ErrorReport {
    std::string label = "JFA"; // the plan's name
    int width = 0;
    int height = 0;
    std::int64_t sites = 0;  // input sites
    std::int64_t m = 0;      // distinct site positions (used in E)
    std::int64_t pixels = 0; // width * height
    std::int64_t errorPixels = 0;
    std::int64_t clusters = 0;
    std::int64_t singles = 0;
    std::int64_t singlesAtVertices = 0;
    double singleVertexShare = 0.0;   // singlesAtVertices / singles (0 when there are none)
    std::int64_t interiorSingles = 0; // singles not on the grid's outer rows/columns
    std::int64_t interiorSinglesAtVertices = 0;        // of which at a Voronoi vertex
    std::map<std::int64_t, std::int64_t> clusterSizes; // size -> count
    std::vector<IntPoint> singlesOffVertices;          // single errors not at a vertex
    std::int64_t h = 0;                                // regions reaching the grid boundary
    std::int64_t hullBoundarySites = 0;                // b: sites on the hull boundary
    std::int64_t delaunayTriangles = 0;                // 2m - 2 - b (0 when m < 3 / collinear)
    double r = 0.0;                                    // estimated circumradius (px)
    ErrorEstimate estimate;

    /// One line: measured counts beside the estimate.
    [[nodiscard]] std::string describe() const;
};

/// Analyses `flooded` against the exact diagram; `label` names the plan in describe().
ErrorReport analyzeErrors(const Grid& flooded, const ExactDiagramView& exact,
                          std::string label = "JFA");

} // namespace fl::jfa
