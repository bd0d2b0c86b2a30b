// checkTriangulation: every invariant a triangulation of a point set must satisfy, decided with
// exact predicates so that a report of "ok" is a proof for these inputs, not an estimate.

#include <geometry/Predicates.h>
#include <geometry/Triangulation.h>

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <sstream>
#include <string>

namespace fl::geom {
namespace {

using glm::dvec2;

bool lexLess(dvec2 a, dvec2 b) {
    return a.x < b.x || (a.x == b.x && a.y < b.y);
}

std::string str(std::size_t v) {
    return std::to_string(v);
}

std::string coords(dvec2 p) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "(%.17g, %.17g)", p.x, p.y);
    return buf;
}

// Strictly between a and b on their common line (the caller knows the three are collinear):
// comparisons only, so exact.
bool strictlyBetween(dvec2 a, dvec2 v, dvec2 b) {
    const auto inside = [](double lo, double x, double hi) {
        return (lo < x && x < hi) || (hi < x && x < lo) || (lo == x && x == hi);
    };
    return v != a && v != b && inside(a.x, v.x, b.x) && inside(a.y, v.y, b.y);
}

// Point indices, ordered by coordinates then index, so equal points are adjacent.
std::vector<std::uint32_t> sortedByPosition(const std::vector<dvec2>& points) {
    std::vector<std::uint32_t> order(points.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](std::uint32_t i, std::uint32_t j) {
        if (lexLess(points[i], points[j])) return true;
        if (lexLess(points[j], points[i])) return false;
        return i < j;
    });
    return order;
}

// The strict convex hull (no collinear points), counter-clockwise from the lowest-leftmost
// point, as point indices (Andrew's monotone chain with exact orientation).
std::vector<std::uint32_t> strictHull(const std::vector<dvec2>& points,
                                      const std::vector<std::uint32_t>& sorted) {
    std::vector<std::uint32_t> unique;
    for (const std::uint32_t i : sorted)
        if (unique.empty() || points[unique.back()] != points[i]) unique.push_back(i);
    if (unique.size() < 3) return unique;
    std::vector<std::uint32_t> hull;
    const auto build = [&](auto begin, auto end) {
        const std::size_t base = hull.size();
        for (auto it = begin; it != end; ++it) {
            while (hull.size() >= base + 2 && orient2dSign(points[hull[hull.size() - 2]],
                                                           points[hull.back()], points[*it]) <= 0)
                hull.pop_back();
            hull.push_back(*it);
        }
        hull.pop_back(); // the last point starts the other chain
    };
    build(unique.begin(), unique.end());
    build(unique.rbegin(), unique.rend());
    return hull;
}

class Checker {
  public:
    Checker(const Triangulation& mesh, const TriangulationCheckOptions& options)
        : mesh_(mesh), options_(options) {}

    TriangulationReport run();

  private:
    void problem(std::size_t& counter, std::string message) {
        ++counter;
        ++report_.problemCount;
        if (report_.problems.size() < options_.maxMessages)
            report_.problems.push_back(std::move(message));
    }
    dvec2 at(std::uint32_t e) const { return mesh_.points[mesh_.triangles[e]]; }
    std::string triangleName(std::size_t t) const {
        const auto& tr = mesh_.triangles;
        return "triangle " + str(t) + " (" + str(tr[3 * t]) + ", " + str(tr[3 * t + 1]) + ", " +
               str(tr[3 * t + 2]) + ")";
    }

    void checkIndicesAndOrientation();
    void matchEdges();
    void checkHalfedges();
    void countEuler();
    void checkPointUse();
    void checkBoundary();
    void checkDelaunay();

    const Triangulation& mesh_;
    const TriangulationCheckOptions& options_;
    TriangulationReport report_;
    std::vector<bool> indicesOk_;     // per triangle
    std::vector<bool> orientationOk_; // per triangle
    std::vector<std::uint32_t> twin_; // per halfedge, from the triangles alone
    std::vector<std::uint32_t> sorted_;
    std::size_t otherProblems_ = 0;
};

TriangulationReport Checker::run() {
    const std::size_t indices = mesh_.triangles.size();
    if (indices % 3 != 0) {
        problem(report_.badIndices,
                "triangles holds " + str(indices) + " indices, not a multiple of 3");
        return report_;
    }
    report_.triangles = indices / 3;
    if (report_.triangles == 0) problem(otherProblems_, "no triangles");
    checkIndicesAndOrientation();
    matchEdges();
    checkHalfedges();
    countEuler();
    sorted_ = sortedByPosition(mesh_.points);
    checkPointUse();
    if (report_.badIndices == 0 && report_.nonManifoldEdges == 0 && report_.triangles > 0)
        checkBoundary();
    if (options_.requireDelaunay) checkDelaunay();
    return report_;
}

void Checker::checkIndicesAndOrientation() {
    const auto& tr = mesh_.triangles;
    indicesOk_.assign(report_.triangles, true);
    orientationOk_.assign(report_.triangles, false);
    for (std::size_t t = 0; t < report_.triangles; ++t) {
        const std::uint32_t i = tr[3 * t], j = tr[3 * t + 1], k = tr[3 * t + 2];
        if (std::max({i, j, k}) >= mesh_.points.size()) {
            problem(report_.badIndices, triangleName(t) + " uses a vertex index >= the " +
                                            str(mesh_.points.size()) + " points");
            indicesOk_[t] = false;
        } else if (i == j || j == k || k == i) {
            problem(report_.badIndices, triangleName(t) + " repeats a vertex");
            indicesOk_[t] = false;
        }
        if (!indicesOk_[t]) continue;
        const int s = orient2dSign(mesh_.points[i], mesh_.points[j], mesh_.points[k]);
        orientationOk_[t] = s > 0;
        if (s < 0) problem(report_.badOrientation, triangleName(t) + " is clockwise");
        if (s == 0)
            problem(report_.badOrientation,
                    triangleName(t) + " is degenerate (collinear vertices)");
    }
}

// Opposites found from the triangles alone, independent of mesh.halfedges.
void Checker::matchEdges() {
    const auto& tr = mesh_.triangles;
    twin_.assign(tr.size(), kNoHalfedge);
    std::vector<std::pair<std::uint64_t, std::uint32_t>> directed;
    for (std::uint32_t e = 0; e < tr.size(); ++e)
        if (indicesOk_[e / 3])
            directed.push_back({(std::uint64_t{tr[e]} << 32) | tr[nextHalfedge(e)], e});
    std::sort(directed.begin(), directed.end());
    for (std::size_t i = 1; i < directed.size(); ++i)
        if (directed[i].first == directed[i - 1].first) {
            const std::uint32_t e = directed[i].second;
            problem(report_.nonManifoldEdges,
                    "directed edge " + str(tr[e]) + " -> " + str(tr[nextHalfedge(e)]) +
                        " occurs in triangles " + str(directed[i - 1].second / 3) + " and " +
                        str(e / 3) + " (non-manifold or inconsistently oriented)");
        }
    for (const auto& [key, e] : directed) {
        const std::uint64_t reverse = (key << 32) | (key >> 32);
        const auto it = std::lower_bound(directed.begin(), directed.end(),
                                         std::pair<std::uint64_t, std::uint32_t>{reverse, 0});
        if (it != directed.end() && it->first == reverse) twin_[e] = it->second;
    }
}

void Checker::checkHalfedges() {
    const auto& half = mesh_.halfedges;
    if (half.size() != mesh_.triangles.size()) {
        problem(report_.badHalfedges, "halfedges holds " + str(half.size()) + " entries for " +
                                          str(mesh_.triangles.size()) + " triangle corners");
        return;
    }
    for (std::uint32_t e = 0; e < half.size(); ++e) {
        if (!indicesOk_[e / 3] || half[e] == twin_[e]) continue;
        const auto name = [](std::uint32_t h) {
            return h == kNoHalfedge ? std::string("none") : str(h);
        };
        problem(report_.badHalfedges, "halfedge " + str(e) + " (" + str(mesh_.triangles[e]) +
                                          " -> " + str(mesh_.triangles[nextHalfedge(e)]) +
                                          ") has opposite " + name(half[e]) +
                                          " but the triangles give " + name(twin_[e]));
    }
}

void Checker::countEuler() {
    std::vector<bool> used(mesh_.points.size(), false);
    std::size_t faces = 0;
    for (std::size_t t = 0; t < report_.triangles; ++t) {
        if (!indicesOk_[t]) continue;
        ++faces;
        for (int k = 0; k < 3; ++k) used[mesh_.triangles[3 * t + k]] = true;
    }
    report_.vertices = static_cast<std::size_t>(std::count(used.begin(), used.end(), true));
    for (std::uint32_t e = 0; e < twin_.size(); ++e) {
        if (!indicesOk_[e / 3]) continue;
        if (twin_[e] == kNoHalfedge) {
            ++report_.boundaryEdges;
            ++report_.edges;
        } else if (e < twin_[e]) {
            ++report_.edges;
        }
    }
    const auto euler = static_cast<long long>(report_.vertices) -
                       static_cast<long long>(report_.edges) + static_cast<long long>(faces);
    if (faces > 0 && euler != 1) {
        report_.eulerMismatch = true;
        problem(otherProblems_, "V - E + F = " + std::to_string(euler) + " (V " +
                                    str(report_.vertices) + ", E " + str(report_.edges) + ", F " +
                                    str(faces) + "), not 1: holes, handles or separate pieces");
    }
}

void Checker::checkPointUse() {
    const auto& pts = mesh_.points;
    std::vector<bool> used(pts.size(), false);
    for (std::size_t t = 0; t < report_.triangles; ++t)
        if (indicesOk_[t])
            for (int k = 0; k < 3; ++k) used[mesh_.triangles[3 * t + k]] = true;
    // Walk groups of equal points: unused members of a group with a used member are duplicates;
    // two used members make two vertices at one position, which no valid mesh has.
    for (std::size_t begin = 0; begin < sorted_.size();) {
        std::size_t end = begin + 1;
        while (end < sorted_.size() && pts[sorted_[end]] == pts[sorted_[begin]]) ++end;
        std::uint32_t firstUsed = kNoHalfedge;
        for (std::size_t i = begin; i < end; ++i) {
            const std::uint32_t p = sorted_[i];
            if (!used[p]) continue;
            if (firstUsed == kNoHalfedge) {
                firstUsed = p;
            } else {
                problem(otherProblems_, "points " + str(firstUsed) + " and " + str(p) +
                                            " coincide at " + coords(pts[p]) +
                                            " and both are used");
            }
        }
        for (std::size_t i = begin; i < end; ++i) {
            const std::uint32_t p = sorted_[i];
            if (used[p]) continue;
            if (firstUsed != kNoHalfedge) {
                report_.duplicatePoints.push_back(p);
                if (!options_.allowDuplicatePoints)
                    problem(otherProblems_,
                            "point " + str(p) + " duplicates point " + str(firstUsed));
            } else {
                report_.unusedPoints.push_back(p);
                problem(otherProblems_,
                        "point " + str(p) + " " + coords(pts[p]) + " is in no triangle");
            }
        }
        begin = end;
    }
    std::sort(report_.unusedPoints.begin(), report_.unusedPoints.end());
    std::sort(report_.duplicatePoints.begin(), report_.duplicatePoints.end());
}

// The boundary must be one closed cycle that turns only left (or runs straight on), whose
// corners are exactly the convex hull's vertices in the same order: then it is the hull.
void Checker::checkBoundary() {
    const auto& tr = mesh_.triangles;
    const auto& pts = mesh_.points;
    std::vector<std::uint32_t> outgoing(pts.size(), kNoHalfedge);
    std::size_t boundaryCount = 0;
    std::uint32_t start = kNoHalfedge;
    for (std::uint32_t e = 0; e < tr.size(); ++e) {
        if (twin_[e] != kNoHalfedge) continue;
        ++boundaryCount;
        if (start == kNoHalfedge) start = e;
        if (outgoing[tr[e]] != kNoHalfedge) {
            problem(report_.hullProblems,
                    "vertex " + str(tr[e]) + " has two boundary edges leaving it (pinched mesh)");
            return;
        }
        outgoing[tr[e]] = e;
    }
    if (start == kNoHalfedge) {
        problem(report_.hullProblems, "the mesh has no boundary (closed surface)");
        return;
    }
    std::vector<std::uint32_t> cycle; // vertices in boundary order
    std::uint32_t e = start;
    do {
        cycle.push_back(tr[e]);
        e = outgoing[tr[nextHalfedge(e)]];
        if (e == kNoHalfedge) {
            problem(report_.hullProblems,
                    "the boundary is not closed at vertex " + str(cycle.back()));
            return;
        }
    } while (e != start && cycle.size() <= boundaryCount);
    if (cycle.size() != boundaryCount) {
        problem(report_.hullProblems, "the boundary consists of several cycles (" +
                                          str(boundaryCount) + " boundary edges, first cycle " +
                                          str(cycle.size()) + "): holes or separate pieces");
        return;
    }

    std::vector<std::uint32_t> corners;
    const std::size_t n = cycle.size();
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint32_t u = cycle[(i + n - 1) % n], v = cycle[i], w = cycle[(i + 1) % n];
        const int s = orient2dSign(pts[u], pts[v], pts[w]);
        if (s < 0)
            problem(report_.hullProblems, "the boundary turns clockwise at vertex " + str(v) +
                                              ": not convex, so not the convex hull");
        else if (s == 0 && !strictlyBetween(pts[u], pts[v], pts[w]))
            problem(report_.hullProblems, "the boundary doubles back at vertex " + str(v));
        else if (s > 0)
            corners.push_back(v);
    }
    if (report_.hullProblems > 0) return;

    const std::vector<std::uint32_t> hull = strictHull(pts, sorted_);
    const auto rotation = std::find_if(corners.begin(), corners.end(), [&](std::uint32_t c) {
        return pts[c] == pts[hull.front()];
    });
    bool same = corners.size() == hull.size() && rotation != corners.end();
    if (same) {
        std::rotate(corners.begin(), rotation, corners.end());
        for (std::size_t i = 0; i < hull.size() && same; ++i)
            same = pts[corners[i]] == pts[hull[i]];
    }
    if (!same) {
        std::string message = "the boundary is not the convex hull: it has " + str(corners.size()) +
                              " corners, the hull " + str(hull.size());
        for (const std::uint32_t h : hull)
            if (std::none_of(corners.begin(), corners.end(),
                             [&](std::uint32_t c) { return pts[c] == pts[h]; })) {
                message += "; hull vertex " + str(h) + " " + coords(pts[h]) + " is not a corner";
                break;
            }
        problem(report_.hullProblems, message);
    }
}

void Checker::checkDelaunay() {
    const auto& tr = mesh_.triangles;
    for (std::uint32_t e = 0; e < tr.size(); ++e) {
        const std::uint32_t o = twin_[e];
        if (o == kNoHalfedge || o < e) continue;
        if (!orientationOk_[e / 3] || !orientationOk_[o / 3]) continue; // already reported
        if (incircleSign(at(e), at(nextHalfedge(e)), at(prevHalfedge(e)), at(prevHalfedge(o))) > 0)
            problem(report_.nonDelaunayEdges,
                    "edge " + str(tr[e]) + " - " + str(tr[nextHalfedge(e)]) +
                        " is not locally Delaunay: point " + str(tr[prevHalfedge(o)]) +
                        " lies inside the circumcircle of " + triangleName(e / 3));
    }
}

} // namespace

std::string TriangulationReport::summary() const {
    std::ostringstream out;
    out << triangles << " triangles, " << vertices << " vertices, " << edges << " edges ("
        << boundaryEdges << " on the boundary); " << problemCount << " problem(s)";
    if (!duplicatePoints.empty()) out << "; " << duplicatePoints.size() << " duplicate point(s)";
    for (const std::string& p : problems) out << "\n  - " << p;
    if (problems.size() < problemCount)
        out << "\n  - ... and " << problemCount - problems.size() << " more";
    return out.str();
}

TriangulationReport checkTriangulation(const Triangulation& mesh,
                                       const TriangulationCheckOptions& options) {
    return Checker(mesh, options).run();
}

} // namespace fl::geom
