#pragma once
// Exact nearest-site fields for tests and error counting (thesis §4.4-4.5 count the grid points
// where JFA misses the nearest site).
//
// The sites are the non-empty cells of a seed grid (as seedPoints / seedMask write them), with
// the positions and ids they hold; distances are those of NearestSite: exact 64-bit integer
// squares for integer sites, float dx*dx + dy*dy (no FMA) for sub-pixel sites. Every distance a
// field stores is exact in a double (int64 squares < 2^53; floats widen exactly), so comparing a
// flood's distance with the field's is exact.
//
// Which nearest site a field records when several are equally near: bruteForceNearest and
// exactNearestSearch record NearestSite's winner (smaller id, then y, then x), so their grids
// equal an error-free flood texel for texel; exactIntegerEdt records *a* nearest site (the
// distance is exact, the tie choice is its own). countErrors compares distances only, so ties
// count as correct whichever site a flood kept.

#include <jfa/Grid.h>
#include <jfa/NearestSite.h>

#include <cstdint>
#include <vector>

namespace fl::jfa {

/// Per grid point of a W x H grid: a nearest site and its squared distance.
struct ExactField {
    /// A nearest site's cell per grid point (kEmptyCell from CpuKernel.h if there are no sites).
    Grid nearest;
    /// Its squared distance in NearestSite's arithmetic; +infinity if there are no sites.
    std::vector<double> distSq;

    /// Squared distance at grid point (x, y).
    [[nodiscard]] double at(int x, int y) const {
        return distSq[std::size_t(y) * std::size_t(nearest.width) + std::size_t(x)];
    }
};

/// The sites of a seed grid: its non-empty cells (NearestSite::empty) in row-major order.
std::vector<Cell> siteCells(const Grid& seeds);

/// Squared distance from grid point (px, py) to site `c` in the criterion's arithmetic.
double squaredDistance(const NearestSite& criterion, int px, int py, const Cell& c);

/// Brute force, O(W * H * sites): every grid point checks every site (tests of the others only).
ExactField bruteForceNearest(const Grid& seeds, const NearestSite& criterion);

/// Exact Euclidean distance transform of integer sites (separable: lower envelopes of parabolas
/// along columns, then rows, as in Meijster et al. 2000 and Felzenszwalb & Huttenlocher 2012;
/// the same 1D transform as the 3D reference of jfa/Jfa3d.h), O(W * H), integer arithmetic. Every
/// site must have integral coordinates inside the grid (std::invalid_argument otherwise); sites
/// sharing a position keep NearestSite's better one there. Records a nearest site, not
/// necessarily NearestSite's tie winner.
ExactField exactIntegerEdt(const Grid& seeds);

/// Exact nearest-site search for any sites (integer or sub-pixel, inside the grid or not): a
/// uniform bucket grid (about one site per bucket) searched in rings of buckets around each grid
/// point until no unvisited bucket can hold a site as near as the best found (with a safety
/// margin covering float rounding). Records NearestSite's winner. Expected O(W * H) for
/// uniformly spread sites.
ExactField exactNearestSearch(const Grid& seeds, const NearestSite& criterion);

/// The fastest exact field: exactIntegerEdt for integer sites inside the grid, else
/// exactNearestSearch.
ExactField exactNearest(const Grid& seeds, const NearestSite& criterion);

/// Whether flooded texel (x, y) is correct: it holds a site whose distance to (x, y), in
/// NearestSite's arithmetic, equals the exact nearest distance (ties are correct), or it is empty
/// and there are no sites.
bool isCorrect(const Grid& flooded, const ExactField& exact, int x, int y,
               const NearestSite& criterion);

/// Number of texels of `flooded` that are not correct (isCorrect). Sizes must match.
std::int64_t countErrors(const Grid& flooded, const ExactField& exact,
                         const NearestSite& criterion);

/// 1 where a texel of `flooded` is not correct, else 0 (W * H values, row-major).
std::vector<std::uint8_t> errorMask(const Grid& flooded, const ExactField& exact,
                                    const NearestSite& criterion);

} // namespace fl::jfa
