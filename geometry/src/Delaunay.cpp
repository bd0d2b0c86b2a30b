// delaunay(): the thesis' pipeline end to end (ch. 6): input checks, G1-G6 through the chosen
// backend, then the CPU steps C1-C4, each timed, with the stages kept on request.
//
// Indices: the backend runs on all input points, so its indices are the input indices; exact
// duplicates always share a pixel, so they are among its missing sites and are simply not
// inserted by C3 (duplicateOf names the point each one repeats). The CPU steps renumber the
// sites in spatial order (Numbering) and map back at the end.
//
// Certification: T' + C1 is trusted only after WorkMesh checks the degree argument on it
// (DelaunayMesh.h), on the exact pixel grid C2 starts from (PixelGrid). §6.4 proves it holds
// for a correct discrete Voronoi diagram; JFA errors or degenerate corners could break it, and
// then (as for inputs whose pixels are collinear) the incremental fallback takes over: slower,
// never wrong. After that every edit is a local one proven to keep a triangulation.
#include <geometry/Delaunay.h>

#include "Stopwatch.h"

#include <geometry/Predicates.h>

#include <geometry/detail/DelaunaySteps.h>

#include <jfa/CpuKernel.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

namespace fl::geom {
namespace {

using detail::WorkMesh;
using glm::dvec2;

using detail::Stopwatch;

// Gives v's memory back (clear() keeps it): the CPU steps drop each array once no later step
// reads it, which lowers the pipeline's peak (peak bytes per point).
template <class T>
void release(std::vector<T>& v) {
    std::vector<T>().swap(v);
}

std::string coords(dvec2 p) {
    char buf[80];
    std::snprintf(buf, sizeof buf, "(%.17g, %.17g)", p.x, p.y);
    return buf;
}

// The input conditions of the header, each with its own message.
void requireTriangulable(const std::vector<dvec2>& points) {
    for (std::size_t i = 0; i < points.size(); ++i)
        if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y))
            throw std::invalid_argument("delaunay: point " + std::to_string(i) +
                                        " has a non-finite coordinate " + coords(points[i]));
    if (points.size() > kMaxDiscreteSites)
        throw std::invalid_argument("delaunay: " + std::to_string(points.size()) +
                                    " points, at most " + std::to_string(kMaxDiscreteSites) +
                                    " are supported");
    if (!points.empty()) {
        const dvec2 a = points.front();
        const auto b = std::find_if(points.begin(), points.end(), [&](dvec2 p) { return p != a; });
        if (b != points.end() &&
            std::any_of(b, points.end(), [&](dvec2 c) { return orient2dSign(a, *b, c) != 0; }))
            return;
    }
    std::vector<dvec2> sorted = points;
    const auto less = [](dvec2 p, dvec2 q) { return p.x != q.x ? p.x < q.x : p.y < q.y; };
    std::sort(sorted.begin(), sorted.end(), less);
    const auto distinct = std::size_t(std::unique(sorted.begin(), sorted.end()) - sorted.begin());
    if (distinct < 3)
        throw std::invalid_argument("delaunay: needs at least 3 distinct points, got " +
                                    std::to_string(distinct) + " (of " +
                                    std::to_string(points.size()) + " points)");
    throw std::invalid_argument("delaunay: all " + std::to_string(distinct) +
                                " distinct points are collinear; they have no triangulation");
}

// The missing sites grouped by key(m) (< buckets), ascending, each group in `missing`'s order
// (ascending site): a counting sort, linear, where comparison sorts of a million pairs took a
// fifth of the pipeline's CPU time at 1M points.
template <class Key>
std::vector<MissingSite> groupMissing(const std::vector<MissingSite>& missing, std::size_t buckets,
                                      const Key& key) {
    std::vector<std::uint32_t> start(buckets + 1, 0);
    for (const MissingSite& m : missing) {
        if (key(m) >= buckets) // a backend's broken result, not to be written out of bounds
            throw std::logic_error("delaunay: missing site " + std::to_string(m.site) +
                                   " has keeper " + std::to_string(m.keeper) + ", not a kept site");
        ++start[key(m) + 1];
    }
    for (std::size_t b = 1; b <= buckets; ++b) start[b] += start[b - 1];
    std::vector<MissingSite> out(missing.size());
    for (const MissingSite& m : missing) out[start[key(m)]++] = m;
    return out;
}

// Fills duplicateOf from G1's missing sites (equal points share a pixel, and the pixel's keeper
// has the lowest index there); returns the number of duplicates. Only sites of one pixel can be
// equal, so each pixel's sites (its keeper and its missing ones, a few on average) are sorted on
// their own, by position and then index: the lowest index of equal points is their original.
std::size_t findDuplicates(const std::vector<dvec2>& points,
                           const std::vector<MissingSite>& missing,
                           std::vector<std::uint32_t>& duplicateOf) {
    duplicateOf.resize(points.size());
    for (std::uint32_t i = 0; i < points.size(); ++i) duplicateOf[i] = i;
    const std::vector<MissingSite> grouped =
        groupMissing(missing, points.size(), [](const MissingSite& m) { return m.keeper; });
    struct Member {
        dvec2 p;
        std::uint32_t index;
    };
    std::vector<Member> pixel; // one pixel's sites
    std::size_t count = 0;
    for (std::size_t i = 0; i < grouped.size();) {
        const std::uint32_t keeper = grouped[i].keeper;
        pixel.assign(1, {points[keeper], keeper});
        for (; i < grouped.size() && grouped[i].keeper == keeper; ++i)
            pixel.push_back({points[grouped[i].site], grouped[i].site});
        std::sort(pixel.begin(), pixel.end(), [](const Member& a, const Member& b) {
            if (a.p.x != b.p.x) return a.p.x < b.p.x;
            if (a.p.y != b.p.y) return a.p.y < b.p.y;
            return a.index < b.index;
        });
        for (std::size_t k = 1; k < pixel.size(); ++k) {
            if (pixel[k].p != pixel[k - 1].p) continue;
            duplicateOf[pixel[k].index] = duplicateOf[pixel[k - 1].index];
            ++count;
        }
    }
    return count;
}

// The CPU steps work on their own numbering of the sites, in spatial order: first the sites of
// S' in the order their triangles appear in T' + C1 (rows of the texture, bottom up), then the
// missing sites grouped by their keeper. Every mesh, position and adjacency array is then read
// nearly sequentially; with input indices (random for random input) each access would be a
// cache miss at a million points.
struct Numbering {
    std::vector<std::uint32_t> inputOf;   // local -> input index
    std::size_t kept = 0;                 // locals [0, kept) are S'
    std::vector<std::uint32_t> missing;   // local index of each missing site (after `kept`)
    std::vector<std::uint32_t> keeper;    // local index of the site that took its pixel
    std::vector<std::uint32_t> triangles; // T' + C1 in local indices
};

Numbering number(const std::vector<std::uint32_t>& tPrime, const std::vector<std::uint32_t>& hull,
                 const SnappedSites& snapped, const std::vector<std::uint32_t>& duplicateOf) {
    Numbering num;
    std::vector<std::uint32_t> localOf(duplicateOf.size(), kNoHalfedge); // kNoHalfedge: none yet
    num.inputOf.reserve(duplicateOf.size());
    const auto add = [&](std::uint32_t v) {
        std::uint32_t& local = localOf[v];
        if (local == kNoHalfedge) {
            local = static_cast<std::uint32_t>(num.inputOf.size());
            num.inputOf.push_back(v);
        }
        return local;
    };
    num.triangles.resize(tPrime.size() + hull.size());
    std::uint32_t* out = num.triangles.data();
    for (std::size_t i = 0; i < tPrime.size(); ++i) {
        // The ids are input indices, in random order for random input: fetch ahead.
        if (i + 16 < tPrime.size()) __builtin_prefetch(&localOf[tPrime[i + 16]], 1);
        *out++ = add(tPrime[i]);
    }
    for (const std::uint32_t v : hull) *out++ = add(v);
    for (const std::uint32_t v : snapped.kept) add(v); // in no triangle: certification fails
    num.kept = num.inputOf.size();
    // By local keeper, then input site (a keeper holds a pixel, so it is among the kept).
    const std::vector<MissingSite> byKeeper = groupMissing(
        snapped.missing, num.kept, [&](const MissingSite& m) { return localOf[m.keeper]; });
    for (const MissingSite& m : byKeeper) {
        if (duplicateOf[m.site] != m.site) continue;
        num.missing.push_back(add(m.site));
        num.keeper.push_back(localOf[m.keeper]);
    }
    return num;
}

// Where C2 starts: each site of S' at its pixel, in world coordinates, on an exact grid
// base + pixel * h. The mapping's own inverse (TextureMapping::toWorld) rounds, and rounding can
// turn collinear pixels (a hull edge along a diagonal) into a slightly reflex chain, or flip a
// thin triangle, so the certified T' + C1 would no longer be a triangulation there. On the grid
// every orientation is h^2 times the pixels' one, exactly: base and h are multiples of a power
// of two u chosen so that every grid point is an integer multiple of u below 2^53 u, hence a
// double. h is 1 / scale rounded to a multiple of u (relative error ~2^-37 for ordinary data),
// so the grid sits where the pixels are, up to far less than a pixel.
class PixelGrid {
  public:
    PixelGrid(const TextureMapping& m, dvec2 lo, dvec2 hi) {
        const double reach = std::max({std::fabs(lo.x), std::fabs(lo.y), std::fabs(hi.x),
                                       std::fabs(hi.y), std::numeric_limits<double>::min()});
        u_ = std::max(std::ldexp(1.0, std::ilogb(reach) - 49),
                      std::numeric_limits<double>::denorm_min());
        h_ = std::max(std::round(m.texelSize() / u_), 1.0) * u_;
        const dvec2 corner = m.toWorld(dvec2(0.0)); // pixel (0, 0) in world coordinates
        base_ = {snap(corner.x), snap(corner.y)};
    }
    [[nodiscard]] dvec2 at(glm::ivec2 pixel) const { return base_ + dvec2(pixel) * h_; }

  private:
    [[nodiscard]] double snap(double v) const { return std::round(v / u_) * u_; }
    double u_, h_;
    dvec2 base_;
};

// All sites in boustrophedon pixel order: short walks for the fallback's insertions.
std::vector<std::uint32_t> pixelOrder(const Numbering& num, const SnappedSites& snapped) {
    const int n = std::max(snapped.mapping.size, 1);
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed;
    for (std::uint32_t l = 0; l < num.inputOf.size(); ++l) {
        const glm::ivec2 p = snapped.pixels[num.inputOf[l]];
        const int x = p.y % 2 == 0 ? p.x : n - 1 - p.x;
        keyed.push_back({std::uint64_t(p.y) * std::uint64_t(n) + std::uint64_t(x), l});
    }
    std::sort(keyed.begin(), keyed.end());
    std::vector<std::uint32_t> order;
    order.reserve(keyed.size());
    for (const auto& k : keyed) order.push_back(k.second);
    return order;
}

// The mesh's live triangles in input indices (for the stages).
std::vector<std::uint32_t> inputTriangles(const WorkMesh& mesh, const Numbering& num) {
    std::vector<std::uint32_t> out;
    out.reserve(3 * mesh.liveTriangles());
    for (std::size_t e = 0; e < mesh.triangles.size(); e += 3)
        if (mesh.triangles[e] != detail::kFreeSlot)
            for (std::size_t k = e; k < e + 3; ++k) out.push_back(num.inputOf[mesh.triangles[k]]);
    return out;
}

// The points' bounds; `halved` when they are wider than the largest double, in which case
// the sites are the points halved (exact, apart from subnormals, which only affects which pixel
// they snap to) so that they can be mapped.
struct Sites {
    dvec2 lo, hi;
    bool halved = false;
    std::vector<dvec2> halvedPoints;
};

Sites siteBounds(const std::vector<dvec2>& points) {
    Sites s;
    s.lo = points.front();
    s.hi = s.lo;
    for (const dvec2& p : points) {
        s.lo = glm::min(s.lo, p);
        s.hi = glm::max(s.hi, p);
    }
    s.halved = !std::isfinite(s.hi.x - s.lo.x) || !std::isfinite(s.hi.y - s.lo.y);
    if (s.halved) {
        s.halvedPoints = points;
        for (dvec2& p : s.halvedPoints) p *= 0.5;
    }
    return s;
}

// C1-C4 on the result of G1-G6, one member per step, in the order delaunay() runs them.
class CpuSteps {
  public:
    CpuSteps(const std::vector<dvec2>& points, const DelaunayOptions& options, const Sites& sites,
             DelaunayResult& r)
        : points_(points), options_(options), sites_(sites), r_(r) {}

    // C1: the hull T' lacks, the CPU steps' numbering, the mesh at the sites' pixels, certified
    // as a triangulation (or rebuilt on the final positions).
    void completeHull() {
        const std::vector<std::uint32_t>& tPrime = r_.discrete.triangles();
        for (const std::uint32_t v : tPrime)
            if (v >= points_.size())
                throw std::logic_error("delaunay: T' names site " + std::to_string(v));
        std::vector<std::uint32_t> hull; // the triangles C1 adds
        const std::optional<std::size_t> added = detail::completeHull(r_.discrete, hull);
        r_.counts.hullTriangles = added.value_or(0);
        r_.cpu.c1 = clock_.lap();
        if (options_.keepStages) {
            keep(tPrime);
            std::vector<std::uint32_t> c1 = tPrime;
            c1.insert(c1.end(), hull.begin(), hull.end());
            keep(std::move(c1));
        }
        clock_.lap();
        num_ = number(tPrime, hull, r_.discrete.snapped, r_.duplicateOf);
        const bool finite = startPositions();
        // The degree argument certifies T' + C1 as a triangulation of S' on those positions;
        // anything else goes to the fallback.
        const bool certified =
            added && finite && num_.kept >= 3 && mesh_->setTriangles(std::move(num_.triangles)) &&
            (r_.discrete.mesh.stats.degenerate == 0 || mesh_->flipFlatTriangles()) &&
            mesh_->isTriangulation(num_.kept);
        if (!certified) fallback();
        r_.cpu.c1 += clock_.lap();
    }

    // C2, in the numbering's (spatial) order.
    void shift() {
        if (!rebuilt_) {
            std::vector<std::uint32_t> order(num_.kept);
            for (std::uint32_t l = 0; l < num_.kept; ++l) order[l] = l;
            detail::ShiftStats shifted = detail::shiftSites(*mesh_, target_, order);
            r_.counts.goodShifts = shifted.good;
            r_.counts.badShifts = shifted.bad;
            deferred_ = std::move(shifted.deferred);
            if (shifted.stuck) fallback();
        }
        release(target_); // the mesh's points are the targets now
        r_.cpu.c2 = clock_.lap();
        if (options_.keepStages) keep(inputTriangles(*mesh_, num_));
        clock_.lap();
    }

    // C3: first the sites C2 had to leave out, then the missing ones, each from its keeper.
    void insertMissing() {
        if (!rebuilt_) {
            std::vector<std::uint32_t> toInsert = deferred_, near = deferred_;
            toInsert.insert(toInsert.end(), num_.missing.begin(), num_.missing.end());
            near.insert(near.end(), num_.keeper.begin(), num_.keeper.end());
            r_.counts.missingInserted = num_.missing.size();
            release(num_.missing);
            release(num_.keeper);
            release(deferred_);
            // Room for every triangle C3 makes (two per site), so the arrays are not copied as
            // they double, nor left up to twice as large as they need to be.
            mesh_->reserveCapacity(2 * toInsert.size());
            const std::size_t steps0 = mesh_->walkSteps, flips0 = mesh_->insertFlips;
            r_.counts.sequentialInserts =
                detail::insertSites(*mesh_, toInsert, near, options_.discrete.threads);
            r_.counts.walkSteps = mesh_->walkSteps - steps0;
            r_.counts.insertFlips = mesh_->insertFlips - flips0;
        }
        r_.cpu.c3 = clock_.lap();
        if (options_.keepStages) keep(inputTriangles(*mesh_, num_));
        clock_.lap();
    }

    // C4 in the local numbering (cache-friendly), then back to input indices.
    void flip() {
        mesh_->compact();
        r_.counts.flips = detail::flipToDelaunay(*mesh_, options_.discrete.threads);
        std::vector<std::uint32_t>& tris = mesh_->triangles;
        jfa::parallelRows(int(tris.size() / 3), options_.discrete.threads,
                          [&](int begin, int end, int) {
                              for (auto e = 3 * std::size_t(begin); e < 3 * std::size_t(end); ++e)
                                  tris[e] = num_.inputOf[tris[e]];
                          });
        r_.mesh.triangles = std::move(mesh_->triangles);
        r_.mesh.halfedges = std::move(mesh_->halfedges);
        mesh_.reset(); // its points and vertex edges, before the result's copy of the points
        num_ = {};
        r_.mesh.points = points_;
        r_.cpu.c4 = clock_.lap();
        keep(r_.mesh.triangles);
    }

    // The exact checker over the result (--check); a failure is a bug of the pipeline.
    void check() {
        clock_.lap();
        const TriangulationReport report = checkTriangulation(r_.mesh);
        r_.cpu.check = clock_.lap();
        if (!report.ok())
            throw std::runtime_error("delaunay: the result is not the Delaunay triangulation "
                                     "(a bug in the pipeline):\n" +
                                     report.summary());
    }

  private:
    // Every site at its final position (C2's targets), and where C2 starts from: the sites of
    // S' at their pixels, in world coordinates; false when a start is not finite.
    bool startPositions() {
        const SnappedSites& snapped = r_.discrete.snapped;
        const bool halved = sites_.halved;
        const PixelGrid grid(snapped.mapping, halved ? sites_.lo * 0.5 : sites_.lo,
                             halved ? sites_.hi * 0.5 : sites_.hi);
        target_.assign(num_.inputOf.size(), dvec2(0.0));
        std::vector<dvec2> start(num_.inputOf.size());
        std::atomic<bool> finite = true;
        jfa::parallelRows(int(target_.size()), options_.discrete.threads,
                          [&](int begin, int end, int) {
                              for (auto l = std::size_t(begin); l < std::size_t(end); ++l) {
                                  if (l + 16 < std::size_t(end)) {
                                      __builtin_prefetch(&points_[num_.inputOf[l + 16]]);
                                      __builtin_prefetch(&snapped.pixels[num_.inputOf[l + 16]]);
                                  }
                                  const std::uint32_t i = num_.inputOf[l];
                                  target_[l] = points_[i];
                                  if (l >= num_.kept) {
                                      start[l] = target_[l];
                                  } else {
                                      start[l] = grid.at(snapped.pixels[i]);
                                      if (halved) start[l] *= 2.0;
                                      if (!std::isfinite(start[l].x) || !std::isfinite(start[l].y))
                                          finite = false;
                                  }
                              }
                          });
        mesh_.emplace(std::move(start), options_.discrete.threads);
        return finite;
    }

    void fallback() {
        mesh_->points = target_;
        detail::rebuild(*mesh_, pixelOrder(num_, r_.discrete.snapped));
        ++r_.counts.rebuilds;
        rebuilt_ = true;
    }

    void keep(std::vector<std::uint32_t> stage) {
        if (options_.keepStages) r_.stages.push_back(std::move(stage));
    }

    const std::vector<dvec2>& points_;
    const DelaunayOptions& options_;
    const Sites& sites_;
    DelaunayResult& r_;
    Stopwatch clock_;
    Numbering num_;
    std::vector<dvec2> target_;
    std::optional<WorkMesh> mesh_;
    std::vector<std::uint32_t> deferred_;
    bool rebuilt_ = false;
};

} // namespace

DelaunayResult delaunay(const std::vector<dvec2>& points, const DelaunayOptions& options) {
    requireTriangulable(points);
    DelaunayResult r;
    // G1-G6.
    const Sites sites = siteBounds(points);
    const std::vector<dvec2>& mapped = sites.halved ? sites.halvedPoints : points;
    r.discrete = options.discreteBackend ? options.discreteBackend(mapped, options.discrete)
                                         : discreteDelaunay(mapped, options.discrete);
    if (r.discrete.snapped.pixels.size() != points.size())
        throw std::logic_error("delaunay: the discrete backend returned " +
                               std::to_string(r.discrete.snapped.pixels.size()) + " pixels for " +
                               std::to_string(points.size()) + " points");
    r.counts.duplicates = findDuplicates(points, r.discrete.snapped.missing, r.duplicateOf);
    // C1-C4 (and the check).
    CpuSteps steps(points, options, sites, r);
    steps.completeHull();
    steps.shift();
    steps.insertMissing();
    steps.flip();
    if (options.check) steps.check();
    return r;
}

} // namespace fl::geom
