// G1-G6 on the GL side in a row, timed, plus the read-backs that fill DiscreteDelaunay (thesis
// §6.3.2); the steps themselves are in GlDiscreteDelaunaySteps.cpp.
#include "GlDiscreteDelaunayDetail.h"

#include <gpu/ShaderLibrary.h>
#include <jfa/CpuKernel.h>

#include <chrono>
#include <stdexcept>
#include <string>

namespace fl::geom {

namespace {

class Stopwatch {
  public:
    // Starts once the GPU has finished earlier work, which is not ours to time.
    Stopwatch() : last_((glFinish(), std::chrono::steady_clock::now())) {}
    // Milliseconds since the last call (or construction), once the GPU has finished.
    double lap() {
        // llvmpipe's timer queries read 0 for compute, so wall time after glFinish it is.
        glFinish();
        const auto now = std::chrono::steady_clock::now();
        const double ms = std::chrono::duration<double, std::milli>(now - last_).count();
        last_ = now;
        return ms;
    }

  private:
    std::chrono::steady_clock::time_point last_;
};

// A step's GL errors surface at that step, not as odd data several steps later.
void checkStep(const char* step) {
    gl::throwIfErrors((std::string("GL discrete Delaunay ") + step).c_str());
}

void checkShape(const IdTexture& ids, const char* what) {
    if (ids.width <= 0 || ids.height <= 0 ||
        ids.ids.size() != std::size_t(ids.width) * std::size_t(ids.height))
        throw std::invalid_argument(std::string(what) + ": the texture is empty or its size (" +
                                    std::to_string(ids.width) + "x" + std::to_string(ids.height) +
                                    ") does not match its data");
}

// glGetTextureImage into a vector of the texture's texel type, rows packed tight.
template <typename T>
void readTexture(const gl::Texture& texture, GLenum format, GLenum type, std::vector<T>& out) {
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
    readTexture(texture, GL_RED_INTEGER, type, grid.*texels);
    return grid;
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

} // namespace gl_stages

using gl_stages::readChain;
using gl_stages::readCorners;
using gl_stages::readIds;
using gl_stages::uploadIds;

GlDiscreteDelaunay::GlDiscreteDelaunay(const gl::ShaderLibrary& shaders, jfa::GlKernelKind flood)
    : impl_(std::make_unique<Impl>(shaders, flood)) {}
GlDiscreteDelaunay::~GlDiscreteDelaunay() = default;
GlDiscreteDelaunay::GlDiscreteDelaunay(GlDiscreteDelaunay&&) noexcept = default;
GlDiscreteDelaunay& GlDiscreteDelaunay::operator=(GlDiscreteDelaunay&&) noexcept = default;

const GlDiscreteExtras& GlDiscreteDelaunay::extras() const {
    return impl_->extras;
}

DiscreteDelaunay GlDiscreteDelaunay::run(const std::vector<glm::dvec2>& sites,
                                         const DiscreteDelaunayOptions& options) {
    // Bad input fails before any work and with discreteDelaunay's messages: the thread count,
    // the size, the plan, then (in G1) the site count and the sites.
    jfa::resolveThreads(options.threads);
    fitTextureMapping({}, options.size);
    const int n = options.size;
    const jfa::Plan plan = jfa::parsePlan(options.plan, n, n);
    if (sites.size() > kMaxDiscreteSites) {
        throw std::invalid_argument("discrete Delaunay: " + std::to_string(sites.size()) +
                                    " sites, at most " + std::to_string(kMaxDiscreteSites) +
                                    " fit (ids are stored in floats)");
    }
    Impl& g = *impl_;
    DiscreteDelaunay r;
    Stopwatch clock;

    // G1: the double-precision mapping stays on the host (as snapSites); the GPU resolves who
    // keeps each pixel.
    SnappedSites& snapped = r.snapped;
    snapped.mapping = fitTextureMapping(sites, n);
    snapped.pixels.resize(sites.size());
    for (std::size_t i = 0; i < sites.size(); ++i)
        snapped.pixels[i] = snapped.mapping.pixelOf(sites[i]);
    g.resize(n, n);
    g.uploadPixels(snapped.pixels);
    const std::vector<std::uint32_t> keepers = g.claimPixels(sites.size());
    for (std::size_t i = 0; i < keepers.size(); ++i) {
        const auto site = static_cast<std::uint32_t>(i);
        if (keepers[i] == site)
            snapped.kept.push_back(site);
        else
            snapped.missing.push_back({site, keepers[i]});
    }
    checkStep("G1");
    r.timings.g1 = clock.lap();

    g.flood(plan);
    checkStep("G2");
    r.timings.g2 = clock.lap();

    const gl::Texture& cleaned = g.removeIslands(g.voronoi, r.islands);
    checkStep("G3");
    r.timings.g3 = clock.lap();

    const CornerCounts counts = g.classifyCorners(cleaned);
    checkStep("G4");
    r.timings.g4 = clock.lap();

    const gl::Texture& chain = g.chainRows();
    checkStep("G5");
    r.timings.g5 = clock.lap();

    r.mesh = g.buildTriangles(cleaned, chain, counts);
    checkStep("G6");
    r.timings.g6 = clock.lap();

    // The intermediate stages, for the step pictures and the visualiser; the CPU steps need
    // only the mesh, the missing sites and (C1) the cleaned texture.
    r.voronoi = readIds(g.voronoi);
    r.cleaned = readIds(cleaned);
    r.corners = readCorners(g.corners, counts);
    r.chain = readChain(chain);
    checkStep("read-back");
    g.extras.readbackMs = clock.lap();

    if (options.countIslands) r.islandsBefore = countIslandComponents(r.voronoi, snapped.pixels);
    return r;
}

IslandStats GlDiscreteDelaunay::removeIslands(IdTexture& ids,
                                              const std::vector<glm::ivec2>& pixels) {
    checkShape(ids, "GL removeIslands");
    Impl& g = *impl_;
    g.resize(ids.width, ids.height);
    g.uploadPixels(pixels);
    uploadIds(g.voronoi, ids);
    IslandStats stats;
    const gl::Texture& out = g.removeIslands(g.voronoi, stats);
    ids = readIds(out);
    checkStep("G3");
    return stats;
}

DiscreteTriangles GlDiscreteDelaunay::buildTriangles(const IdTexture& ids,
                                                     const std::vector<glm::ivec2>& pixels,
                                                     CornerTexture* corners, VertexChain* chain) {
    checkShape(ids, "GL buildTriangles");
    Impl& g = *impl_;
    g.resize(ids.width, ids.height);
    g.uploadPixels(pixels);
    uploadIds(g.voronoi, ids);
    const CornerCounts counts = g.classifyCorners(g.voronoi);
    const gl::Texture& chainTexture = g.chainRows();
    DiscreteTriangles mesh = g.buildTriangles(g.voronoi, chainTexture, counts);
    if (corners) *corners = readCorners(g.corners, counts);
    if (chain) *chain = readChain(chainTexture);
    checkStep("G4-G6");
    return mesh;
}

DiscreteDelaunay glDiscreteDelaunay(const std::vector<glm::dvec2>& sites,
                                    const DiscreteDelaunayOptions& options) {
    const gl::ShaderLibrary shaders;
    GlDiscreteDelaunay backend(shaders);
    return backend.run(sites, options);
}

} // namespace fl::geom
