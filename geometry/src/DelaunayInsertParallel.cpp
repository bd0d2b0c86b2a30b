// Step C3 on several threads: the sites to insert are cut into one strip per thread
// (quantiles of their coordinate along the wider axis, so the strips hold equal counts), and
// every vertex of the mesh belongs to the strip its position falls in. Each thread runs the
// incremental Delaunay insertion of DelaunayInsert.cpp on its own strip's sites, in their BRIO
// order, but touches only *its* triangles: those whose three vertices are all in its strip.
//
// Why that is race-free without locks: a triangle with vertices in two strips is frozen (no
// thread changes its vertices), so a thread reads
//   - vertices of its own triangles, and of any triangle across one of their edges (such a
//     triangle shares two of the thread's vertices, so it is the thread's or frozen: nobody
//     else writes its vertices);
//   - halfedges only of edges whose endpoints are both its own: another thread writes a halfedge
//     entry only for an edge with both endpoints in *its* strip;
//   - vertexEdge only of its own vertices; points are not written during C3.
// It writes its own triangles' slots, the halfedge entries of its own edges (also where they
// sit in a frozen neighbour), vertexEdge of its own vertices, and new triangles only into slots
// reserved for it before the threads start (so the arrays never grow while they run).
//
// A site whose walk would enter a triangle that is not the thread's, that lies outside the hull
// or on a vertex, or on an edge next to such a triangle, is left untouched for the sequential pass
// (insertSites), which runs after all threads have joined. A Lawson flip across an edge to a
// triangle that is not the thread's is skipped: the triangulation stays valid (every operation
// is one of WorkMesh's, which keep it, on triangles no one else touches), and C4 flips whatever
// was left. The result after C4 is the Delaunay triangulation, the same set of triangles as the
// sequential path wherever it is unique (tests: delaunay_test, ParallelC3*).
#include <geometry/detail/DelaunaySteps.h>

#include "TriangulationWalk.h"
#include <geometry/detail/TriangulationFlip.h>

#include <base/Parallel.h>

#include <algorithm>
#include <cstdint>

namespace fl::geom::detail {

using glm::dvec2;

// A walk in a strip longer than this gives up (the sequential pass has no limit but the scan).
constexpr std::size_t kStripWalkLimit = 512;
// Sites a strip tries before it may give up for too many failures.
constexpr std::size_t kStripTrial = 256;

class RegionInserter {
  public:
    RegionInserter(WorkMesh& mesh, const std::vector<std::uint8_t>& regionOf, std::uint8_t region,
                   std::vector<std::uint32_t> slots)
        : m_(mesh), regionOf_(regionOf), region_(region), slots_(std::move(slots)),
          random_(2463534242u + region) {}

    /// Appends `count` free slots to the mesh (before the threads start; none grows it after).
    static std::uint32_t reserveSlots(WorkMesh& mesh, std::size_t count) {
        const auto first = static_cast<std::uint32_t>(mesh.triangles.size() / 3);
        mesh.triangles.resize(mesh.triangles.size() + 3 * count, 0);
        mesh.halfedges.resize(mesh.halfedges.size() + 3 * count, kNoHalfedge);
        for (std::size_t t = first; t < first + count; ++t) mesh.triangles[3 * t] = kFreeSlot;
        return first;
    }
    /// After the threads: the slots they did not use become the mesh's free slots, the counters
    /// the mesh's, and the walks' default start a live triangle.
    void finish() {
        m_.freeSlots_.insert(m_.freeSlots_.end(), slots_.begin(), slots_.end());
        m_.walkSteps += steps_;
        m_.insertFlips += flips_;
        if (m_.triangles[3 * m_.lastTriangle_] == kFreeSlot && lastEdge_ != kNoHalfedge)
            m_.lastTriangle_ = lastEdge_ / 3;
    }

  private:
    // WorkMesh's splits take new triangles from this strip's slots (an interior edge split
    // here has both sides this strip's: tryInsert checked).
    [[nodiscard]] auto slotMaker() {
        return [this](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
            return addTriangle(a, b, c);
        };
    }

  public:
    /// Inserts site v walking from site `from` (one of this strip's sites in the mesh, or
    /// kNoHalfedge); false, changing nothing, if that needs a triangle that is not this strip's.
    bool tryInsert(std::uint32_t v, std::uint32_t from) {
        if (from == kNoHalfedge || !ownsVertex(from) || !m_.inMesh(from)) return false;
        // WorkMesh::locate's walk, refusing the triangles that are not this strip's.
        const dvec2 q = m_.points[v];
        const WalkEnd end = visibilityWalk(
            m_.triangles, m_.halfedges, m_.vertexEdge[from] / 3, q, kStripWalkLimit, random_,
            [this](std::uint32_t a, std::uint32_t b, dvec2 p) { return m_.orient(a, b, p); },
            [this](std::uint32_t t) { return ownsTriangle(t); });
        steps_ += end.steps;
        if (end.kind == WalkEnd::Kind::Inside) {
            m_.splitInside(end.triangle, v, slotMaker(), pending_);
        } else if (end.kind == WalkEnd::Kind::OnEdge &&
                   (m_.halfedges[end.edge] == kNoHalfedge ||
                    ownsTriangle(m_.halfedges[end.edge] / 3))) {
            m_.splitOnEdge(end.edge, v, slotMaker(), pending_);
        } else {
            // Outside the hull, on a vertex, too long, on a triangle or beside one not ours.
            return false;
        }
        restoreDelaunay();
        return true;
    }

  private:
    [[nodiscard]] bool ownsVertex(std::uint32_t v) const { return regionOf_[v] == region_; }
    [[nodiscard]] bool ownsTriangle(std::uint32_t t) const {
        const std::uint32_t* tri = &m_.triangles[3 * t];
        return tri[0] != kFreeSlot && ownsVertex(tri[0]) && ownsVertex(tri[1]) &&
               ownsVertex(tri[2]);
    }
    // WorkMesh::addTriangle from this strip's reserved slots (2 per site: always enough).
    std::uint32_t addTriangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        const std::uint32_t t = slots_.back();
        slots_.pop_back();
        std::uint32_t* tri = &m_.triangles[3 * t];
        tri[0] = a;
        tri[1] = b;
        tri[2] = c;
        m_.touch(t);
        lastEdge_ = 3 * t;
        return 3 * t;
    }
    // As WorkMesh::restoreDelaunay, skipping edges to triangles that are not this strip's.
    void restoreDelaunay() {
        const auto noBoundaryTracking = [](std::uint32_t) {};
        while (!pending_.empty()) {
            const std::uint32_t e = pending_.back();
            pending_.pop_back();
            const std::uint32_t o = m_.halfedges[e];
            if (o == kNoHalfedge || !ownsTriangle(o / 3) ||
                !shouldFlip(m_.points, m_.triangles, m_.halfedges, e))
                continue;
            flip(m_.triangles, m_.halfedges, e, noBoundaryTracking);
            ++flips_;
            m_.touch(e / 3);
            m_.touch(o / 3);
            pending_.insert(pending_.end(), {e, prevHalfedge(e), o, prevHalfedge(o)});
        }
    }

    WorkMesh& m_;
    const std::vector<std::uint8_t>& regionOf_;
    std::uint8_t region_;
    std::vector<std::uint32_t> slots_;
    std::vector<std::uint32_t> pending_;
    std::uint32_t random_;
    std::uint32_t lastEdge_ = kNoHalfedge;
    std::size_t steps_ = 0, flips_ = 0;
};

namespace {

// The strip of every mesh point: quantiles of the sites' coordinate along the wider axis of
// their bounding box, so each strip gets the same number of sites.
std::vector<std::uint8_t> stripOf(const WorkMesh& mesh, const std::vector<std::uint32_t>& sites,
                                  int strips) {
    dvec2 lo = mesh.points[sites.front()], hi = lo;
    for (const std::uint32_t s : sites) {
        lo = glm::min(lo, mesh.points[s]);
        hi = glm::max(hi, mesh.points[s]);
    }
    const int axis = hi.x - lo.x >= hi.y - lo.y ? 0 : 1;
    std::vector<double> coord(sites.size());
    for (std::size_t i = 0; i < sites.size(); ++i) coord[i] = mesh.points[sites[i]][axis];
    std::vector<double> cuts;
    for (int k = 1; k < strips; ++k) {
        const auto at =
            coord.begin() + std::ptrdiff_t(coord.size() * std::size_t(k) / std::size_t(strips));
        std::nth_element(coord.begin(), at, coord.end());
        cuts.push_back(*at);
    }
    std::vector<std::uint8_t> strip(mesh.points.size());
    for (std::size_t v = 0; v < strip.size(); ++v)
        strip[v] = static_cast<std::uint8_t>(
            std::upper_bound(cuts.begin(), cuts.end(), mesh.points[v][axis]) - cuts.begin());
    return strip;
}

} // namespace

std::vector<std::uint32_t> insertInStrips(WorkMesh& mesh, const std::vector<std::uint32_t>& sites,
                                          const std::vector<std::uint32_t>& near,
                                          const std::vector<std::uint32_t>& order, int threads) {
    const int strips = std::min(bandCount(int(sites.size()), threads), 255);
    const std::vector<std::uint8_t> strip = stripOf(mesh, sites, strips);
    std::vector<std::vector<std::uint32_t>> items(
        static_cast<std::size_t>(strips)); // positions in order
    for (std::uint32_t k = 0; k < order.size(); ++k) items[strip[sites[order[k]]]].push_back(k);
    std::vector<RegionInserter> inserters;
    for (int r = 0; r < strips; ++r) {
        const std::size_t count = 2 * items[std::size_t(r)].size();
        const std::uint32_t first = RegionInserter::reserveSlots(mesh, count);
        std::vector<std::uint32_t> slots(count);
        for (std::size_t i = 0; i < count; ++i) slots[i] = first + std::uint32_t(count - 1 - i);
        inserters.emplace_back(mesh, strip, std::uint8_t(r), std::move(slots));
    }
    std::vector<std::vector<std::uint32_t>> left(static_cast<std::size_t>(strips));
    const auto distance2 = [](dvec2 a, dvec2 b) {
        const dvec2 d = a - b;
        return d.x * d.x + d.y * d.y;
    };
    parallelRows(strips, threads, [&](int begin, int end, int) {
        for (int r = begin; r < end; ++r) {
            RegionInserter& inserter = inserters[std::size_t(r)];
            std::uint32_t previous = kNoHalfedge;
            std::size_t tried = 0, failed = 0;
            for (const std::uint32_t k : items[std::size_t(r)]) {
                // A strip where most sites need other strips' triangles (long triangles across
                // the borders, e.g. collinear input) gives up: every failed walk is wasted work.
                if (tried >= kStripTrial && 2 * failed > tried) {
                    left[std::size_t(r)].push_back(k);
                    continue;
                }
                ++tried;
                const std::uint32_t i = order[k], t = sites[i], s = near[i];
                const dvec2 q = mesh.points[t];
                // As insertSites: from the previous site or the keeper, whichever is nearer.
                std::uint32_t from = previous;
                if (s < mesh.points.size() && strip[s] == r && mesh.inMesh(s) &&
                    (from == kNoHalfedge ||
                     distance2(mesh.points[s], q) < distance2(mesh.points[from], q)))
                    from = s;
                if (inserter.tryInsert(t, from) ||
                    (from != previous && inserter.tryInsert(t, previous))) {
                    previous = t;
                } else {
                    left[std::size_t(r)].push_back(k);
                    ++failed;
                }
            }
        }
    });
    for (RegionInserter& inserter : inserters) inserter.finish();
    std::vector<std::uint32_t> rest;
    for (const auto& l : left)
        for (const std::uint32_t k : l) rest.push_back(order[k]);
    // Back into the BRIO order (positions k were kept per strip; the strips interleave).
    std::vector<std::uint32_t> position(sites.size());
    for (std::uint32_t k = 0; k < order.size(); ++k) position[order[k]] = k;
    std::sort(rest.begin(), rest.end(),
              [&](std::uint32_t a, std::uint32_t b) { return position[a] < position[b]; });
    return rest;
}

} // namespace fl::geom::detail
