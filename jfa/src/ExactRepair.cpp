#include <jfa/ExactRepair.h>

#include <jfa/CpuKernel.h>
#include <jfa/GlKernel.h>

#include <gpu/BindScope.h>

#include <base/Parallel.h>

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace fl::jfa {

namespace {

// The vertex a walk from non-empty `cell` starts at: the one its w names.
std::uint32_t startVertex(const SiteGraph& graph, const Cell& cell) {
    const float w = cell.w;
    if (!(w >= 0.0f && w < float(graph.vertices.size())) || w != float(std::uint32_t(w)))
        throw std::invalid_argument("repairNearest: cell of site " + std::to_string(cell.z) +
                                    " names vertex " + std::to_string(w) + " of a graph of " +
                                    std::to_string(graph.vertices.size()));
    return std::uint32_t(w);
}

} // namespace

Cell walkToNearest(const SiteGraph& graph, int px, int py, const Cell& start) {
    const NearestSite criterion{true};
    const bool empty = criterion.empty(start);
    if (!empty && NearestSite::squaredInt(px, py, start) == 0) return start; // a site's pixel
    if (graph.vertices.empty()) return start;
    std::uint32_t at = empty ? 0u : startVertex(graph, start);
    Cell best = graph.vertices[at];
    std::int64_t bestDistance = NearestSite::squaredInt(px, py, best);
    // Each move is strictly better under a strict total order: at most V - 1 of them.
    for (std::size_t moves = 0; moves < graph.vertices.size(); ++moves) {
        std::uint32_t next = at;
        for (std::uint32_t k = graph.offsets[at]; k < graph.offsets[at + 1]; ++k) {
            const std::uint32_t n = graph.neighbours[k];
            const Cell& c = graph.vertices[n];
            // criterion.better, with the distance computed once per candidate.
            const std::int64_t d = NearestSite::squaredInt(px, py, c);
            if (d < bestDistance || (d == bestDistance && criterion.better(px, py, c, best))) {
                best = c;
                bestDistance = d;
                next = n;
            }
        }
        if (next == at) break;
        at = next;
    }
    return best;
}

namespace {

// floor(a / b) for b > 0.
std::int64_t floorDiv(std::int64_t a, std::int64_t b) {
    return a >= 0 ? a / b : -((-a + b - 1) / b);
}

// The texels x of row y where vertex v's site is strictly nearer than each of its neighbours
// (its open Voronoi cell in the graph, cut by the row): [lo, hi], empty when lo > hi. There no
// neighbour is better, so the walk stops at once and the texel becomes vertices[v].
// |p - s|^2 < |p - n|^2  <=>  2x(n.x - s.x) < |n|^2 - |s|^2 - 2y(n.y - s.y), exact in int64.
struct RowInterval {
    std::int64_t lo = 1, hi = 0;
};

RowInterval rowInterval(const SiteGraph& graph, std::uint32_t v, int y) {
    const Cell& s = graph.vertices[v];
    const std::int64_t sx = std::int64_t(s.x), sy = std::int64_t(s.y);
    RowInterval r{std::numeric_limits<std::int64_t>::min(),
                  std::numeric_limits<std::int64_t>::max()};
    for (std::uint32_t k = graph.offsets[v]; k < graph.offsets[v + 1]; ++k) {
        const Cell& n = graph.vertices[graph.neighbours[k]];
        const std::int64_t nx = std::int64_t(n.x), ny = std::int64_t(n.y);
        const std::int64_t a = 2 * (nx - sx);
        const std::int64_t b = nx * nx + ny * ny - sx * sx - sy * sy - 2 * y * (ny - sy);
        if (a > 0)
            r.hi = std::min(r.hi, floorDiv(b - 1, a)); // a x < b  <=>  x <= floor((b - 1) / a)
        else if (a < 0)
            r.lo = std::max(r.lo, floorDiv(-b, -a) + 1); // (-a) x > -b
        else if (b <= 0)
            return {}; // the whole row is at least as near to n
    }
    return r;
}

} // namespace

void repairNearest(Grid& flooded, const SiteGraph& graph, int threads, RepairMethod method) {
    if (graph.offsets.size() != graph.vertices.size() + 1)
        throw std::invalid_argument("repairNearest: the graph's offsets do not match its " +
                                    std::to_string(graph.vertices.size()) + " vertices");
    const int w = flooded.width;
    const bool intervals = method == RepairMethod::RowIntervals;
    parallelRows(flooded.height, threads, [&](int rowBegin, int rowEnd, int) {
        for (int y = rowBegin; y < rowEnd; ++y) {
            // A row crosses few cells: consecutive texels mostly start from the same vertex.
            std::int64_t cached = -1;
            RowInterval in;
            for (int x = 0; x < w; ++x) {
                Cell& c = flooded.at(x, y);
                if (intervals && !graph.vertices.empty() && c.z >= 0.0f &&
                    NearestSite::squaredInt(x, y, c) != 0) {
                    const std::uint32_t v = startVertex(graph, c);
                    if (v != cached) {
                        cached = v;
                        in = rowInterval(graph, v, y);
                    }
                    if (x >= in.lo && x <= in.hi) {
                        // Mostly the cell already is the vertex: no store, no dirty line.
                        if (!(c == graph.vertices[v])) c = graph.vertices[v];
                        continue;
                    }
                }
                c = walkToNearest(graph, x, y, c);
            }
        }
    });
}

// ---- GL twin ------------------------------------------------------------------------------------

namespace {

// A storage buffer holding `values` (at least one element's bytes: GL rejects empty storage).
template <class T>
gl::Buffer storageOf(const std::vector<T>& values) {
    const std::vector<T> one(1);
    const std::vector<T>& data = values.empty() ? one : values;
    return gl::Buffer(GLsizeiptr(data.size() * sizeof(T)), data.data(), 0);
}

} // namespace

GlExactRepair::GlExactRepair(const gl::ShaderLibrary& shaders)
    : program_(gl::Program::build(shaders, {{GL_COMPUTE_SHADER, "jfa_exact_repair.comp.glsl"},
                                            {GL_COMPUTE_SHADER, NearestSite::glslFile}})) {}

void GlExactRepair::setGraph(const SiteGraph& graph) {
    if (graph.offsets.size() != graph.vertices.size() + 1)
        throw std::invalid_argument("GlExactRepair: the graph's offsets do not match its " +
                                    std::to_string(graph.vertices.size()) + " vertices");
    vertices_ = storageOf(graph.vertices);
    offsets_ = storageOf(graph.offsets);
    neighbours_ = storageOf(graph.neighbours);
    vertexCount_ = std::uint32_t(graph.vertices.size());
}

const gl::Texture& GlExactRepair::run(const gl::Texture& flooded) {
    if (!offsets_.id()) throw std::logic_error("GlExactRepair::run before setGraph");
    if (out_.width() != flooded.width() || out_.height() != flooded.height())
        out_ = gl::Texture(GL_RGBA32F, flooded.width(), flooded.height());
    glUseProgram(program_.id());
    gl::BindScope scope;
    setCriterionUniforms(scope, program_, NearestSite{true});
    program_.set("uSize", glm::ivec2(flooded.width(), flooded.height()));
    program_.set("uVertexCount", int(vertexCount_));
    scope.texture(gl::bind::Flooded, flooded.id())
        .image(gl::bind::RepairOut, out_.id(), GL_WRITE_ONLY, GL_RGBA32F)
        .storage(gl::bind::RepairVertices, vertices_.id())
        .storage(gl::bind::RepairOffsets, offsets_.id())
        .storage(gl::bind::RepairNeighbours, neighbours_.id());
    glDispatchCompute(GLuint((flooded.width() + 7) / 8), GLuint((flooded.height() + 7) / 8), 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                    GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    scope.release(); // before the error check, so that it covers the unbinding too
    glUseProgram(0);
    gl::throwIfErrors("jfa exact repair");
    return out_;
}

} // namespace fl::jfa
