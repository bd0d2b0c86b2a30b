#include <jfa/CpuKernel.h>
#include <jfa/Reference.h>

#include "LowerEnvelope.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

namespace fl::jfa {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

ExactField emptyField(int width, int height) {
    ExactField field;
    field.nearest = Grid(width, height, kEmptyCell);
    field.distSq.assign(field.nearest.cells.size(), kInfinity);
    return field;
}

void checkSeeds(const Grid& seeds, const char* what) {
    if (seeds.width < 1 || seeds.height < 1 ||
        seeds.cells.size() != std::size_t(seeds.width) * std::size_t(seeds.height)) {
        throw std::invalid_argument(std::string(what) + ": malformed " +
                                    std::to_string(seeds.width) + "x" +
                                    std::to_string(seeds.height) + " seed grid");
    }
}

// Keeps the nearer of `candidate` and the best so far (ties: NearestSite's order).
struct Nearest {
    const Cell* best = nullptr;
    double dist = kInfinity;

    void offer(const NearestSite& criterion, int px, int py, const Cell& candidate) {
        const double d = squaredDistance(criterion, px, py, candidate);
        if (best == nullptr || d < dist ||
            (d == dist && criterion.better(px, py, candidate, *best))) {
            best = &candidate;
            dist = d;
        }
    }
};

// Position the criterion measures from: truncated to integers for integer sites (as
// NearestSite::squaredInt converts), the float position otherwise.
double effective(const NearestSite& criterion, float v) {
    return criterion.integerSites ? double(static_cast<long long>(v)) : double(v);
}

} // namespace

std::vector<Cell> siteCells(const Grid& seeds) {
    std::vector<Cell> sites;
    for (const Cell& c : seeds.cells) {
        if (!NearestSite{}.empty(c)) sites.push_back(c);
    }
    return sites;
}

double squaredDistance(const NearestSite& criterion, int px, int py, const Cell& c) {
    return criterion.integerSites ? double(NearestSite::squaredInt(px, py, c))
                                  : double(NearestSite::squaredFloat(px, py, c));
}

ExactField bruteForceNearest(const Grid& seeds, const NearestSite& criterion) {
    checkSeeds(seeds, "bruteForceNearest");
    ExactField field = emptyField(seeds.width, seeds.height);
    const std::vector<Cell> sites = siteCells(seeds);
    if (sites.empty()) return field;
    for (int y = 0; y < seeds.height; ++y) {
        for (int x = 0; x < seeds.width; ++x) {
            Nearest nearest;
            for (const Cell& s : sites) nearest.offer(criterion, x, y, s);
            const std::size_t i = std::size_t(y) * std::size_t(seeds.width) + std::size_t(x);
            field.nearest.cells[i] = *nearest.best;
            field.distSq[i] = nearest.dist;
        }
    }
    return field;
}

ExactField exactIntegerEdt(const Grid& seeds) {
    checkSeeds(seeds, "exactIntegerEdt");
    const int w = seeds.width, h = seeds.height;
    const NearestSite criterion{true};
    // Rasterize the sites at their positions; a shared position keeps the better site.
    std::vector<Cell> sites = siteCells(seeds);
    if (sites.empty()) return emptyField(w, h);
    std::vector<int> siteAt(std::size_t(w) * std::size_t(h), -1);
    for (std::size_t i = 0; i < sites.size(); ++i) {
        const Cell& c = sites[i];
        if (!(c.x >= 0.0f && c.y >= 0.0f && c.x <= float(w - 1) && c.y <= float(h - 1) &&
              c.x == std::floor(c.x) && c.y == std::floor(c.y))) {
            throw std::invalid_argument("exactIntegerEdt: site " + std::to_string(c.z) + " at (" +
                                        std::to_string(c.x) + ", " + std::to_string(c.y) +
                                        ") is not an integer position inside the " +
                                        std::to_string(w) + "x" + std::to_string(h) + " grid");
        }
        const int x = int(c.x), y = int(c.y);
        int& slot = siteAt[std::size_t(y) * std::size_t(w) + std::size_t(x)];
        if (slot < 0 || criterion.better(x, y, c, sites[std::size_t(slot)])) slot = int(i);
    }

    // Separable (as the 3D reference): squared distances along each column to the nearest site
    // in it, then along each row over those. Position (x, y) ends up with the column c of its
    // nearest site, and (c, y) kept that site's row r from the column pass.
    const std::size_t n = siteAt.size();
    std::vector<std::int64_t> dist(n, detail::kFarSquared);
    for (std::size_t i = 0; i < n; ++i) {
        if (siteAt[i] >= 0) dist[i] = 0;
    }
    std::vector<int> nearestRow(n), nearestColumn(n);
    const auto wz = std::size_t(w);
    detail::transformLines(
        dist.data(), nearestRow.data(), wz, h, wz, [](std::size_t x) { return x; }, 1);
    detail::transformLines(
        dist.data(), nearestColumn.data(), std::size_t(h), w, 1,
        [wz](std::size_t y) { return y * wz; }, 1);
    ExactField field = emptyField(w, h);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const std::size_t i = std::size_t(y) * wz + std::size_t(x);
            const int c = nearestColumn[i];
            const int r = nearestRow[std::size_t(y) * wz + std::size_t(c)];
            field.nearest.cells[i] =
                sites[std::size_t(siteAt[std::size_t(r) * wz + std::size_t(c)])];
            field.distSq[i] = double(dist[i]);
        }
    }
    return field;
}

ExactField exactNearestSearch(const Grid& seeds, const NearestSite& criterion) {
    checkSeeds(seeds, "exactNearestSearch");
    const int w = seeds.width, h = seeds.height;
    ExactField field = emptyField(w, h);
    const std::vector<Cell> sites = siteCells(seeds);
    if (sites.empty()) return field;

    // Buckets over the bounding box of the sites and the grid, about one site per bucket.
    double minX = 0.0, minY = 0.0, maxX = double(w - 1), maxY = double(h - 1);
    for (const Cell& c : sites) {
        const double x = effective(criterion, c.x), y = effective(criterion, c.y);
        minX = std::min(minX, x);
        maxX = std::max(maxX, x);
        minY = std::min(minY, y);
        maxY = std::max(maxY, y);
    }
    const double spanX = maxX - minX, spanY = maxY - minY;
    const double size = std::max(
        1.0, std::sqrt(std::max(spanX, 1.0) * std::max(spanY, 1.0) / double(sites.size())));
    const int nx = int(std::min(spanX / size, 1.0e6)) + 1,
              ny = int(std::min(spanY / size, 1.0e6)) + 1;
    auto bucketOf = [size](double v, double origin, int count) {
        return int(std::clamp(std::floor((v - origin) / size), 0.0, double(count - 1)));
    };
    std::vector<std::size_t> start(std::size_t(nx) * std::size_t(ny) + 1, 0);
    std::vector<std::size_t> bucket(sites.size());
    for (std::size_t i = 0; i < sites.size(); ++i) {
        const int bx = bucketOf(effective(criterion, sites[i].x), minX, nx);
        const int by = bucketOf(effective(criterion, sites[i].y), minY, ny);
        bucket[i] = std::size_t(by) * std::size_t(nx) + std::size_t(bx);
        ++start[bucket[i] + 1];
    }
    for (std::size_t b = 1; b < start.size(); ++b) start[b] += start[b - 1];
    std::vector<std::size_t> order(sites.size());
    {
        std::vector<std::size_t> fill(start.begin(), start.end() - 1);
        for (std::size_t i = 0; i < sites.size(); ++i) order[fill[bucket[i]]++] = i;
    }

    // Float distances may undershoot the true ones by a relative ~4 * 2^-24; stop only when the
    // unvisited buckets are farther than that (and an absolute slack for bucket rounding).
    constexpr double kRelative = 1.0 - 0x1.0p-16;
    constexpr double kSlack = 1e-9;
    for (int py = 0; py < h; ++py) {
        for (int px = 0; px < w; ++px) {
            const int cx = bucketOf(px, minX, nx), cy = bucketOf(py, minY, ny);
            Nearest nearest;
            auto scan = [&](int bx, int by) {
                const std::size_t b = std::size_t(by) * std::size_t(nx) + std::size_t(bx);
                for (std::size_t k = start[b]; k < start[b + 1]; ++k)
                    nearest.offer(criterion, px, py, sites[order[k]]);
            };
            for (int r = 0;; ++r) {
                const int x0 = cx - r, x1 = cx + r, y0 = cy - r, y1 = cy + r;
                for (int by = std::max(y0, 0); by <= std::min(y1, ny - 1); ++by) {
                    if (by == y0 || by == y1) {
                        for (int bx = std::max(x0, 0); bx <= std::min(x1, nx - 1); ++bx)
                            scan(bx, by);
                    } else {
                        if (x0 >= 0) scan(x0, by);
                        if (x1 < nx && x1 != x0) scan(x1, by);
                    }
                }
                if (x0 <= 0 && y0 <= 0 && x1 >= nx - 1 && y1 >= ny - 1) break;
                if (nearest.best == nullptr) continue;
                double bound = kInfinity; // distance from p to the nearest unvisited bucket
                if (x0 > 0) bound = std::min(bound, px - (minX + x0 * size));
                if (x1 < nx - 1) bound = std::min(bound, minX + (x1 + 1) * size - px);
                if (y0 > 0) bound = std::min(bound, py - (minY + y0 * size));
                if (y1 < ny - 1) bound = std::min(bound, minY + (y1 + 1) * size - py);
                bound -= kSlack;
                if (bound > 0.0 && bound * bound * kRelative > nearest.dist) break;
            }
            const std::size_t i = std::size_t(py) * std::size_t(w) + std::size_t(px);
            field.nearest.cells[i] = *nearest.best;
            field.distSq[i] = nearest.dist;
        }
    }
    return field;
}

ExactField exactNearest(const Grid& seeds, const NearestSite& criterion) {
    checkSeeds(seeds, "exactNearest");
    if (criterion.integerSites) {
        const std::vector<Cell> sites = siteCells(seeds);
        const bool rasterizable = std::all_of(sites.begin(), sites.end(), [&](const Cell& c) {
            return c.x >= 0.0f && c.y >= 0.0f && c.x <= float(seeds.width - 1) &&
                   c.y <= float(seeds.height - 1) && c.x == std::floor(c.x) &&
                   c.y == std::floor(c.y);
        });
        if (rasterizable) return exactIntegerEdt(seeds);
    }
    return exactNearestSearch(seeds, criterion);
}

bool isCorrect(const Grid& flooded, const ExactField& exact, int x, int y,
               const NearestSite& criterion) {
    const Cell& c = flooded.at(x, y);
    const double want = exact.at(x, y);
    if (criterion.empty(c)) return want == kInfinity;
    return squaredDistance(criterion, x, y, c) == want;
}

std::vector<std::uint8_t> errorMask(const Grid& flooded, const ExactField& exact,
                                    const NearestSite& criterion) {
    if (flooded.width != exact.nearest.width || flooded.height != exact.nearest.height ||
        flooded.cells.size() != exact.distSq.size()) {
        throw std::invalid_argument(
            "errorMask: flooded grid " + std::to_string(flooded.width) + "x" +
            std::to_string(flooded.height) + " does not match the exact field " +
            std::to_string(exact.nearest.width) + "x" + std::to_string(exact.nearest.height));
    }
    std::vector<std::uint8_t> mask(flooded.cells.size(), 0);
    for (int y = 0; y < flooded.height; ++y) {
        for (int x = 0; x < flooded.width; ++x) {
            if (!isCorrect(flooded, exact, x, y, criterion))
                mask[std::size_t(y) * std::size_t(flooded.width) + std::size_t(x)] = 1;
        }
    }
    return mask;
}

std::int64_t countErrors(const Grid& flooded, const ExactField& exact,
                         const NearestSite& criterion) {
    std::int64_t errors = 0;
    for (std::uint8_t e : errorMask(flooded, exact, criterion)) errors += e;
    return errors;
}

} // namespace fl::jfa
