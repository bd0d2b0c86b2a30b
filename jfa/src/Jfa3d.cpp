#include <jfa/Jfa3d.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <limits>
#include <stdexcept>
#include <string_view>
#include <thread>
#include <utility>

namespace fl::jfa {

namespace {

using Cells = std::vector<std::int32_t>;

// Squared distance between 'no site' entries of the exact transform (any finite distance is
// smaller; kept far from overflow when a line adds (x - q)^2 to it).
constexpr std::int64_t kInf = std::numeric_limits<std::int64_t>::max() / 4;

std::string cat(std::initializer_list<std::string_view> parts) {
    std::string text;
    for (std::string_view part : parts) text += part;
    return text;
}

std::string extentText(Extent3 e) {
    return cat(
        {std::to_string(e.width), "x", std::to_string(e.height), "x", std::to_string(e.depth)});
}

void checkExtent(Extent3 e) {
    const auto bad = [](int side) { return side < 1 || side > kMaxGridExtent3d; };
    if (bad(e.width) || bad(e.height) || bad(e.depth) || e.voxels() > kMaxVoxels3d) {
        throw std::invalid_argument(
            cat({"3D grid ", extentText(e), " is out of range: each side must be 1..",
                 std::to_string(kMaxGridExtent3d), " and at most ", std::to_string(kMaxVoxels3d),
                 " voxels in all"}));
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
            throw std::invalid_argument(
                cat({"site ", std::to_string(i), " (id ", std::to_string(s.id), ") at (",
                     std::to_string(s.x), ", ", std::to_string(s.y), ", ", std::to_string(s.z),
                     ") lies outside the ", extentText(e), " grid"}));
        }
    }
}

int threadCount(int requested, std::size_t work) {
    std::size_t n = requested > 0 ? std::size_t(requested) : std::thread::hardware_concurrency();
    n = std::clamp<std::size_t>(n, 1, std::max<std::size_t>(work, 1));
    return int(n);
}

// Runs fn(chunk, begin, end) for chunk = 0..chunks-1 over contiguous parts of [0, count), one
// thread per chunk. Results never depend on the split: every item reads read-only input only.
template <typename F>
void parallelChunks(std::size_t count, int chunks, F&& fn) {
    const auto part = [&](int t) { return count * std::size_t(t) / std::size_t(chunks); };
    if (chunks == 1) return fn(0, std::size_t(0), count);
    std::vector<std::thread> pool;
    for (int t = 0; t < chunks; ++t)
        pool.emplace_back([&fn, t, b = part(t), e = part(t + 1)] { fn(t, b, e); });
    for (std::thread& thread : pool) thread.join();
}

// Runs fn(i) for every i in [0, count), items handed out one at a time (load balance).
template <typename F>
void parallelItems(std::size_t count, int threads, F&& fn) {
    const int n = threadCount(threads, count);
    std::atomic<std::size_t> next{0};
    const auto worker = [&] {
        for (std::size_t i = next++; i < count; i = next++) fn(i);
    };
    if (n == 1) {
        worker();
        return;
    }
    std::vector<std::thread> pool;
    for (int t = 0; t < n; ++t) pool.emplace_back(worker);
    for (std::thread& thread : pool) thread.join();
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

// Ceil(n / d) for d > 0.
std::int64_t ceilDiv(std::int64_t n, std::int64_t d) {
    return n >= 0 ? (n + d - 1) / d : -((-n) / d);
}

// Exact 1D lower envelope of parabolas: d[x] = min_q (x - q)^2 + f[q] over q with f[q] < kInf
// (kInf if there is none), in integers. v holds the envelope's parabolas, from[j] the first x
// where v[j] is minimal.
void envelope1d(const std::int64_t* f, int n, std::int64_t* d, int* v, std::int64_t* from) {
    int k = -1;
    for (int q = 0; q < n; ++q) {
        if (f[q] >= kInf) continue;
        const std::int64_t fq = f[q] + std::int64_t(q) * q;
        std::int64_t start = 0;
        while (k >= 0) {
            const int p = v[k];
            // q is at most p from ceil(...) on.
            start = ceilDiv(fq - (f[p] + std::int64_t(p) * p), 2 * std::int64_t(q - p));
            if (start > from[k]) break;
            --k;
        }
        if (k < 0) start = 0;
        if (start >= n) continue; // q is never the minimum inside the line
        ++k;
        v[k] = q;
        from[k] = start;
    }
    if (k < 0) {
        std::fill(d, d + n, kInf);
        return;
    }
    int j = 0;
    for (int x = 0; x < n; ++x) {
        while (j < k && from[j + 1] <= x) ++j;
        const std::int64_t dx = x - v[j];
        d[x] = dx * dx + f[v[j]];
    }
}

// Transforms every line of `dist` along one axis: lines of length n, elements `stride` apart,
// line i starting at lineStart(i).
template <typename Start>
void transformLines(std::vector<std::int64_t>& dist, std::size_t lines, int n, std::size_t stride,
                    Start lineStart, int threads) {
    parallelChunks(
        lines, threadCount(threads, lines), [&](int, std::size_t begin, std::size_t end) {
            std::vector<std::int64_t> f(static_cast<std::size_t>(n)), d(f.size()), from(f.size());
            std::vector<int> v(f.size());
            for (std::size_t i = begin; i < end; ++i) {
                std::int64_t* line = dist.data() + lineStart(i);
                for (int x = 0; x < n; ++x) f[std::size_t(x)] = line[std::size_t(x) * stride];
                envelope1d(f.data(), n, d.data(), v.data(), from.data());
                for (int x = 0; x < n; ++x) line[std::size_t(x) * stride] = d[std::size_t(x)];
            }
        });
}

// One 2D pass on a slice grid of w x h texels at `scale` (grid point of texel (x, y) is
// (x * scale, y * scale, slice)); returns whether any texel changed.
bool pass2d(const Cells& in, Cells& out, int w, int h, int k, int scale, int slice,
            const Site3* sites) {
    bool changed = false;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            Best best;
            for (int yy = y - k; yy <= y + k; yy += k) {
                if (yy < 0 || yy >= h) continue;
                const std::int32_t* row = in.data() + std::size_t(yy) * std::size_t(w);
                for (int xx = x - k; xx <= x + k; xx += k) {
                    if (xx >= 0 && xx < w) best.offer(sites, row[xx], x * scale, y * scale, slice);
                }
            }
            const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
            changed |= best.site != in[i];
            out[i] = best.site;
        }
    }
    return changed;
}

void checkSlicePlan(const Plan& plan, Extent3 e) {
    if (plan.width() != e.width || plan.height() != e.height) {
        throw std::invalid_argument(cat({"slice-by-slice flooding of a ", extentText(e),
                                         " grid needs a plan for ", std::to_string(e.width), "x",
                                         std::to_string(e.height), ", got ", plan.describe()}));
    }
}

void checkSlice(Extent3 e, int slice) {
    if (slice < 0 || slice >= e.depth) {
        throw std::invalid_argument(
            cat({"slice ", std::to_string(slice), " is outside the ", extentText(e), " grid"}));
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

// Floods one slice from its projected sites through all stages of `plan`.
std::vector<std::int32_t> floodProjected(const std::vector<Site3>& sites, Extent3 e, int slice,
                                         const Plan& plan, const Cells& projected) {
    const std::vector<Stage>& stages = plan.stages();
    const Site3* s = sites.data();
    int scale = 1; // the first stage is 2^(stages - 1) times smaller than the slice
    for (std::size_t i = 1; i < stages.size(); ++i) {
        if (scale > kMaxGridExtent3d) throw std::invalid_argument("plan has too many stages");
        scale *= 2;
    }
    int w = stages.front().width, h = stages.front().height;
    Cells a(std::size_t(w) * std::size_t(h), kNoSite), b;
    // Seed: each texel keeps the best projected site of the scale x scale block it covers.
    for (int y = 0; y < e.height; ++y) {
        for (int x = 0; x < e.width; ++x) {
            const std::int32_t c =
                projected[std::size_t(y) * std::size_t(e.width) + std::size_t(x)];
            if (c == kNoSite) continue;
            const int tx = x / scale, ty = y / scale;
            std::int32_t& cell = a[std::size_t(ty) * std::size_t(w) + std::size_t(tx)];
            Best best{cell, cell == kNoSite ? std::numeric_limits<std::int64_t>::max()
                                            : squared(s[cell], tx * scale, ty * scale, slice)};
            best.offer(s, c, tx * scale, ty * scale, slice);
            cell = best.site;
        }
    }
    for (std::size_t i = 0; i < stages.size(); ++i) {
        const Stage& stage = stages[i];
        if (i > 0) { // expand: texel (x, y) takes the cell of (x / 2, y / 2)
            b.assign(std::size_t(stage.width) * std::size_t(stage.height), kNoSite);
            for (int y = 0; y < stage.height; ++y) {
                for (int x = 0; x < stage.width; ++x) {
                    b[std::size_t(y) * std::size_t(stage.width) + std::size_t(x)] =
                        a[std::size_t(y / 2) * std::size_t(w) + std::size_t(x / 2)];
                }
            }
            std::swap(a, b);
            w = stage.width;
            h = stage.height;
            scale /= 2;
        }
        b.resize(a.size());
        for (int step : stage.steps) {
            const bool changed = pass2d(a, b, w, h, step, scale, slice, s);
            std::swap(a, b);
            if (stage.untilUnchanged && !changed) break;
        }
    }
    return a;
}

// splitmix64: a small portable PRNG (same sequence everywhere).
struct SplitMix64 {
    std::uint64_t state;
    std::uint64_t next() {
        std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
        return z ^ (z >> 31);
    }
    // Uniform in [0, n) without modulo bias.
    std::uint64_t below(std::uint64_t n) {
        const std::uint64_t limit = std::numeric_limits<std::uint64_t>::max() -
                                    std::numeric_limits<std::uint64_t>::max() % n;
        std::uint64_t r = next();
        while (r >= limit) r = next();
        return r % n;
    }
};

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
        throw std::invalid_argument(cat({"3D flooding runs single-stage plans only, not \"",
                                         plan.name(), "\" (no half resolution in 3D)"}));
    }
    return plan;
}

SiteGrid3 flood3d(const std::vector<Site3>& sites, Extent3 extent, const Plan& plan, int threads) {
    checkSites(sites, extent);
    if (plan.stages().size() != 1) {
        throw std::invalid_argument(
            cat({"3D flooding runs single-stage plans only, not ", plan.describe()}));
    }
    SiteGrid3 grid(extent);
    Cells& a = grid.cells;
    for (std::size_t i = 0; i < sites.size(); ++i) { // seed: distance 0, ties by id then index
        const Site3& s = sites[i];
        std::int32_t& cell = a[grid.index(s.x, s.y, s.z)];
        if (cell == kNoSite || tieLess(sites.data(), std::int32_t(i), cell)) cell = std::int32_t(i);
    }
    const Stage& stage = plan.stages().front();
    const std::size_t rows = std::size_t(extent.height) * std::size_t(extent.depth);
    const int n = threadCount(threads, rows);
    Cells b(a.size());
    std::vector<char> changed(static_cast<std::size_t>(n)); // one flag per chunk
    for (int step : stage.steps) {
        parallelChunks(rows, n, [&](int t, std::size_t begin, std::size_t end) {
            changed[std::size_t(t)] = pass3d(a, b, extent, step, sites.data(), begin, end);
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
    std::vector<std::int64_t> dist(extent.voxels(), kInf);
    if (sites.empty()) {
        std::fill(dist.begin(), dist.end(), kNoDistance);
        return dist;
    }
    for (const Site3& s : sites)
        dist[(std::size_t(s.z) * h + std::size_t(s.y)) * w + std::size_t(s.x)] = 0;
    // Along x (line = row (y, z)), then y (line = column (x, z)), then z (line = (x, y)).
    transformLines(
        dist, h * d, extent.width, 1, [&](std::size_t i) { return i * w; }, threads);
    transformLines(
        dist, w * d, extent.height, w, [&](std::size_t i) { return (i / w) * w * h + i % w; },
        threads);
    transformLines(
        dist, w * h, extent.depth, w * h, [](std::size_t i) { return i; }, threads);
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
    parallelItems(std::size_t(extent.depth), threads, [&](std::size_t z) {
        const Cells result =
            floodProjected(sites, extent, int(z), plan, projectChecked(sites, extent, int(z)));
        std::copy(result.begin(), result.end(), grid.cells.begin() + std::ptrdiff_t(z * sliceSize));
    });
    return grid;
}

// ---- errors and the experiment -----------------------------------------------------------------

std::string ErrorCount3d::describe() const {
    std::string text =
        cat({method, " on ", extentText(extent), ", ", std::to_string(sites),
             sites == 1 ? " site: " : " sites: ", std::to_string(erroneous),
             " erroneous voxels of ", std::to_string(voxels), " (",
             percentText(voxels > 0 ? double(erroneous) / double(voxels) : 0.0), ")"});
    if (empty > 0) text += cat({", ", std::to_string(empty), " without a site"});
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
        throw std::invalid_argument(cat({"randomSites3d: ", std::to_string(count),
                                         " distinct sites do not fit into ", extentText(extent)}));
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
    return cat({std::to_string(size), "^3, ", std::to_string(sites), " sites, ", method, ": mean ",
                mean, " erroneous voxels (per seed: ", seeds, "), ", perSite, " per site"});
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
                rows.push_back({size, count, cat({"3D ", plan.name()}), {}});
            for (const Plan& plan : slicePlans) {
                rows.push_back({size, count, cat({"slice ", plan.name()}), {}});
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
