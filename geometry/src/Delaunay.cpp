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

#include "DelaunaySteps.h"

#include <jfa/CpuKernel.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace fl::geom {
namespace {

using detail::WorkMesh;
using glm::dvec2;

using detail::Stopwatch;

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

// Fills duplicateOf from G1's missing sites (equal points share a pixel, and the pixel's keeper
// has the lowest index there); returns the number of duplicates.
std::size_t findDuplicates(const std::vector<dvec2>& points,
                           const std::vector<MissingSite>& missing,
                           std::vector<std::uint32_t>& duplicateOf) {
    duplicateOf.resize(points.size());
    for (std::uint32_t i = 0; i < points.size(); ++i) duplicateOf[i] = i;
    struct Member {
        std::uint32_t keeper, index;
    };
    std::vector<Member> members;
    members.reserve(2 * missing.size());
    for (const MissingSite& m : missing) members.push_back({m.keeper, m.site});
    for (const MissingSite& m : missing) members.push_back({m.keeper, m.keeper});
    std::sort(members.begin(), members.end(), [&](const Member& a, const Member& b) {
        if (a.keeper != b.keeper) return a.keeper < b.keeper;
        const dvec2 p = points[a.index], q = points[b.index];
        if (p.x != q.x) return p.x < q.x;
        if (p.y != q.y) return p.y < q.y;
        return a.index < b.index;
    });
    std::size_t count = 0;
    for (std::size_t i = 1; i < members.size(); ++i) {
        const Member& first = members[i - 1];
        const Member& m = members[i];
        if (m.index == first.index || m.keeper != first.keeper ||
            points[m.index] != points[first.index])
            continue;
        duplicateOf[m.index] = duplicateOf[first.index];
        ++count;
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
    std::vector<std::uint32_t> localOf;   // input -> local index (kNoHalfedge: not a site)
    std::size_t kept = 0;                 // locals [0, kept) are S'
    std::vector<std::uint32_t> missing;   // local index of each missing site (after `kept`)
    std::vector<std::uint32_t> keeper;    // local index of the site that took its pixel
    std::vector<std::uint32_t> triangles; // T' + C1 in local indices
};

Numbering number(const std::vector<std::uint32_t>& tPrime, const std::vector<std::uint32_t>& hull,
                 const SnappedSites& snapped, const std::vector<std::uint32_t>& duplicateOf) {
    Numbering num;
    num.localOf.assign(duplicateOf.size(), kNoHalfedge);
    num.inputOf.reserve(duplicateOf.size());
    const auto add = [&](std::uint32_t v) {
        std::uint32_t& local = num.localOf[v];
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
        if (i + 16 < tPrime.size()) __builtin_prefetch(&num.localOf[tPrime[i + 16]], 1);
        *out++ = add(tPrime[i]);
    }
    for (const std::uint32_t v : hull) *out++ = add(v);
    for (const std::uint32_t v : snapped.kept) add(v); // in no triangle: certification fails
    num.kept = num.inputOf.size();
    std::vector<std::pair<std::uint32_t, std::uint32_t>> byKeeper; // (local keeper, input site)
    for (const MissingSite& m : snapped.missing)
        if (duplicateOf[m.site] == m.site) byKeeper.push_back({num.localOf[m.keeper], m.site});
    std::sort(byKeeper.begin(), byKeeper.end());
    for (const auto& [keeper, site] : byKeeper) {
        add(site);
        num.missing.push_back(num.localOf[site]);
        num.keeper.push_back(keeper);
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

} // namespace

DelaunayResult delaunay(const std::vector<dvec2>& points, const DelaunayOptions& options) {
    requireTriangulable(points);
    DelaunayResult r;

    // G1-G6. A bounding box wider than the largest double cannot be mapped; halving the points
    // (exact, apart from subnormals, which only affects which pixel they snap to) makes it fit.
    dvec2 lo = points.front(), hi = lo;
    for (const dvec2& p : points) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const bool halved = !std::isfinite(hi.x - lo.x) || !std::isfinite(hi.y - lo.y);
    std::vector<dvec2> halvedPoints;
    if (halved) {
        halvedPoints = points;
        for (dvec2& p : halvedPoints) p *= 0.5;
    }
    const std::vector<dvec2>& sites = halved ? halvedPoints : points;
    r.discrete = options.discreteBackend ? options.discreteBackend(sites, options.discrete)
                                         : discreteDelaunay(sites, options.discrete);
    const SnappedSites& snapped = r.discrete.snapped;
    if (snapped.pixels.size() != points.size())
        throw std::logic_error("delaunay: the discrete backend returned " +
                               std::to_string(snapped.pixels.size()) + " pixels for " +
                               std::to_string(points.size()) + " points");
    r.counts.duplicates = findDuplicates(points, snapped.missing, r.duplicateOf);
    const auto keep = [&](std::vector<std::uint32_t> stage) {
        if (options.keepStages) r.stages.push_back(std::move(stage));
    };

    Stopwatch clock;
    // C1 on T' (input indices), then the CPU steps' own numbering.
    const std::vector<std::uint32_t>& tPrime = r.discrete.triangles();
    for (const std::uint32_t v : tPrime)
        if (v >= points.size())
            throw std::logic_error("delaunay: T' names site " + std::to_string(v));
    std::vector<std::uint32_t> hull; // the triangles C1 adds
    const std::optional<std::size_t> added = detail::completeHull(r.discrete, hull);
    r.counts.hullTriangles = added.value_or(0);
    r.cpu.c1 = clock.lap();
    if (options.keepStages) {
        keep(tPrime);
        std::vector<std::uint32_t> c1 = tPrime;
        c1.insert(c1.end(), hull.begin(), hull.end());
        keep(std::move(c1));
    }
    clock.lap();
    Numbering num = number(tPrime, hull, snapped, r.duplicateOf);
    // Every site at its final position (C2's targets), and where C2 starts from: the sites of
    // S' at their pixels, in world coordinates.
    const PixelGrid grid(snapped.mapping, halved ? lo * 0.5 : lo, halved ? hi * 0.5 : hi);
    std::vector<dvec2> target(num.inputOf.size()), start(num.inputOf.size());
    std::atomic<bool> finite = true;
    jfa::parallelRows(int(target.size()), options.discrete.threads, [&](int begin, int end, int) {
        for (auto l = std::size_t(begin); l < std::size_t(end); ++l) {
            if (l + 16 < std::size_t(end)) {
                __builtin_prefetch(&points[num.inputOf[l + 16]]);
                __builtin_prefetch(&snapped.pixels[num.inputOf[l + 16]]);
            }
            const std::uint32_t i = num.inputOf[l];
            target[l] = points[i];
            if (l >= num.kept) {
                start[l] = target[l];
            } else {
                start[l] = grid.at(snapped.pixels[i]);
                if (halved) start[l] *= 2.0;
                if (!std::isfinite(start[l].x) || !std::isfinite(start[l].y)) finite = false;
            }
        }
    });
    WorkMesh mesh(std::move(start), options.discrete.threads);
    // The degree argument certifies T' + C1 as a triangulation of S' on those positions;
    // anything else goes to the fallback.
    const bool certified = added && finite && num.kept >= 3 &&
                           mesh.setTriangles(std::move(num.triangles)) &&
                           (r.discrete.mesh.stats.degenerate == 0 || mesh.flipFlatTriangles()) &&
                           mesh.isTriangulation(num.kept);
    bool rebuilt = false;
    const auto fallback = [&] {
        mesh.points = target;
        detail::rebuild(mesh, pixelOrder(num, snapped));
        ++r.counts.rebuilds;
        rebuilt = true;
    };
    if (!certified) fallback();
    r.cpu.c1 += clock.lap();

    // C2, in the numbering's (spatial) order.
    std::vector<std::uint32_t> deferred;
    if (!rebuilt) {
        std::vector<std::uint32_t> order(num.kept);
        for (std::uint32_t l = 0; l < num.kept; ++l) order[l] = l;
        detail::ShiftStats shifted = detail::shiftSites(mesh, target, order);
        r.counts.goodShifts = shifted.good;
        r.counts.badShifts = shifted.bad;
        deferred = std::move(shifted.deferred);
        if (shifted.stuck) fallback();
    }
    r.cpu.c2 = clock.lap();
    if (options.keepStages) keep(inputTriangles(mesh, num));
    clock.lap();

    // C3: first the sites C2 had to leave out, then the missing ones, each from its keeper.
    if (!rebuilt) {
        std::vector<std::uint32_t> toInsert = deferred, near = deferred;
        toInsert.insert(toInsert.end(), num.missing.begin(), num.missing.end());
        near.insert(near.end(), num.keeper.begin(), num.keeper.end());
        const std::size_t steps0 = mesh.walkSteps, flips0 = mesh.insertFlips;
        r.counts.sequentialInserts =
            detail::insertSites(mesh, toInsert, near, options.discrete.threads);
        r.counts.walkSteps = mesh.walkSteps - steps0;
        r.counts.insertFlips = mesh.insertFlips - flips0;
        r.counts.missingInserted = num.missing.size();
    }
    r.cpu.c3 = clock.lap();
    if (options.keepStages) keep(inputTriangles(mesh, num));
    clock.lap();

    // C4 in the local numbering (cache-friendly), then back to input indices.
    mesh.compact();
    r.counts.flips = mesh.makeDelaunay();
    for (std::uint32_t& v : mesh.triangles) v = num.inputOf[v];
    r.mesh.points = points;
    r.mesh.triangles = std::move(mesh.triangles);
    r.mesh.halfedges = std::move(mesh.halfedges);
    r.cpu.c4 = clock.lap();
    keep(r.mesh.triangles);

    if (options.check) {
        clock.lap();
        const TriangulationReport report = checkTriangulation(r.mesh);
        r.cpu.check = clock.lap();
        if (!report.ok())
            throw std::runtime_error("delaunay: the result is not the Delaunay triangulation "
                                     "(a bug in the pipeline):\n" +
                                     report.summary());
    }
    return r;
}

} // namespace fl::geom
