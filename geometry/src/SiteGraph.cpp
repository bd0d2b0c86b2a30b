#include <geometry/SiteGraph.h>

#include <geometry/Triangulation.h>

#include <jfa/NearestSite.h>

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

// Interior sites start their walks at a boundary site of their row: the last one to their left,
// else the first one to their right, else vertex 0.
void tagInterior(jfa::Grid& seeds, const std::vector<int>& vertexAt) {
    const int w = seeds.width;
    for (int y = 0; y < seeds.height; ++y) {
        const int* row = &vertexAt[std::size_t(y) * std::size_t(w)];
        int first = -1;
        for (int x = 0; x < w && first < 0; ++x) first = row[x];
        int last = first < 0 ? 0 : first;
        for (int x = 0; x < w; ++x) {
            if (row[x] >= 0)
                last = row[x];
            else if (isSite(seeds, x, y))
                seeds.at(x, y).w = float(last);
        }
    }
}

} // namespace

jfa::SiteGraph buildSiteGraph(jfa::Grid& seeds) {
    jfa::SiteGraph graph;
    const int w = seeds.width, h = seeds.height;
    std::vector<int> vertexAt(std::size_t(w) * std::size_t(h), -1);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (!isSite(seeds, x, y)) continue;
            jfa::Cell& c = seeds.at(x, y);
            if (c.x != float(x) || c.y != float(y))
                throw std::invalid_argument(
                    "buildSiteGraph: pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                    ") holds site " + std::to_string(c.z) + " at (" + std::to_string(c.x) + ", " +
                    std::to_string(c.y) + "); the exact repair takes integer sites only");
            if (!onBoundary(seeds, x, y)) continue;
            vertexAt[std::size_t(y) * std::size_t(w) + std::size_t(x)] = int(graph.vertices.size());
            c.w = float(graph.vertices.size());
            graph.vertices.push_back(c);
        }
    tagInterior(seeds, vertexAt);
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
