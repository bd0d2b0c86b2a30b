#include <geometry/SiteGraph.h>

#include <geometry/Triangulation.h>

#include <jfa/NearestSite.h>
#include <jfa/Reference.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace fl::geom {

namespace {

using Edge = std::pair<std::uint32_t, std::uint32_t>;

bool isSite(const jfa::Grid& g, int x, int y) {
    return !jfa::NearestSite{}.empty(g.at(x, y));
}

// A site with a 4-neighbour inside the grid that is not a site (SiteGraph.h says why only these).
bool onBoundary(const jfa::Grid& g, int x, int y) {
    return (x > 0 && !isSite(g, x - 1, y)) || (x + 1 < g.width && !isSite(g, x + 1, y)) ||
           (y > 0 && !isSite(g, x, y - 1)) || (y + 1 < g.height && !isSite(g, x, y + 1));
}

bool collinear(const std::vector<jfa::Cell>& v) {
    if (v.size() < 3) return true;
    const std::int64_t ax = std::int64_t(v[0].x), ay = std::int64_t(v[0].y);
    const std::int64_t bx = std::int64_t(v[1].x) - ax, by = std::int64_t(v[1].y) - ay;
    return std::all_of(v.begin() + 2, v.end(), [&](const jfa::Cell& c) {
        return bx * (std::int64_t(c.y) - ay) - by * (std::int64_t(c.x) - ax) == 0;
    });
}

// Every undirected edge once per direction: the triangulation's, or the chain along the line.
std::vector<Edge> directedEdges(const std::vector<jfa::Cell>& v) {
    std::vector<Edge> edges;
    if (collinear(v)) {
        std::vector<std::uint32_t> order(v.size());
        for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
        // Lexicographic order is the order along any line.
        std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
            return v[a].x != v[b].x ? v[a].x < v[b].x : v[a].y < v[b].y;
        });
        for (std::size_t i = 1; i < order.size(); ++i) {
            edges.emplace_back(order[i - 1], order[i]);
            edges.emplace_back(order[i], order[i - 1]);
        }
        return edges;
    }
    std::vector<glm::dvec2> points(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) points[i] = {double(v[i].x), double(v[i].y)};
    const Triangulation t = delaunayReference(points);
    edges.reserve(t.triangles.size() + 64);
    for (std::uint32_t e = 0; e < t.triangles.size(); ++e) {
        const std::uint32_t a = t.triangles[e], b = t.triangles[nextHalfedge(e)];
        edges.emplace_back(a, b); // the twin halfedge adds (b, a) unless e is on the hull
        if (t.halfedges[e] == kNoHalfedge) edges.emplace_back(b, a);
    }
    return edges;
}

// The pixel of sites[k], which must be an integer position inside the grid whose cell holds it,
// after sites[k - 1] in row-major order.
std::pair<int, int> pixelOfSite(const jfa::Grid& seeds, const std::vector<jfa::Cell>& sites,
                                std::size_t k) {
    const jfa::Cell& c = sites[k];
    const int x = int(c.x), y = int(c.y);
    const bool own = c.x >= 0.0f && c.y >= 0.0f && c.x < float(seeds.width) &&
                     c.y < float(seeds.height) && c.x == float(x) && c.y == float(y) &&
                     isSite(seeds, x, y) && seeds.at(x, y).z == c.z;
    if (!own)
        throw std::invalid_argument("buildSiteGraph: site " + std::to_string(c.z) + " at (" +
                                    std::to_string(c.x) + ", " + std::to_string(c.y) +
                                    ") is not at its own pixel of the seeds; the exact repair "
                                    "takes integer sites only");
    if (k > 0 && (sites[k - 1].y > c.y || (sites[k - 1].y == c.y && sites[k - 1].x >= c.x)))
        throw std::invalid_argument("buildSiteGraph: the sites are not in row-major order");
    return {x, y};
}

} // namespace

jfa::SiteGraph buildSiteGraph(jfa::Grid& seeds) {
    return buildSiteGraph(seeds, jfa::siteCells(seeds));
}

jfa::SiteGraph buildSiteGraph(jfa::Grid& seeds, const std::vector<jfa::Cell>& sites) {
    jfa::SiteGraph graph;
    std::vector<std::uint8_t> boundary; // per site of the current row
    for (std::size_t row = 0; row < sites.size();) {
        std::size_t end = row;
        while (end < sites.size() && sites[end].y == sites[row].y) ++end;
        // Boundary sites become vertices (row-major order), tagged with their index.
        const std::uint32_t first = std::uint32_t(graph.vertices.size());
        boundary.assign(end - row, 0);
        for (std::size_t k = row; k < end; ++k) {
            const auto [x, y] = pixelOfSite(seeds, sites, k);
            if (!onBoundary(seeds, x, y)) continue;
            boundary[k - row] = 1;
            jfa::Cell& c = seeds.at(x, y);
            c.w = float(graph.vertices.size());
            graph.vertices.push_back(c);
        }
        // Interior sites start their walks at the row's last boundary site to their left, else
        // its first one, else vertex 0 (a walk from any vertex ends right; a near one is short).
        std::uint32_t last = first < graph.vertices.size() ? first : 0u;
        for (std::size_t k = row; k < end; ++k) {
            jfa::Cell& c = seeds.at(int(sites[k].x), int(sites[k].y));
            if (boundary[k - row])
                last = std::uint32_t(c.w);
            else
                c.w = float(last);
        }
        row = end;
    }
    std::vector<Edge> edges = directedEdges(graph.vertices);
    std::sort(edges.begin(), edges.end());
    graph.offsets.assign(graph.vertices.size() + 1, 0);
    for (const Edge& e : edges) ++graph.offsets[e.first + 1];
    for (std::size_t v = 0; v < graph.vertices.size(); ++v)
        graph.offsets[v + 1] += graph.offsets[v];
    graph.neighbours.reserve(edges.size());
    for (const Edge& e : edges) graph.neighbours.push_back(e.second);
    return graph;
}

} // namespace fl::geom
