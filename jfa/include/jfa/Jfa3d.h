#pragma once
// Jump flooding in 3D (thesis §4.6): a CPU simulation of 3D JFA and its variants on a W x H x D
// voxel grid, the exact 3D distance reference, the slice-by-slice variant (§4.6.2) and the error
// counts and experiment behind Fig. 4.16 / 4.17. CPU only, no GL. The 3D pass is its own; a
// slice flood is the 2D CPU kernel (jfa/CpuKernel.h) with a 3D-distance criterion, and the exact
// transform runs the 1D lower envelope exactIntegerEdt (jfa/Reference.h) is built from.
//
// Conventions. Sites have integer coordinates inside the grid and an id; every result cell holds
// the index of a site in the list the function was given (kNoSite = none). The nearest site wins;
// equal squared distances (exact, 64-bit integers) go to the smaller id, then the smaller index,
// so every result is deterministic and independent of the thread count. Voxel (x, y, z) is cell
// (z * H + y) * W + x.
//
// Step sequences are the 2D flood plans of <jfa/Plan.h>: a 3D flood runs the steps of a
// single-stage plan built for n = max(W, H, D) (plan3d()); a pass with step k reads the 27 voxels
// (x + i k, y + j k, z + l k), i, j, l in {-1, 0, 1}, inside the grid. The slice-by-slice variant
// runs any plan built for the W x H slice (half resolution included) with 9 neighbours per pass.

#include <jfa/Plan.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace fl::jfa {

/// A point site: integer voxel coordinates and an id (ties go to the smaller id).
struct Site3 {
    int x = 0;
    int y = 0;
    int z = 0;
    int id = 0;
    friend bool operator==(const Site3&, const Site3&) = default;
};

/// Size of a voxel grid; each side 1..kMaxGridExtent3d.
struct Extent3 {
    int width = 0;
    int height = 0;
    int depth = 0;
    [[nodiscard]] std::size_t voxels() const {
        return std::size_t(width) * std::size_t(height) * std::size_t(depth);
    }
    friend bool operator==(const Extent3&, const Extent3&) = default;
};

/// Largest side of a 3D grid (and at most kMaxVoxels3d voxels in all).
inline constexpr int kMaxGridExtent3d = 4096;
inline constexpr std::size_t kMaxVoxels3d = std::size_t(1) << 30;
/// Cell value of a voxel that has no site.
inline constexpr std::int32_t kNoSite = -1;
/// Squared distance of a voxel when there are no sites at all.
inline constexpr std::int64_t kNoDistance = INT64_MAX;

/// Per voxel: the index (into the site list) of the site recorded there, or kNoSite.
struct SiteGrid3 {
    Extent3 extent;
    std::vector<std::int32_t> cells;

    SiteGrid3() = default;
    /// A grid of `e` filled with kNoSite.
    explicit SiteGrid3(Extent3 e) : extent(e), cells(e.voxels(), kNoSite) {}
    /// Linear index of voxel (x, y, z).
    [[nodiscard]] std::size_t index(int x, int y, int z) const {
        return (std::size_t(z) * std::size_t(extent.height) + std::size_t(y)) *
                   std::size_t(extent.width) +
               std::size_t(x);
    }
    /// Site index recorded at voxel (x, y, z).
    [[nodiscard]] std::int32_t at(int x, int y, int z) const { return cells[index(x, y, z)]; }
    friend bool operator==(const SiteGrid3&, const SiteGrid3&) = default;
};

// ---- 3D jump flooding --------------------------------------------------------------------------

/// The 3D step plan for `spec` (jfa, jfa+1, jfa+2, jfa2, 1+jfa, doubling, flood, ...): parsePlan
/// for an n x n grid, n = max(W, H, D); throws std::invalid_argument for half-resolution plans.
Plan plan3d(std::string_view spec, Extent3 extent);
/// The grid a 3D flood starts from: each site at its voxel (two sites on one voxel: ties as
/// above), kNoSite elsewhere. Throws std::invalid_argument on bad sites or extents.
SiteGrid3 seedGrid3d(const std::vector<Site3>& sites, Extent3 extent);
/// Runs the passes of a single-stage `plan` on the 3D grid seeded with `sites`; threads <= 0
/// means one per hardware thread. Throws std::invalid_argument on bad sites, extents or plans.
SiteGrid3 flood3d(const std::vector<Site3>& sites, Extent3 extent, const Plan& plan,
                  int threads = 0);

// ---- exact references --------------------------------------------------------------------------

/// Exact squared Euclidean distance from every voxel to its nearest site (separable exact EDT in
/// integer arithmetic); kNoDistance everywhere if there are no sites.
std::vector<std::int64_t> exactSquaredDistances3d(const std::vector<Site3>& sites, Extent3 extent,
                                                  int threads = 0);
/// Brute force over all sites per voxel (small inputs only): the nearest site, ties as above.
SiteGrid3 bruteForceNearest3d(const std::vector<Site3>& sites, Extent3 extent);
/// Squared distances of the sites a grid records (kNoDistance where a voxel holds none).
std::vector<std::int64_t> recordedSquaredDistances(const SiteGrid3& grid,
                                                   const std::vector<Site3>& sites);

// ---- slice by slice (§4.6.2) -------------------------------------------------------------------

/// Site indices projected onto slice z = `slice` (W x H, row-major): per pixel the site nearest
/// to the slice (|site.z - slice| smallest; ties as above), or kNoSite.
std::vector<std::int32_t> projectSites(const std::vector<Site3>& sites, Extent3 extent, int slice);
/// projectSites for every slice at once (threads over slices): the grid the slice-by-slice
/// variant starts from, slice z of it = projectSites(sites, extent, z).
SiteGrid3 projectedSeeds3d(const std::vector<Site3>& sites, Extent3 extent, int threads = 0);
/// Floods one slice with a 2D `plan` for W x H from the projected sites, comparing candidates by
/// their full 3D distance to (x, y, slice); returns W x H site indices.
std::vector<std::int32_t> floodSlice(const std::vector<Site3>& sites, Extent3 extent, int slice,
                                     const Plan& plan);
/// floodSlice for every slice (threads over slices); the slice-by-slice 3D diagram.
SiteGrid3 floodSliceBySlice(const std::vector<Site3>& sites, Extent3 extent, const Plan& plan,
                            int threads = 0);

// ---- variants ----------------------------------------------------------------------------------

/// Which neighbours a pass reads: the 27 of 3D JFA, or the 9 of the voxel's own slice.
enum class Flood3dShape { Volume, Slices };

/// One 3D Voronoi variant: a plan and the shape its passes have (`voronoi3d --variant`, the GL
/// kernel's test and the benchmark read this one table).
struct Flood3dVariant {
    const char* name;   // e.g. "jfa", "slices"
    const char* plan;   // plan spec (plan3d for Volume, parsePlan for the W x H slice)
    Flood3dShape shape; // 3D passes or slice by slice
    const char* label;  // e.g. "3D JFA", "slice 1+JFA" (thesis Fig. 4.16 / 4.17)
};
/// Every variant: 3D jfa, jfa+1, jfa+2, jfa2 (Fig. 4.16) and slice jfa, 1+jfa (Fig. 4.17).
const std::vector<Flood3dVariant>& flood3dVariants();
/// The variant called `name`, or nullptr.
const Flood3dVariant* findFlood3dVariant(std::string_view name);
/// The variant's plan for `extent` (throws std::invalid_argument on a bad extent).
Plan variantPlan(const Flood3dVariant& variant, Extent3 extent);
/// The grid a flood of `shape` starts from: seedGrid3d, or projectedSeeds3d for Slices.
SiteGrid3 startGrid3d(const std::vector<Site3>& sites, Extent3 extent, Flood3dShape shape,
                      int threads = 0);
/// The CPU flood of `variant`: flood3d or floodSliceBySlice with its plan.
SiteGrid3 floodVariant3d(const Flood3dVariant& variant, const std::vector<Site3>& sites,
                         Extent3 extent, int threads = 0);

// ---- errors and the experiment -----------------------------------------------------------------

/// Erroneous voxels of one result against the exact diagram.
struct ErrorCount3d {
    std::string method;         // e.g. "3D JFA", "slice 1+JFA"
    Extent3 extent;             // grid size
    std::size_t sites = 0;      // number of sites
    std::int64_t erroneous = 0; // error voxels: recorded distance exceeds the exact one
    std::int64_t empty = 0;     // voxels with no site at all (also counted as erroneous)
    std::int64_t voxels = 0;    // voxels in the grid
    /// One line, e.g. "3D JFA on 64x64x64, 1000 sites: 37 error voxels of 262144 (0.0141%)".
    [[nodiscard]] std::string describe() const;
};

/// Counts voxels whose recorded site is farther than the exact nearest distance (ties count as
/// correct) given exact = exactSquaredDistances3d(sites, grid.extent).
ErrorCount3d countErrors3d(const SiteGrid3& grid, const std::vector<Site3>& sites,
                           const std::vector<std::int64_t>& exact, std::string method);

/// `count` sites at distinct uniformly random voxels, ids 0..count-1, from a fixed portable PRNG
/// (same sites on every platform for the same seed); throws if count exceeds the voxel count.
std::vector<Site3> randomSites3d(int count, Extent3 extent, std::uint64_t seed);

/// What the Fig. 4.16 / 4.17 experiment runs: cubic sizes x site counts x seeds x methods.
struct Experiment3dConfig {
    std::vector<int> sizes{64, 128};
    std::vector<int> siteCounts{100, 1000, 5000};
    std::vector<std::uint64_t> seeds{1, 2, 3};
    std::vector<std::string> plans3d{"jfa", "jfa+1", "jfa+2", "jfa2"}; // full 3D JFA (Fig. 4.16)
    std::vector<std::string> slicePlans{"jfa", "1+jfa"};               // slice by slice (Fig. 4.17)
    int threads = 0;
};

/// One method at one size and site count, over all seeds.
struct Experiment3dRow {
    int size = 0;       // grid is size^3
    int sites = 0;      // site count
    std::string method; // "3D JFA", "3D JFA+1", ..., "slice JFA", "slice 1+JFA"
    std::vector<std::int64_t> errorsPerSeed; // erroneous voxels, one per seed (config order)
    /// Mean erroneous voxels over the seeds.
    [[nodiscard]] double meanErrors() const;
    /// One line: size, sites, method, mean, per-seed counts and errors per site.
    [[nodiscard]] std::string describe() const;
};

/// Runs the experiment; rows ordered by size, site count, then method (3D plans, slice plans).
std::vector<Experiment3dRow> runExperiment3d(const Experiment3dConfig& config);

} // namespace fl::jfa
