// The GL backend's transfers back to the host: the one mapped read-back of the result buffer
// that run() needs, and the texture read-backs of the intermediate stages, made only when a
// caller asks for them (GlDiscreteDelaunay::setReadStages, countIslands, the G3 / G4-G6 twins).
#include "GlDiscreteDelaunayDetail.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>

namespace fl::geom {

namespace {

// glGetTextureImage into a vector of the texture's texel type, rows packed tight.
template <typename T>
void readTexels(const gl::Texture& texture, GLenum format, GLenum type, std::vector<T>& out) {
    out.resize(std::size_t(texture.width()) * std::size_t(texture.height()));
    GLint alignment = 4;
    glGetIntegerv(GL_PACK_ALIGNMENT, &alignment);
    // One-byte texels (the corner cases) would otherwise pad rows to 4 bytes.
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(texture.id(), 0, format, type, static_cast<GLsizei>(out.size() * sizeof(T)),
                      out.data());
    glPixelStorei(GL_PACK_ALIGNMENT, alignment);
}

// A one-channel integer texture read back into a grid struct (width, height, texels).
template <class GridT, typename T>
GridT readGrid(const gl::Texture& texture, GLenum type, std::vector<T> GridT::*texels) {
    GridT grid;
    grid.width = texture.width();
    grid.height = texture.height();
    readTexels(texture, GL_RED_INTEGER, type, grid.*texels);
    return grid;
}

// G6's records (delaunay_triangles.comp.glsl), already in the CPU's order, as DiscreteTriangles.
DiscreteTriangles parseMesh(const std::uint32_t* words, const ResultLayout& layout,
                            const gl_stages::ResultData& data) {
    using namespace gl_stages;
    DiscreteTriangles mesh;
    const std::size_t vertexCount = data.header[kHeadVertices];
    const std::size_t triangleCount = data.header[kHeadTriangles];
    const std::uint32_t* v = words + layout.vertices / sizeof(std::uint32_t);
    mesh.vertices.reserve(vertexCount); // not resize: each vertex is written once
    for (std::size_t k = 0; k < vertexCount; ++k, v += 6)
        mesh.vertices.push_back(VoronoiVertex{{int(v[0] & 0xffffu), int(v[0] >> 16)},
                                              static_cast<CornerCase>(v[1]),
                                              {v[2], v[3], v[4], v[5]}});
    const std::uint32_t* t = words + layout.triangles / sizeof(std::uint32_t);
    mesh.triangles.assign(t, t + 3 * triangleCount);
    const std::uint32_t* tv = words + layout.triangleVertex / sizeof(std::uint32_t);
    mesh.triangleVertex.assign(tv, tv + triangleCount);
    mesh.stats.threeColour = data.header[kHeadStats];
    mesh.stats.fourColour = data.header[kHeadStats + 1];
    mesh.stats.degenerate = data.header[kHeadStats + 2];
    mesh.stats.clockwise = data.header[kHeadStats + 3];
    return mesh;
}

} // namespace

namespace gl_stages {

void uploadIds(const gl::Texture& texture, const IdTexture& ids) {
    glTextureSubImage2D(texture.id(), 0, 0, 0, ids.width, ids.height, GL_RED_INTEGER,
                        GL_UNSIGNED_INT, ids.ids.data());
}

IdTexture readIds(const gl::Texture& texture) {
    return readGrid<IdTexture>(texture, GL_UNSIGNED_INT, &IdTexture::ids);
}

CornerTexture readCorners(const gl::Texture& texture, const CornerCounts& counts) {
    static_assert(sizeof(CornerCase) == 1, "CornerCase is read back as r8ui bytes");
    CornerTexture corners =
        readGrid<CornerTexture>(texture, GL_UNSIGNED_BYTE, &CornerTexture::cases);
    corners.counts = counts;
    return corners;
}

VertexChain readChain(const gl::Texture& texture) {
    return readGrid<VertexChain>(texture, GL_INT, &VertexChain::next);
}

CornerCounts ResultData::cornerCounts(int width, int height) const {
    CornerCounts counts{};
    std::int64_t counted = 0;
    for (std::size_t k = 1; k < kCornerCaseCount; ++k) {
        counts[k] = header[kHeadCorners + k];
        counted += counts[k];
    }
    // The kernel counts only the rare cases; case 1 is every other corner, border ones included.
    counts[0] = std::int64_t(width) * height - counted;
    return counts;
}

IslandStats ResultData::islandStats() const {
    IslandStats stats;
    stats.passes = static_cast<int>(header[kHeadPasses]);
    stats.reassigned =
        std::int64_t(header[kHeadReassignedLo]) | std::int64_t(header[kHeadReassignedHi]) << 32;
    stats.converged = header[kHeadConverged] != 0;
    return stats;
}

void ResultData::checkMeshCounts() const {
    std::int64_t vertices = 0, triangles = 0;
    for (CornerCase c : {CornerCase::ThreeA, CornerCase::ThreeB, CornerCase::ThreeC,
                         CornerCase::ThreeD, CornerCase::Four}) {
        const std::int64_t count = header[kHeadCorners + std::size_t(c)];
        vertices += count;
        triangles += std::int64_t(trianglesOf(c)) * count;
    }
    if (vertices != header[kHeadVertices] || triangles != header[kHeadTriangles])
        throw std::logic_error("GL buildTriangles: the chains name " +
                               std::to_string(header[kHeadVertices]) + " vertices and " +
                               std::to_string(header[kHeadTriangles]) + " triangles, G4 counted " +
                               std::to_string(vertices) + " and " + std::to_string(triangles));
}

ResultData readResult(const gl::Buffer& buffer, const ResultLayout& layout, int width, int height) {
    ResultData data;
    // One map of the whole used range: the one read-back (on a discrete GPU the driver copies
    // the range once; on llvmpipe it is the buffer's memory).
    const auto* words = static_cast<const std::uint32_t*>(glMapNamedBufferRange(
        buffer.id(), 0, static_cast<GLsizeiptr>(layout.end), GL_MAP_READ_BIT));
    if (words == nullptr)
        throw gl::GlError("GL discrete Delaunay: cannot map the result buffer (" +
                          std::to_string(layout.end) + " bytes)");
    std::copy_n(words, kHeaderWords, data.header.begin());
    const std::uint32_t* keepers = words + layout.keepers / sizeof(std::uint32_t);
    data.keepers.assign(keepers, keepers + layout.sites);
    if (layout.texels > 0) {
        data.cleaned.width = width;
        data.cleaned.height = height;
        const std::uint32_t* ids = words + layout.cleaned / sizeof(std::uint32_t);
        data.cleaned.ids.assign(ids, ids + layout.texels);
    }
    // Records past a capacity were dropped: the caller runs again with room for them.
    if (data.meshFits(layout)) data.mesh = parseMesh(words, layout, data);
    glUnmapNamedBuffer(buffer.id());
    return data;
}

} // namespace gl_stages

gl_stages::ResultData GlDiscreteDelaunay::Impl::readResult() {
    ++extras.readbacks;
    return gl_stages::readResult(result, layout, width, height);
}

} // namespace fl::geom
