#include <jfa/CpuKernel.h>
#include <jfa/Jfa3d.h>
#include <jfa/Sites.h>

#include "LowerEnvelope.h"

#include <base/Parallel.h>
#include <base/Text.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <string_view>
#include <utility>

namespace fl::jfa {

namespace {

using Cells = std::vector<std::int32_t>;

std::string extentText(Extent3 e) {
    return fl::cat(e.width, "x", e.height, "x", e.depth);
}

void checkExtent(Extent3 e) {
    const auto bad = [](int side) { return side < 1 || side > kMaxGridExtent3d; };
    if (bad(e.width) || bad(e.height) || bad(e.depth) || e.voxels() > kMaxVoxels3d) {
        throw std::invalid_argument(
            fl::cat("3D grid ", extentText(e), " is out of range: each side must be 1..",
                    kMaxGridExtent3d, " and at most ", kMaxVoxels3d, " voxels in all"));
    }
}

void checkSites(const std::vector<Site3>& sites, Extent3 e) {
    checkExtent(e);
    if (sites.size() > std::size_t(std::numeric_limits<std::int32_t>::max())) {
        throw std::invalid_argument("3D flooding: too many sites");
    }
    for (std::size_t i = 0; i < sites.size(); ++i) {
        const Site3& s = sites[i];
        if (s.x < 0 || s.y < 0 || s.z < 0 || s.x >= e.width || s.y >= e.height || s.z >= e.depth) {
            throw std::invalid_argument(fl::cat("site ", i, " (id ", s.id, ") at (", s.x, ", ", s.y,
                                                ", ", s.z, ") lies outside the ", extentText(e),
                                                " grid"));
        }
    }
}

// Threads for fl::parallelRows: this header's "<= 0 = one per hardware thread".
int poolSize(int threads) {
    return std::max(threads, 0);
}

std::int64_t squared(const Site3& s, int x, int y, int z) {
    const std::int64_t dx = std::int64_t(s.x) - x, dy = std::int64_t(s.y) - y,
                       dz = std::int64_t(s.z) - z;
    return dx * dx + dy * dy + dz * dz;
}

// Tie-break between two different sites at equal distance: smaller id, then smaller index.
bool tieLess(const Site3* sites, std::int32_t a, std::int32_t b) {
    if (sites[a].id != sites[b].id) return sites[a].id < sites[b].id;
    return a < b;
}

// The running best of one cell: offer() candidates in any order, the result is the same.
struct Best {
    std::int32_t site = kNoSite;
    std::int64_t distance = std::numeric_limits<std::int64_t>::max();

    void offer(const Site3* sites, std::int32_t c, int x, int y, int z) {
        if (c < 0 || c == site) return;
        const std::int64_t d = squared(sites[c], x, y, z);
        if (d < distance || (d == distance && tieLess(sites, c, site))) {
            site = c;
            distance = d;
        }
    }
};

// One 3D pass with step k over the rows [rowBegin, rowEnd) (row r = z * H + y); returns whether
// any cell changed.
bool pass3d(const Cells& in, Cells& out, Extent3 e, int k, const Site3* sites, std::size_t rowBegin,
            std::size_t rowEnd) {
    const int w = e.width, h = e.height;
    bool changed = false;
    const std::int32_t* rows[9];
    for (std::size_t r = rowBegin; r < rowEnd; ++r) {
        const int z = int(r / std::size_t(h)), y = int(r % std::size_t(h));
        int rowCount = 0;
        for (int zz = z - k; zz <= z + k; zz += k) {
            if (zz < 0 || zz >= e.depth) continue;
            for (int yy = y - k; yy <= y + k; yy += k) {
                if (yy < 0 || yy >= h) continue;
                rows[rowCount++] =
                    in.data() +
                    (std::size_t(zz) * std::size_t(h) + std::size_t(yy)) * std::size_t(w);
            }
        }
        const std::size_t base = r * std::size_t(w);
        for (int x = 0; x < w; ++x) {
            Best best;
            const bool left = x >= k, right = x + k < w;
            for (int i = 0; i < rowCount; ++i) {
                const std::int32_t* row = rows[i];
                best.offer(sites, row[x], x, y, z);
                if (left) best.offer(sites, row[x - k], x, y, z);
                if (right) best.offer(sites, row[x + k], x, y, z);
            }
            changed |= best.site != in[base + std::size_t(x)];
            out[base + std::size_t(x)] = best.site;
        }
    }
    return changed;
}

void checkSlicePlan(const Plan& plan, Extent3 e) {
    if (plan.width() != e.width || plan.height() != e.height) {
        throw std::invalid_argument(fl::cat("slice-by-slice flooding of a ", extentText(e),
                                            " grid needs a plan for ", e.width, "x", e.height,
                                            ", got ", plan.describe()));
    }
}

void checkSlice(Extent3 e, int slice) {
    if (slice < 0 || slice >= e.depth) {
        throw std::invalid_argument(
            fl::cat("slice ", slice, " is outside the ", extentText(e), " grid"));
    }
}

std::vector<std::int32_t> projectChecked(const std::vector<Site3>& sites, Extent3 e, int slice) {
    Cells cells(std::size_t(e.width) * std::size_t(e.height), kNoSite);
    for (std::size_t i = 0; i < sites.size(); ++i) {
        const Site3& s = sites[i];
        std::int32_t& cell = cells[std::size_t(s.y) * std::size_t(e.width) + std::size_t(s.x)];
        const auto c = std::int32_t(i);
        if (cell == kNoSite) {
            cell = c;
            continue;
        }
        const int dz = std::abs(s.z - slice),
                  current = std::abs(sites[std::size_t(cell)].z - slice);
        if (dz < current || (dz == current && tieLess(sites.data(), c, cell))) cell = c;
    }
    return cells;
}

// A slice flood is a 2D flood (jfa/CpuKernel.h) whose cells name sites of the 3D list: the index
// is split into z = its low 24 bits and w = the rest, both exact in a float (kEmptyCell, z = -1,
// is "no site"), so every int32 index fits.
Cell siteCell(std::int32_t index) {
    return {0.0f, 0.0f, float(index & 0xFFFFFF), float(index >> 24)};
}
std::int32_t siteIndex(const Cell& c) {
    return c.z < 0.0f ? kNoSite : std::int32_t(c.z) | (std::int32_t(c.w) << 24);
}

// Candidates compare by their full 3D distance to grid point (px, py, slice), ties as Best.
struct SliceCriterion {
    static constexpr const char* glslFile = nullptr; // CPU only: no GL kernel runs it
    const Site3* sites;
    int slice;

    [[nodiscard]] bool empty(const Cell& c) const { return c.z < 0.0f; }
    [[nodiscard]] bool better(int px, int py, const Cell& a, const Cell& b) const {
        const std::int32_t ia = siteIndex(a), ib = siteIndex(b);
        const std::int64_t da = squared(sites[ia], px, py, slice),
                           db = squared(sites[ib], px, py, slice);
        return da != db ? da < db : tieLess(sites, ia, ib);
    }
};
static_assert(Criterion<SliceCriterion>);

// Floods one slice from its projected sites through all stages of `plan` (one thread: the
// callers split the work by slices).
std::vector<std::int32_t> floodProjected(const std::vector<Site3>& sites, Extent3 e, int slice,
                                         const Plan& plan, const Cells& projected) {
    Grid seeds(e.width, e.height, kEmptyCell);
    for (std::size_t i = 0; i < projected.size(); ++i) {
        if (projected[i] != kNoSite) seeds.cells[i] = siteCell(projected[i]);
    }
    FloodOptions options;
    options.threads = 1;
    const Grid flooded = flood(plan, seeds, SliceCriterion{sites.data(), slice}, options);
    Cells result(flooded.cells.size());
    std::transform(flooded.cells.begin(), flooded.cells.end(), result.begin(), siteIndex);
    return result;
}

std::string percentText(double fraction) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.4f%%", 100.0 * fraction);
    return buffer;
}

} // namespace

// ---- 3D jump flooding --------------------------------------------------------------------------

Plan plan3d(std::string_view spec, Extent3 extent) {
    checkExtent(extent);
    const int n = std::max({extent.width, extent.height, extent.depth});
    Plan plan = parsePlan(spec, n, n);
    if (plan.stages().size() != 1) {
        throw std::invalid_argument(fl::cat("3D flooding runs single-stage plans only, not \"",
                                            plan.name(), "\" (no half resolution in 3D)"));
    }
    return plan;
}

SiteGrid3 seedGrid3d(const std::vector<Site3>& sites, Extent3 extent) {
    checkSites(sites, extent);
    SiteGrid3 grid(extent);
    for (std::size_t i = 0; i < sites.size(); ++i) { // distance 0: ties by id then index
        const Site3& s = sites[i];
        std::int32_t& cell = grid.cells[grid.index(s.x, s.y, s.z)];
        if (cell == kNoSite || tieLess(sites.data(), std::int32_t(i), cell)) cell = std::int32_t(i);
    }
    return grid;
}

SiteGrid3 flood3d(const std::vector<Site3>& sites, Extent3 extent, const Plan& plan, int threads) {
    checkSites(sites, extent);
    if (plan.stages().size() != 1) {
        throw std::invalid_argument(
            fl::cat("3D flooding runs single-stage plans only, not ", plan.describe()));
    }
    SiteGrid3 grid = seedGrid3d(sites, extent);
    Cells& a = grid.cells;
    const Stage& stage = plan.stages().front();
    const int rows = extent.height * extent.depth;
    const int threadCount = poolSize(threads);
    Cells b(a.size());
    std::vector<char> changed(std::size_t(fl::bandCount(rows, threadCount))); // one flag per band
    for (int step : stage.steps) {
        fl::parallelRows(rows, threadCount, [&](int begin, int end, int band) {
            changed[std::size_t(band)] =
                pass3d(a, b, extent, step, sites.data(), std::size_t(begin), std::size_t(end));
        });
        std::swap(a, b);
        const bool any = std::any_of(changed.begin(), changed.end(), [](char c) { return c; });
        if (stage.untilUnchanged && !any) break;
    }
    return grid;
}

// ---- exact references --------------------------------------------------------------------------

std::vector<std::int64_t> exactSquaredDistances3d(const std::vector<Site3>& sites, Extent3 extent,
                                                  int threads) {
    checkSites(sites, extent);
    const std::size_t w = std::size_t(extent.width), h = std::size_t(extent.height),
                      d = std::size_t(extent.depth);
    std::vector<std::int64_t> dist(extent.voxels(), detail::kFarSquared);
    if (sites.empty()) {
        std::fill(dist.begin(), dist.end(), kNoDistance);
        return dist;
    }
    for (const Site3& s : sites)
        dist[(std::size_t(s.z) * h + std::size_t(s.y)) * w + std::size_t(s.x)] = 0;
    // Along x (line = row (y, z)), then y (line = column (x, z)), then z (line = (x, y)).
    const int pool = poolSize(threads);
    detail::transformLines(
        dist.data(), nullptr, h * d, extent.width, 1, [&](std::size_t i) { return i * w; }, pool);
    detail::transformLines(
        dist.data(), nullptr, w * d, extent.height, w,
        [&](std::size_t i) { return (i / w) * w * h + i % w; }, pool);
    detail::transformLines(
        dist.data(), nullptr, w * h, extent.depth, w * h, [](std::size_t i) { return i; }, pool);
    return dist;
}

SiteGrid3 bruteForceNearest3d(const std::vector<Site3>& sites, Extent3 extent) {
    checkSites(sites, extent);
    SiteGrid3 grid(extent);
    for (int z = 0; z < extent.depth; ++z) {
        for (int y = 0; y < extent.height; ++y) {
            for (int x = 0; x < extent.width; ++x) {
                Best best;
                for (std::size_t i = 0; i < sites.size(); ++i) {
                    best.offer(sites.data(), std::int32_t(i), x, y, z);
                }
                grid.cells[grid.index(x, y, z)] = best.site;
            }
        }
    }
    return grid;
}

std::vector<std::int64_t> recordedSquaredDistances(const SiteGrid3& grid,
                                                   const std::vector<Site3>& sites) {
    const Extent3 e = grid.extent;
    std::vector<std::int64_t> result(grid.cells.size(), kNoDistance);
    for (int z = 0; z < e.depth; ++z) {
        for (int y = 0; y < e.height; ++y) {
            for (int x = 0; x < e.width; ++x) {
                const std::size_t i = grid.index(x, y, z);
                const std::int32_t c = grid.cells[i];
                if (c == kNoSite) continue;
                if (c < 0 || std::size_t(c) >= sites.size()) {
                    throw std::invalid_argument("grid records a site index outside the site list");
                }
                result[i] = squared(sites[std::size_t(c)], x, y, z);
            }
        }
    }
    return result;
}

// ---- slice by slice ----------------------------------------------------------------------------

std::vector<std::int32_t> projectSites(const std::vector<Site3>& sites, Extent3 extent, int slice) {
    checkSites(sites, extent);
    checkSlice(extent, slice);
    return projectChecked(sites, extent, slice);
}

SiteGrid3 projectedSeeds3d(const std::vector<Site3>& sites, Extent3 extent, int threads) {
    checkSites(sites, extent);
    SiteGrid3 grid(extent);
    const std::size_t sliceSize = std::size_t(extent.width) * std::size_t(extent.height);
    fl::parallelRows(extent.depth, poolSize(threads), [&](int begin, int end, int) {
        for (int z = begin; z < end; ++z) {
            const Cells slice = projectChecked(sites, extent, z);
            std::copy(slice.begin(), slice.end(),
                      grid.cells.begin() + std::ptrdiff_t(std::size_t(z) * sliceSize));
        }
    });
    return grid;
}

std::vector<std::int32_t> floodSlice(const std::vector<Site3>& sites, Extent3 extent, int slice,
                                     const Plan& plan) {
    checkSites(sites, extent);
    checkSlice(extent, slice);
    checkSlicePlan(plan, extent);
    return floodProjected(sites, extent, slice, plan, projectChecked(sites, extent, slice));
}

SiteGrid3 floodSliceBySlice(const std::vector<Site3>& sites, Extent3 extent, const Plan& plan,
                            int threads) {
    checkSites(sites, extent);
    checkSlicePlan(plan, extent);
    SiteGrid3 grid(extent);
    const std::size_t sliceSize = std::size_t(extent.width) * std::size_t(extent.height);
    fl::parallelRows(extent.depth, poolSize(threads), [&](int begin, int end, int) {
        for (int z = begin; z < end; ++z) {
            const Cells result =
                floodProjected(sites, extent, z, plan, projectChecked(sites, extent, z));
            std::copy(result.begin(), result.end(),
                      grid.cells.begin() + std::ptrdiff_t(std::size_t(z) * sliceSize));
        }
    });
    return grid;
}

// ---- variants ----------------------------------------------------------------------------------

const std::vector<Flood3dVariant>& flood3dVariants() {
    static const std::vector<Flood3dVariant> variants{
        {"jfa", "jfa", Flood3dShape::Volume, "3D JFA"},
        {"jfa+1", "jfa+1", Flood3dShape::Volume, "3D JFA+1"},
        {"jfa+2", "jfa+2", Flood3dShape::Volume, "3D JFA+2"},
        {"jfa2", "jfa2", Flood3dShape::Volume, "3D JFA^2"},
        {"slices", "jfa", Flood3dShape::Slices, "slice JFA"},
        {"slices-1+jfa", "1+jfa", Flood3dShape::Slices, "slice 1+JFA"},
    };
    return variants;
}

const Flood3dVariant* findFlood3dVariant(std::string_view name) {
    for (const Flood3dVariant& v : flood3dVariants())
        if (name == v.name) return &v;
    return nullptr;
}

Plan variantPlan(const Flood3dVariant& variant, Extent3 extent) {
    if (variant.shape == Flood3dShape::Volume) return plan3d(variant.plan, extent);
    checkExtent(extent);
    return parsePlan(variant.plan, extent.width, extent.height);
}

SiteGrid3 startGrid3d(const std::vector<Site3>& sites, Extent3 extent, Flood3dShape shape,
                      int threads) {
    return shape == Flood3dShape::Volume ? seedGrid3d(sites, extent)
                                         : projectedSeeds3d(sites, extent, threads);
}

SiteGrid3 floodVariant3d(const Flood3dVariant& variant, const std::vector<Site3>& sites,
                         Extent3 extent, int threads) {
    const Plan plan = variantPlan(variant, extent);
    return variant.shape == Flood3dShape::Volume ? flood3d(sites, extent, plan, threads)
                                                 : floodSliceBySlice(sites, extent, plan, threads);
}

// ---- errors and the experiment -----------------------------------------------------------------

std::string ErrorCount3d::describe() const {
    std::string text =
        fl::cat(method, " on ", extentText(extent), ", ", sites,
                sites == 1 ? " site: " : " sites: ", erroneous,
                erroneous == 1 ? " error voxel of " : " error voxels of ", voxels, " (",
                percentText(voxels > 0 ? double(erroneous) / double(voxels) : 0.0), ")");
    if (empty > 0) text += fl::cat(", ", empty, " without a site");
    return text;
}

ErrorCount3d countErrors3d(const SiteGrid3& grid, const std::vector<Site3>& sites,
                           const std::vector<std::int64_t>& exact, std::string method) {
    if (exact.size() != grid.cells.size() || grid.cells.size() != grid.extent.voxels()) {
        throw std::invalid_argument("countErrors3d: grid and exact distances differ in size");
    }
    const std::vector<std::int64_t> recorded = recordedSquaredDistances(grid, sites);
    ErrorCount3d count{
        std::move(method), grid.extent, sites.size(), 0, 0, std::int64_t(grid.cells.size())};
    for (std::size_t i = 0; i < recorded.size(); ++i) {
        if (recorded[i] < exact[i]) {
            throw std::invalid_argument(
                "countErrors3d: a recorded site is nearer than the exact distance; the exact "
                "distances belong to other sites");
        }
        if (recorded[i] > exact[i]) {
            ++count.erroneous;
            if (grid.cells[i] == kNoSite) ++count.empty;
        }
    }
    return count;
}

std::vector<Site3> randomSites3d(int count, Extent3 extent, std::uint64_t seed) {
    checkExtent(extent);
    if (count < 0 || std::size_t(count) > extent.voxels()) {
        throw std::invalid_argument(fl::cat(
            "randomSites3d: ", count, " distinct sites do not fit into ", extentText(extent)));
    }
    SplitMix64 rng{seed};
    std::vector<bool> taken(extent.voxels(), false);
    std::vector<Site3> sites;
    sites.reserve(std::size_t(count));
    const std::size_t w = std::size_t(extent.width), h = std::size_t(extent.height);
    while (sites.size() < std::size_t(count)) {
        const std::size_t v = std::size_t(rng.below(extent.voxels()));
        if (taken[v]) continue;
        taken[v] = true;
        sites.push_back(Site3{int(v % w), int(v / w % h), int(v / (w * h)), int(sites.size())});
    }
    return sites;
}

double Experiment3dRow::meanErrors() const {
    if (errorsPerSeed.empty()) return 0.0;
    double sum = 0.0;
    for (std::int64_t e : errorsPerSeed) sum += double(e);
    return sum / double(errorsPerSeed.size());
}

std::string Experiment3dRow::describe() const {
    char mean[64];
    std::snprintf(mean, sizeof mean, "%.2f", meanErrors());
    char perSite[64];
    std::snprintf(perSite, sizeof perSite, "%.5f", sites > 0 ? meanErrors() / sites : 0.0);
    std::string seeds;
    for (std::int64_t e : errorsPerSeed) {
        if (!seeds.empty()) seeds += ' ';
        seeds += std::to_string(e);
    }
    return fl::cat(size, "^3, ", sites, " sites, ", method, ": mean ", mean,
                   " erroneous voxels (per seed: ", seeds, "), ", perSite, " per site");
}

std::vector<Experiment3dRow> runExperiment3d(const Experiment3dConfig& config) {
    std::vector<Experiment3dRow> rows;
    for (int size : config.sizes) {
        const Extent3 extent{size, size, size};
        std::vector<Plan> plans, slicePlans;
        for (const std::string& spec : config.plans3d) plans.push_back(plan3d(spec, extent));
        for (const std::string& spec : config.slicePlans) {
            slicePlans.push_back(parsePlan(spec, size, size));
        }
        for (int count : config.siteCounts) {
            const std::size_t first = rows.size();
            for (const Plan& plan : plans)
                rows.push_back({size, count, fl::cat("3D ", plan.name()), {}});
            for (const Plan& plan : slicePlans) {
                rows.push_back({size, count, fl::cat("slice ", plan.name()), {}});
            }
            for (std::uint64_t seed : config.seeds) {
                const std::vector<Site3> sites = randomSites3d(count, extent, seed);
                const auto exact = exactSquaredDistances3d(sites, extent, config.threads);
                std::size_t row = first;
                for (const Plan& plan : plans) {
                    const SiteGrid3 grid = flood3d(sites, extent, plan, config.threads);
                    rows[row++].errorsPerSeed.push_back(
                        countErrors3d(grid, sites, exact, plan.name()).erroneous);
                }
                for (const Plan& plan : slicePlans) {
                    const SiteGrid3 grid = floodSliceBySlice(sites, extent, plan, config.threads);
                    rows[row++].errorsPerSeed.push_back(
                        countErrors3d(grid, sites, exact, plan.name()).erroneous);
                }
            }
        }
    }
    return rows;
}

} // namespace fl::jfa
