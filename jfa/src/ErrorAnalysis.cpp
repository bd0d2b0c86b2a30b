// Error analysis of JFA Voronoi diagrams (thesis §4.4, §4.5); definitions in the header.
#include <jfa/ErrorAnalysis.h>

#include <jfa/NearestSite.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace fl::jfa {
namespace {

std::size_t indexOf(int x, int y, int width) {
    return std::size_t(y) * std::size_t(width) + std::size_t(x);
}

void checkSizes(const ExactDiagramView& exact) {
    const std::size_t n =
        std::size_t(std::max(exact.width, 0)) * std::size_t(std::max(exact.height, 0));
    if (exact.width < 0 || exact.height < 0 || exact.squared.size() != n)
        throw std::invalid_argument("error analysis: exact diagram " + std::to_string(exact.width) +
                                    "x" + std::to_string(exact.height) + " has " +
                                    std::to_string(exact.squared.size()) + " distances");
}

// Squared distance from (x, y) to site c in NearestSite's arithmetic, widened exactly to double.
double squaredDistance(int x, int y, const Cell& c, bool integerSites) {
    if (integerSites) return static_cast<double>(NearestSite::squaredInt(x, y, c));
    return static_cast<double>(NearestSite::squaredFloat(x, y, c));
}

bool samePosition(const Cell& a, const Cell& b) {
    return a.x == b.x && a.y == b.y;
}

} // namespace

// ---- error pixels and clusters -----------------------------------------------------------------

bool isErrorPixel(const Cell& c, int x, int y, double exactSquared, bool integerSites) {
    if (c.z < 0.0f) return true;
    return squaredDistance(x, y, c, integerSites) > exactSquared;
}

std::vector<std::uint8_t> errorPixelMask(const Grid& flooded, const ExactDiagramView& exact) {
    checkSizes(exact);
    if (flooded.width != exact.width || flooded.height != exact.height ||
        flooded.cells.size() != exact.squared.size())
        throw std::invalid_argument(
            "error analysis: flooded grid " + std::to_string(flooded.width) + "x" +
            std::to_string(flooded.height) + " but exact diagram " + std::to_string(exact.width) +
            "x" + std::to_string(exact.height));
    std::vector<std::uint8_t> mask(flooded.cells.size(), 0);
    const bool noSites = exact.sites.empty();
    for (int y = 0; y < exact.height; ++y) {
        for (int x = 0; x < exact.width; ++x) {
            const std::size_t i = indexOf(x, y, exact.width);
            const Cell& c = flooded.cells[i];
            // Without any site the only correct cell is an empty one.
            const bool error =
                noSites ? c.z >= 0.0f : isErrorPixel(c, x, y, exact.squared[i], exact.integerSites);
            mask[i] = error ? 1 : 0;
        }
    }
    return mask;
}

ClusterStats errorClusters(std::span<const std::uint8_t> mask, int width, int height) {
    if (width < 0 || height < 0 || mask.size() != std::size_t(width) * std::size_t(height))
        throw std::invalid_argument("error clusters: mask of " + std::to_string(mask.size()) +
                                    " values for " + std::to_string(width) + "x" +
                                    std::to_string(height));
    ClusterStats stats;
    std::vector<std::uint8_t> seen(mask.size(), 0);
    std::vector<std::pair<int, int>> stack;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const std::size_t start = indexOf(x, y, width);
            if (mask[start] == 0 || seen[start] != 0) continue;
            std::int64_t size = 0;
            seen[start] = 1;
            stack.assign(1, {x, y});
            while (!stack.empty()) {
                const auto [cx, cy] = stack.back();
                stack.pop_back();
                ++size;
                for (int dy = -1; dy <= 1; ++dy) {
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int nx = cx + dx, ny = cy + dy;
                        if (nx < 0 || ny < 0 || nx >= width || ny >= height) continue;
                        const std::size_t ni = indexOf(nx, ny, width);
                        if (mask[ni] == 0 || seen[ni] != 0) continue;
                        seen[ni] = 1;
                        stack.emplace_back(nx, ny);
                    }
                }
            }
            stats.errorPixels += size;
            ++stats.clusters;
            ++stats.sizeHistogram[size];
            if (size == 1) {
                ++stats.singles;
                stats.singleIndices.push_back(static_cast<std::int64_t>(start));
            }
        }
    }
    return stats;
}

// ---- exact nearest-site sets and Voronoi vertices ----------------------------------------------

SiteIndex::SiteIndex(std::span<const Cell> sites, bool integerSites) : integerSites_(integerSites) {
    std::vector<Cell> all(sites.begin(), sites.end());
    for (const Cell& c : all)
        if (!std::isfinite(c.x) || !std::isfinite(c.y))
            throw std::invalid_argument("site index: non-finite site position");
    std::sort(all.begin(), all.end(), [](const Cell& a, const Cell& b) {
        if (a.x != b.x) return a.x < b.x;
        if (a.y != b.y) return a.y < b.y;
        return a.z < b.z;
    });
    all.erase(std::unique(all.begin(), all.end(), samePosition), all.end()); // keeps smallest id
    if (all.empty()) {
        bucketStart_.assign(1, 0);
        return;
    }
    double maxX = all.front().x, maxY = all.front().y;
    minX_ = maxX;
    minY_ = maxY;
    for (const Cell& c : all) {
        minX_ = std::min(minX_, double(c.x));
        minY_ = std::min(minY_, double(c.y));
        maxX = std::max(maxX, double(c.x));
        maxY = std::max(maxY, double(c.y));
    }
    // About one site per bucket, at most 2048 buckets per axis.
    const double area = (maxX - minX_ + 1.0) * (maxY - minY_ + 1.0);
    bucketSize_ = std::max({1.0, std::sqrt(area / double(all.size())), (maxX - minX_) / 2047.0,
                            (maxY - minY_) / 2047.0});
    bucketsX_ = int((maxX - minX_) / bucketSize_) + 1;
    bucketsY_ = int((maxY - minY_) / bucketSize_) + 1;
    const auto bucketOf = [this](const Cell& c) {
        const int bx = std::min(bucketsX_ - 1, int((c.x - minX_) / bucketSize_));
        const int by = std::min(bucketsY_ - 1, int((c.y - minY_) / bucketSize_));
        return std::size_t(by) * std::size_t(bucketsX_) + std::size_t(bx);
    };
    bucketStart_.assign(std::size_t(bucketsX_) * std::size_t(bucketsY_) + 1, 0);
    for (const Cell& c : all) ++bucketStart_[bucketOf(c) + 1];
    for (std::size_t b = 1; b < bucketStart_.size(); ++b) bucketStart_[b] += bucketStart_[b - 1];
    sites_.resize(all.size());
    std::vector<std::int32_t> fill(bucketStart_.begin(), bucketStart_.end() - 1);
    for (const Cell& c : all) sites_[std::size_t(fill[bucketOf(c)]++)] = c;
}

std::vector<Cell> SiteIndex::sitesAt(int x, int y, double squared) const {
    std::vector<Cell> found;
    if (sites_.empty() || !(squared >= 0.0) || !std::isfinite(squared)) return found;
    // Every site at that squared distance lies within sqrt(squared) of (x, y) up to the rounding
    // of the float arithmetic; the margin of one pixel covers that many times over.
    const double reach = std::sqrt(squared) * (1.0 + 1e-6) + 1.0;
    const auto clampBucket = [](double v, int count) {
        return int(std::clamp(std::floor(v), 0.0, double(count - 1)));
    };
    const double bx0 = (x - reach - minX_) / bucketSize_, bx1 = (x + reach - minX_) / bucketSize_;
    const double by0 = (y - reach - minY_) / bucketSize_, by1 = (y + reach - minY_) / bucketSize_;
    if (bx1 < 0.0 || by1 < 0.0 || bx0 >= bucketsX_ || by0 >= bucketsY_) return found;
    const int x0 = clampBucket(bx0, bucketsX_), x1 = clampBucket(bx1, bucketsX_);
    const int y0 = clampBucket(by0, bucketsY_), y1 = clampBucket(by1, bucketsY_);
    for (int by = y0; by <= y1; ++by) {
        for (int bx = x0; bx <= x1; ++bx) {
            const std::size_t b = std::size_t(by) * std::size_t(bucketsX_) + std::size_t(bx);
            for (std::int32_t i = bucketStart_[b]; i < bucketStart_[b + 1]; ++i) {
                const Cell& c = sites_[std::size_t(i)];
                if (squaredDistance(x, y, c, integerSites_) == squared) found.push_back(c);
            }
        }
    }
    std::sort(found.begin(), found.end(), [](const Cell& a, const Cell& b) { return a.z < b.z; });
    return found;
}

bool isDiscreteVoronoiVertex(const ExactDiagramView& exact, const SiteIndex& index, int x, int y) {
    checkSizes(exact);
    if (x < 0 || y < 0 || x >= exact.width || y >= exact.height) return false;
    std::vector<Cell> distinct;
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            const int qx = x + dx, qy = y + dy;
            if (qx < 0 || qy < 0 || qx >= exact.width || qy >= exact.height) continue;
            for (const Cell& s :
                 index.sitesAt(qx, qy, exact.squared[indexOf(qx, qy, exact.width)])) {
                const bool known = std::any_of(distinct.begin(), distinct.end(),
                                               [&](const Cell& d) { return samePosition(d, s); });
                if (!known) distinct.push_back(s);
                if (distinct.size() >= 3) return true;
            }
        }
    }
    return false;
}

// ---- the estimate E ----------------------------------------------------------------------------

int jfaPassCount(int n) {
    int passes = 0;
    for (long long step = 1; step <= static_cast<long long>(n) - 1; step *= 2) ++passes;
    return passes;
}

// Thesis §4.4 (it numbers no equations; cited by property). With x = 1 / (pi R) and
// S = sum_{k=0}^{log n - 2} 4^{-3(k+1)}:
//   Property 4.2:  E1 = 2 (1/3  - 2/(pi R) + 2/(pi^2 R^2)) S   (type-v or type-h paths)
//   Property 4.3:  E2 =   (1/12 - 1/(pi R) + 2/(pi^2 R^2)) S   (type-d paths)
//   after them:    E  = (2m - h - 2)(E1 + E2)
//                     ~ 2m (3/4 - 5/(pi R) + 6/(pi^2 R^2)) S   when m >> h.
// Clamping (the thesis' F terms integrate arc lengths "minus 2 grid points" without clipping
// them at 0, so the quadratics in x turn negative for small R and, below their smaller root, grow
// positive again without bound): F1 = 1/3 - 2x + 2x^2 is used only for x < (3 - sqrt 3)/6, i.e.
// R > 6 / (pi (3 - sqrt 3)) ~ 1.506 px, and F2 = 1/12 - x + 2x^2 only for x < (3 - sqrt 3)/12,
// i.e. R > 12 / (pi (3 - sqrt 3)) ~ 3.013 px; below, the term is 0. Both quadratics increase with
// R above those roots, so the clamped E1, E2 are continuous, non-decreasing in R and >= 0. A NaN
// R counts as 0, R = +inf gives the limits 2S/3 and S/12. The vertex count 2m - h - 2 is used
// for m >= 3 (the thesis states it for m > 3) and clamped at 0; m < 3 has no Voronoi vertex.
ErrorEstimate estimateErrors(std::int64_t m, std::int64_t h, double r, int n) {
    constexpr double pi = std::numbers::pi;
    constexpr double sqrt3 = std::numbers::sqrt3;
    const double rootF1 = 6.0 / (pi * (3.0 - sqrt3));
    const double rootF2 = 12.0 / (pi * (3.0 - sqrt3));

    const int logN = jfaPassCount(n);
    double sum = 0.0;
    for (int k = 0; k <= logN - 2; ++k) sum += std::pow(4.0, -3.0 * double(k + 1));

    ErrorEstimate est;
    const double x = std::isinf(r) ? 0.0 : 1.0 / (pi * r);
    const double f1 = r > rootF1 ? 1.0 / 3.0 - 2.0 * x + 2.0 * x * x : 0.0;
    const double f2 = r > rootF2 ? 1.0 / 12.0 - x + 2.0 * x * x : 0.0;
    est.e1 = 2.0 * std::max(0.0, f1) * sum;
    est.e2 = std::max(0.0, f2) * sum;
    est.vertices = m >= 3 ? double(std::max<std::int64_t>(0, 2 * m - h - 2)) : 0.0;
    est.e = est.vertices * (est.e1 + est.e2);
    return est;
}

// The thesis (§4.5.2) divides the grid area by the number of Delaunay triangles "to estimate the
// radius R of the circumcircle" without saying how. We take the equilateral triangle of that
// area: area = (3 sqrt 3 / 4) R^2, so R = sqrt(4 A / (3 sqrt 3)) ~ 0.877 sqrt(A). Why: Delaunay
// triangles are the "fattest" triangulation (max-min angle), the equilateral is its ideal, and
// it is the smallest circumradius any triangle of area A can have, which matches E being a
// lower-bound-style estimate (E grows with R). For reference, the mean circumradius of Poisson-
// Delaunay triangles is (3/4) sqrt(2A) ~ 1.061 sqrt(A), 21% larger.
double circumradiusFromArea(double area) {
    if (!(area > 0.0) || !std::isfinite(area)) return 0.0;
    return std::sqrt(4.0 * area / (3.0 * std::numbers::sqrt3));
}

double estimateCircumradius(int width, int height, std::int64_t delaunayTriangles) {
    if (delaunayTriangles <= 0 || width <= 0 || height <= 0) return 0.0;
    return circumradiusFromArea(double(width) * double(height) / double(delaunayTriangles));
}

std::int64_t boundaryRegionCount(const ExactDiagramView& exact, const SiteIndex& index) {
    checkSizes(exact);
    std::vector<Cell> sites;
    const auto add = [&](int x, int y) {
        for (const Cell& s : index.sitesAt(x, y, exact.squared[indexOf(x, y, exact.width)]))
            sites.push_back(s);
    };
    for (int x = 0; x < exact.width; ++x) {
        add(x, 0);
        if (exact.height > 1) add(x, exact.height - 1);
    }
    for (int y = 1; y + 1 < exact.height; ++y) {
        add(0, y);
        if (exact.width > 1) add(exact.width - 1, y);
    }
    // The index keeps one site per position, so ids identify positions here.
    std::vector<float> ids;
    for (const Cell& s : sites) ids.push_back(s.z);
    std::sort(ids.begin(), ids.end());
    return std::unique(ids.begin(), ids.end()) - ids.begin();
}

// ---- the report --------------------------------------------------------------------------------

std::string ErrorReport::describe() const {
    std::ostringstream out;
    char share[32];
    if (singles > 0)
        std::snprintf(share, sizeof share, "%.1f%%", 100.0 * singleVertexShare);
    else
        std::snprintf(share, sizeof share, "n/a");
    char estimateText[64];
    std::snprintf(estimateText, sizeof estimateText, "estimate E = %.1f (R = %.1f px)", estimate.e,
                  r);
    out << label << ' ' << width << 'x' << height << ", " << sites
        << (sites == 1 ? " site" : " sites") << ": " << errorPixels << " error pixel"
        << (errorPixels == 1 ? "" : "s") << " in " << clusters << " cluster"
        << (clusters == 1 ? "" : "s") << " (" << singles << " single, " << singlesAtVertices
        << " at Voronoi vertices = " << share << "); " << estimateText;
    return out.str();
}

ErrorReport analyzeErrors(const Grid& flooded, const ExactDiagramView& exact, std::string label) {
    const std::vector<std::uint8_t> mask = errorPixelMask(flooded, exact);
    ClusterStats stats = errorClusters(mask, exact.width, exact.height);
    const SiteIndex index(exact.sites, exact.integerSites);

    ErrorReport report;
    report.label = std::move(label);
    report.width = exact.width;
    report.height = exact.height;
    report.sites = static_cast<std::int64_t>(exact.sites.size());
    report.pixels = std::int64_t(exact.width) * std::int64_t(exact.height);
    report.errorPixels = stats.errorPixels;
    report.clusters = stats.clusters;
    report.singles = stats.singles;
    report.clusterSizes = std::move(stats.sizeHistogram);
    for (const std::int64_t i : stats.singleIndices) {
        const int x = int(i % exact.width), y = int(i / exact.width);
        const bool vertex = isDiscreteVoronoiVertex(exact, index, x, y);
        const bool interior = x > 0 && y > 0 && x + 1 < exact.width && y + 1 < exact.height;
        report.singlesAtVertices += vertex ? 1 : 0;
        report.interiorSingles += interior ? 1 : 0;
        report.interiorSinglesAtVertices += interior && vertex ? 1 : 0;
        if (!vertex) report.singlesOffVertices.push_back(IntPoint{x, y});
    }
    report.singleVertexShare =
        report.singles > 0 ? double(report.singlesAtVertices) / double(report.singles) : 0.0;

    const std::span<const Cell> distinct = index.distinctSites();
    report.m = static_cast<std::int64_t>(distinct.size());
    if (exact.integerSites) {
        std::vector<IntPoint> points;
        for (const Cell& c : distinct) points.push_back({std::int64_t(c.x), std::int64_t(c.y)});
        report.hullBoundarySites =
            std::int64_t(convexHull(points, HullBoundary::KeepCollinear).size());
        report.delaunayTriangles = triangulationTriangleCount(points);
    } else {
        std::vector<RealPoint> points;
        for (const Cell& c : distinct) points.push_back({double(c.x), double(c.y)});
        report.hullBoundarySites =
            std::int64_t(convexHull(points, HullBoundary::KeepCollinear).size());
        report.delaunayTriangles = triangulationTriangleCount(points);
    }
    report.h = boundaryRegionCount(exact, index);
    report.r = estimateCircumradius(exact.width, exact.height, report.delaunayTriangles);
    report.estimate =
        estimateErrors(report.m, report.h, report.r, std::max(exact.width, exact.height));
    return report;
}

} // namespace fl::jfa
