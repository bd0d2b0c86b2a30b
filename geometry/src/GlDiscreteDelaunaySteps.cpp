// Steps G1-G6 of the thesis (§6.3.2) as GL compute dispatches (shaders/delaunay_*.glsl); the
// CPU twins are in DiscreteVoronoi*.cpp and DiscreteTriangles*.cpp.
#include "GlDiscreteDelaunayDetail.h"

#include <jfa/CpuKernel.h>
#include <jfa/NearestSite.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace fl::geom {

namespace {

constexpr GLuint kNoSiteValue = kNoSite;
constexpr int kItemGroup = 64; // local size of the 1D kernels (sites, rows)
constexpr int kTileSide = 8;   // local size of the 2D kernels (8 x 8 texels)

// Every later reader of a step's output: samplers, images, atomic counters, SSBOs and the
// host's glGet*/readbacks. One generous barrier per dispatch costs little next to the dispatch
// and leaves no reader to forget.
constexpr GLbitfield kAfterWrites = GL_TEXTURE_FETCH_BARRIER_BIT |
                                    GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                                    GL_TEXTURE_UPDATE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT |
                                    GL_ATOMIC_COUNTER_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT;

gl::Program buildStep(const gl::ShaderLibrary& shaders, const char* file) {
    return gl::Program::build(shaders, {{GL_COMPUTE_SHADER, file}});
}

// A buffer of at least `bytes` (never empty: zero-sized storage is a GL error, and the kernels
// declare every buffer whether or not a run uses it); keeps the contents only when it fits.
void ensureBuffer(gl::Buffer& buffer, std::size_t bytes) {
    const auto need = static_cast<GLsizeiptr>(std::max<std::size_t>(bytes, 16));
    if (buffer && buffer.size() >= need) return;
    // Growing by half again keeps repeated runs with slowly rising counts from reallocating.
    const GLsizeiptr size = std::max(need, buffer.size() + buffer.size() / 2);
    buffer = gl::Buffer(size, nullptr, GL_DYNAMIC_STORAGE_BIT);
}

void zeroBuffer(const gl::Buffer& buffer) {
    const GLuint zero = 0;
    glClearNamedBufferData(buffer.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
}

template <typename T>
std::vector<T> readBuffer(const gl::Buffer& buffer, std::size_t count) {
    std::vector<T> out(count);
    if (count > 0)
        glGetNamedBufferSubData(buffer.id(), 0, static_cast<GLsizeiptr>(count * sizeof(T)),
                                out.data());
    return out;
}

// One invocation per item; more than 65535 groups (2^24 sites) spill into y (dispatchIndex()).
void dispatchItems(std::size_t count) {
    if (count == 0) return;
    const std::size_t groups = (count + kItemGroup - 1) / kItemGroup;
    const std::size_t x = std::min<std::size_t>(groups, 65535);
    glDispatchCompute(static_cast<GLuint>(x), static_cast<GLuint>((groups + x - 1) / x), 1);
    glMemoryBarrier(kAfterWrites);
}

// One invocation per texel of a W x H texture.
void dispatchTexels(int w, int h) {
    glDispatchCompute(static_cast<GLuint>((w + kTileSide - 1) / kTileSide),
                      static_cast<GLuint>((h + kTileSide - 1) / kTileSide), 1);
    glMemoryBarrier(kAfterWrites);
}

// Leaves no program, texture, image or buffer binding behind a step (DESIGN: no global GL state
// outside a pass).
void unbindAll() {
    glUseProgram(0);
    for (GLuint unit = 0; unit < 3; ++unit) glBindTextureUnit(unit, 0);
    for (GLuint unit = 0; unit < 2; ++unit)
        glBindImageTexture(unit, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
    for (GLuint index = 0; index < 5; ++index) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, index, 0);
    glBindBufferBase(GL_ATOMIC_COUNTER_BUFFER, 0, 0);
}

void bindImage(GLuint unit, const gl::Texture& texture, GLenum access) {
    glBindImageTexture(unit, texture.id(), 0, GL_FALSE, 0, access, texture.format());
}

} // namespace

GlDiscreteDelaunay::Impl::Impl(const gl::ShaderLibrary& shaders, jfa::GlKernelKind flood)
    : sitesProgram(buildStep(shaders, "delaunay_sites.comp.glsl")),
      idsProgram(buildStep(shaders, "delaunay_ids.comp.glsl")),
      islandsProgram(buildStep(shaders, "delaunay_islands.comp.glsl")),
      cornersProgram(buildStep(shaders, "delaunay_corners.comp.glsl")),
      chainProgram(buildStep(shaders, "delaunay_chain.comp.glsl")),
      trianglesProgram(buildStep(shaders, "delaunay_triangles.comp.glsl")),
      floodKernel(shaders, flood), changed(sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT),
      cornerCounts(GLsizeiptr(kCornerCaseCount * sizeof(GLuint)), nullptr, GL_DYNAMIC_STORAGE_BIT),
      meshCounters(6 * sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT) {
    gl::throwIfErrors("GL discrete Delaunay setup");
}

void GlDiscreteDelaunay::Impl::resize(int w, int h) {
    if (w == width && h == height) return;
    owner = gl::Texture(GL_R32UI, w, h);
    seeds = gl::Texture(GL_RGBA32F, w, h);
    voronoi = gl::Texture(GL_R32UI, w, h);
    for (gl::Texture& t : islands) t = gl::Texture(GL_R32UI, w, h);
    corners = gl::Texture(GL_R8UI, w, h);
    for (gl::Texture& t : chain) t = gl::Texture(GL_R32I, w, h);
    width = w;
    height = h;
}

void GlDiscreteDelaunay::Impl::uploadPixels(const std::vector<glm::ivec2>& sitePixels) {
    static_assert(sizeof(glm::ivec2) == 2 * sizeof(GLint), "std430 ivec2 layout");
    ensureBuffer(pixels, sitePixels.size() * sizeof(glm::ivec2));
    if (!sitePixels.empty())
        glNamedBufferSubData(pixels.id(), 0,
                             static_cast<GLsizeiptr>(sitePixels.size() * sizeof(glm::ivec2)),
                             sitePixels.data());
}

std::vector<std::uint32_t> GlDiscreteDelaunay::Impl::claimPixels(std::size_t count) {
    glClearTexImage(owner.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &kNoSiteValue);
    const jfa::Cell empty = jfa::kEmptyCell;
    glClearTexImage(seeds.id(), 0, GL_RGBA, GL_FLOAT, &empty);
    if (count == 0) return {};
    ensureBuffer(keepers, count * sizeof(GLuint));
    glUseProgram(sitesProgram.id());
    bindImage(0, owner, GL_READ_WRITE);
    bindImage(1, seeds, GL_WRITE_ONLY);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, pixels.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, keepers.id());
    sitesProgram.set("uCount", static_cast<int>(count));
    // Two dispatches: every claim must land before any site reads its pixel's owner.
    for (int mode : {0, 1}) {
        sitesProgram.set("uMode", mode);
        dispatchItems(count);
    }
    unbindAll();
    return readBuffer<std::uint32_t>(keepers, count);
}

void GlDiscreteDelaunay::Impl::flood(const jfa::Plan& plan) {
    // The CPU's criterion exactly (integer sites), so the GL kernel's cells equal the CPU
    // kernel's texel for texel.
    const gl::Texture& cells = floodKernel.run(plan, seeds, jfa::NearestSite{true});
    glUseProgram(idsProgram.id());
    glBindTextureUnit(0, cells.id());
    bindImage(0, voronoi, GL_WRITE_ONLY);
    idsProgram.set("uSize", glm::ivec2(width, height));
    dispatchTexels(width, height);
    unbindAll();
}

const gl::Texture& GlDiscreteDelaunay::Impl::removeIslands(const gl::Texture& in,
                                                           IslandStats& stats) {
    stats = {};
    // The CPU's cap (removeIslands): 2 N passes end it should recolouring ever cycle.
    const int cap = 2 * std::max(width, height);
    const gl::Texture* src = &in;
    int next = 0;
    glUseProgram(islandsProgram.id());
    islandsProgram.set("uSize", glm::ivec2(width, height));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, pixels.id());
    glBindBufferBase(GL_ATOMIC_COUNTER_BUFFER, 0, changed.id());
    while (true) {
        // Ping-pong: a pass reads only the previous pass' texture, as on the CPU.
        const gl::Texture& dst = islands[next];
        zeroBuffer(changed);
        glBindTextureUnit(0, src->id());
        bindImage(0, dst, GL_WRITE_ONLY);
        dispatchTexels(width, height);
        ++stats.passes;
        // Reading the counter waits for the pass: the thesis' occlusion-query loop.
        const GLuint count = readBuffer<GLuint>(changed, 1)[0];
        if (count == 0) break;
        stats.reassigned += count;
        src = &dst;
        next ^= 1;
        if (stats.passes >= cap) {
            stats.converged = false;
            break;
        }
    }
    unbindAll();
    return *src;
}

CornerCounts GlDiscreteDelaunay::Impl::classifyCorners(const gl::Texture& ids) {
    zeroBuffer(cornerCounts);
    glUseProgram(cornersProgram.id());
    glBindTextureUnit(0, ids.id());
    bindImage(0, corners, GL_WRITE_ONLY);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, cornerCounts.id());
    cornersProgram.set("uSize", glm::ivec2(width, height));
    dispatchTexels(width, height);
    unbindAll();
    const std::vector<GLuint> raw = readBuffer<GLuint>(cornerCounts, kCornerCaseCount);
    CornerCounts counts{};
    std::int64_t vertexLike = 0;
    for (std::size_t k = 1; k < kCornerCaseCount; ++k) {
        counts[k] = raw[k];
        vertexLike += raw[k];
    }
    // The kernel counts only the rare cases; case 1 is every other corner, border ones included.
    counts[0] = std::int64_t(width) * height - vertexLike;
    return counts;
}

const gl::Texture& GlDiscreteDelaunay::Impl::chainRows() {
    // jfaSteps(width), as chainRowsJfa runs them. (Fusing the short steps into one
    // shared-memory dispatch gave the same chains but no speed-up on llvmpipe, where a group
    // barrier costs about what a pass does.)
    std::vector<int> steps = jfa::jfaSteps(width);
    // A one-texel-wide texture has no steps; one pass that reads nothing to its right still
    // seeds the chain.
    if (steps.empty()) steps.push_back(width);
    glUseProgram(chainProgram.id());
    chainProgram.set("uSize", glm::ivec2(width, height));
    glBindTextureUnit(1, corners.id());
    int current = 1; // the first pass reads the corners; chain[1] is only bound, never read
    bool first = true;
    for (int step : steps) {
        const int dst = current ^ 1;
        chainProgram.set("uStep", step);
        chainProgram.set("uFromCorners", first ? 1 : 0);
        glBindTextureUnit(0, chain[current].id());
        bindImage(0, chain[dst], GL_WRITE_ONLY);
        dispatchTexels(width, height);
        current = dst;
        first = false;
    }
    unbindAll();
    return chain[current];
}

DiscreteTriangles GlDiscreteDelaunay::Impl::buildTriangles(const gl::Texture& ids,
                                                           const gl::Texture& chainTexture,
                                                           const CornerCounts& counts) {
    DiscreteTriangles out;
    const int rowCount = height - 1; // corner rows; the top row's corners lie on the border
    if (rowCount <= 0 || width < 2) return out;
    std::int64_t vertexTotal = 0, triangleTotal = 0;
    for (CornerCase c : {CornerCase::ThreeA, CornerCase::ThreeB, CornerCase::ThreeC,
                         CornerCase::ThreeD, CornerCase::Four}) {
        vertexTotal += counts[std::size_t(c)];
        triangleTotal += std::int64_t(trianglesOf(c)) * counts[std::size_t(c)];
    }
    // G4's counts size the buffers exactly (the thesis pre-allocates from counts, too).
    ensureBuffer(rows, std::size_t(rowCount) * 4 * sizeof(GLuint));
    ensureBuffer(vertices, std::size_t(vertexTotal) * 6 * sizeof(GLuint));
    ensureBuffer(triangles, std::size_t(triangleTotal) * 4 * sizeof(GLuint));
    zeroBuffer(meshCounters);
    glUseProgram(trianglesProgram.id());
    glBindTextureUnit(0, ids.id());
    glBindTextureUnit(1, corners.id());
    glBindTextureUnit(2, chainTexture.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, pixels.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, meshCounters.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, rows.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, vertices.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 4, triangles.id());
    trianglesProgram.set("uSize", glm::ivec2(width, height));
    trianglesProgram.set("uVertexCapacity", static_cast<int>(vertexTotal));
    trianglesProgram.set("uTriangleCapacity", static_cast<int>(triangleTotal));
    dispatchItems(std::size_t(rowCount));
    unbindAll();

    const std::vector<GLuint> counters = readBuffer<GLuint>(meshCounters, 6);
    if (counters[0] != vertexTotal || counters[1] != triangleTotal)
        throw std::logic_error("GL buildTriangles: the chains name " + std::to_string(counters[0]) +
                               " vertices and " + std::to_string(counters[1]) +
                               " triangles, G4 counted " + std::to_string(vertexTotal) + " and " +
                               std::to_string(triangleTotal));
    const auto rowData = readBuffer<glm::uvec4>(rows, std::size_t(rowCount));
    const auto vertexData = readBuffer<GLuint>(vertices, std::size_t(vertexTotal) * 6);
    const auto triangleData = readBuffer<glm::uvec4>(triangles, std::size_t(triangleTotal));

    // Rows reserved their blocks in whatever order they ran; copying the blocks row by row
    // gives the CPU's order (rows bottom to top, chain order within a row).
    out.vertices.reserve(std::size_t(vertexTotal));
    out.triangles.reserve(std::size_t(triangleTotal) * 3);
    out.triangleVertex.reserve(std::size_t(triangleTotal));
    for (int y = 0; y < rowCount; ++y) {
        const glm::uvec4 r = rowData[std::size_t(y)];
        if (std::int64_t(r.x) + r.y > vertexTotal || std::int64_t(r.z) + r.w > triangleTotal)
            throw std::logic_error("GL buildTriangles: row " + std::to_string(y) +
                                   " overruns the buffers");
        const auto base = static_cast<std::uint32_t>(out.vertices.size());
        for (GLuint k = 0; k < r.y; ++k) {
            const GLuint* v = &vertexData[std::size_t(r.x + k) * 6];
            out.vertices.push_back(VoronoiVertex{
                {int(v[0]), y}, static_cast<CornerCase>(v[1]), {v[2], v[3], v[4], v[5]}});
        }
        for (GLuint k = 0; k < r.w; ++k) {
            const glm::uvec4 t = triangleData[std::size_t(r.z + k)];
            out.triangles.insert(out.triangles.end(), {t.x, t.y, t.z});
            out.triangleVertex.push_back(base + t.w);
        }
    }
    out.stats.threeColour = counters[2];
    out.stats.fourColour = counters[3];
    out.stats.degenerate = counters[4];
    out.stats.clockwise = counters[5];
    return out;
}

} // namespace fl::geom
