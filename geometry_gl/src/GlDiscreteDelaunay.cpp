// G1-G6 on the GL side in a row, timed, with the one upload and the one read-back that fill
// DiscreteDelaunay (thesis §6.3.2); the steps themselves are in GlDiscreteDelaunaySteps.cpp, the
// read-backs in GlDiscreteDelaunayResult.cpp.
#include "GlDiscreteDelaunayDetail.h"

#include <gpu/ShaderLibrary.h>
#include <jfa/CpuKernel.h>

#include <algorithm>
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

// Corners of a W x H texture that can be Voronoi vertices (the last row and column cannot).
std::size_t innerCorners(int w, int h) {
    return w < 2 || h < 2 ? 0 : std::size_t(w - 1) * std::size_t(h - 1);
}

// G1's host part: the double-precision mapping and snap, as snapSites does, the snap spread
// over `threads` (each pixel depends on its site alone, so the result is the same).
void snapOnHost(const std::vector<glm::dvec2>& sites, int n, int threads, SnappedSites& snapped) {
    snapped.mapping = fitTextureMapping(sites, n);
    snapped.pixels.resize(sites.size());
    jfa::parallelRows(static_cast<int>(sites.size()), threads, [&](int begin, int end, int) {
        for (int i = begin; i < end; ++i)
            snapped.pixels[std::size_t(i)] = snapped.mapping.pixelOf(sites[std::size_t(i)]);
    });
}

// S' and the missing sites from each site's keeper (itself if it kept its pixel).
void splitKeepers(const std::vector<std::uint32_t>& keepers, SnappedSites& snapped) {
    std::size_t kept = 0;
    for (std::size_t i = 0; i < keepers.size(); ++i) kept += keepers[i] == i ? 1 : 0;
    snapped.kept.reserve(kept);
    snapped.missing.reserve(keepers.size() - kept);
    for (std::size_t i = 0; i < keepers.size(); ++i) {
        const auto site = static_cast<std::uint32_t>(i);
        if (keepers[i] == site)
            snapped.kept.push_back(site);
        else
            snapped.missing.push_back({site, keepers[i]});
    }
}

} // namespace

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

void GlDiscreteDelaunay::setReadStages(bool read) {
    impl_->readStages = read;
}

void GlDiscreteDelaunay::setBounds(const GlDiscreteBounds& bounds) {
    impl_->bounds = bounds;
    impl_->neededPasses = 0;
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
    g.extras = {};
    DiscreteDelaunay r;
    Stopwatch clock;

    // G1: the double-precision mapping stays on the host (as snapSites; extras.snapMs says what
    // it costs); its pixels are the one upload. The GPU resolves who keeps each pixel.
    snapOnHost(sites, n, options.threads, r.snapped);
    g.extras.snapMs = clock.lap();
    r.timings.g1 = g.extras.snapMs;
    g.resize(n, n);
    g.uploadPixels(r.snapped.pixels);
    r.timings.g1 += clock.lap();

    // Room for a Delaunay triangulation of the sites (fewer than 2 triangles per site) and then
    // some, never more than the corners allow.
    const std::size_t corners = innerCorners(n, n);
    const auto estimate =
        std::size_t(g.bounds.meshPerSite * double(sites.size())) + g.bounds.meshSlack;
    std::size_t vertexCap = std::min(corners, estimate);
    std::size_t triangleCap = std::min(2 * corners, estimate);
    const int queued = g.bounds.islandPasses > 0 ? g.bounds.islandPasses : std::max(32, n / 8);
    int islandPasses = std::max(queued, g.neededPasses);
    gl_stages::ResultData data;
    while (true) {
        data = g.runSteps(plan, sites.size(), islandPasses, vertexCap, triangleCap, r.timings);
        const bool islandsEnded = data.header[gl_stages::kHeadUnfinished] == 0;
        if (islandsEnded && data.meshFits(g.layout)) break;
        // The second attempt queues the CPU's cap of G3 passes and exactly the room G6 named.
        if (g.extras.attempts > 1)
            throw std::logic_error("GL discrete Delaunay: a second run still did not fit");
        if (!islandsEnded) islandPasses = 2 * n;
        vertexCap = std::max<std::size_t>(vertexCap, data.header[gl_stages::kHeadVertices]);
        triangleCap = std::max<std::size_t>(triangleCap, data.header[gl_stages::kHeadTriangles]);
    }
    Stopwatch readClock;
    data.checkMeshCounts();
    r.islands = data.islandStats();
    g.neededPasses = r.islands.passes;
    splitKeepers(data.keepers, r.snapped);
    r.cleaned = std::move(data.cleaned);
    r.mesh = std::move(data.mesh);

    // The intermediate stages only when asked for (the step pictures, the visualiser, tests):
    // the CPU steps need only the mesh, the missing sites and (C1) the cleaned texture.
    if (g.readStages || options.countIslands) {
        r.voronoi = readIds(g.voronoi);
        ++g.extras.readbacks;
    }
    if (g.readStages) {
        r.corners = readCorners(g.corners, data.cornerCounts(n, n));
        r.chain = readChain(*g.finalChain);
        g.extras.readbacks += 2;
    }
    checkStep("read-back");
    g.extras.readbackMs += readClock.lap();

    if (options.countIslands) r.islandsBefore = countIslandComponents(r.voronoi, r.snapped.pixels);
    return r;
}

gl_stages::ResultData GlDiscreteDelaunay::Impl::runSteps(const jfa::Plan& plan, std::size_t sites,
                                                         int islandPasses, std::size_t vertexCap,
                                                         std::size_t triangleCap,
                                                         DiscreteTimings& timings) {
    Stopwatch clock;
    ++extras.attempts;
    const int n = width;
    prepareResult(sites, std::size_t(n) * std::size_t(n), vertexCap, triangleCap);
    claimPixels(sites);
    checkStep("G1");
    timings.g1 += clock.lap();
    flood(plan);
    checkStep("G2");
    timings.g2 += clock.lap();
    removeIslands(voronoi, islandPasses);
    checkStep("G3");
    timings.g3 += clock.lap();
    classifyCorners(cleaned);
    checkStep("G4");
    timings.g4 += clock.lap();
    finalChain = &chainRows();
    checkStep("G5");
    timings.g5 += clock.lap();
    buildTriangles(cleaned, *finalChain);
    checkStep("G6");
    timings.g6 += clock.lap();
    packCleaned();
    gl_stages::ResultData data = readResult();
    checkStep("read-back");
    extras.readbackMs += clock.lap();
    return data;
}

void GlDiscreteDelaunay::Impl::startFromIds(const IdTexture& ids,
                                            const std::vector<glm::ivec2>& sitePixels,
                                            const char* what) {
    checkShape(ids, what);
    extras = {};
    resize(ids.width, ids.height);
    uploadPixels(sitePixels);
    uploadIds(voronoi, ids);
    ++extras.uploads;
}

IslandStats GlDiscreteDelaunay::removeIslands(IdTexture& ids,
                                              const std::vector<glm::ivec2>& pixels) {
    Impl& g = *impl_;
    g.startFromIds(ids, pixels, "GL removeIslands");
    g.prepareResult(0, 0, 0, 0);
    g.removeIslands(g.voronoi, 2 * std::max(ids.width, ids.height));
    ids = readIds(g.cleaned);
    ++g.extras.readbacks;
    const IslandStats stats = g.readResult().islandStats();
    checkStep("G3");
    return stats;
}

DiscreteTriangles GlDiscreteDelaunay::buildTriangles(const IdTexture& ids,
                                                     const std::vector<glm::ivec2>& pixels,
                                                     CornerTexture* corners, VertexChain* chain) {
    Impl& g = *impl_;
    g.startFromIds(ids, pixels, "GL buildTriangles");
    // Every corner a vertex, two triangles each: room for anything, so one attempt.
    const std::size_t cornerCount = innerCorners(ids.width, ids.height);
    g.prepareResult(0, 0, cornerCount, 2 * cornerCount);
    g.classifyCorners(g.voronoi);
    const gl::Texture& chainTexture = g.chainRows();
    g.buildTriangles(g.voronoi, chainTexture);
    gl_stages::ResultData data = g.readResult();
    data.checkMeshCounts();
    if (corners) *corners = readCorners(g.corners, data.cornerCounts(ids.width, ids.height));
    if (chain) *chain = readChain(chainTexture);
    g.extras.readbacks += (corners ? 1 : 0) + (chain ? 1 : 0);
    checkStep("G4-G6");
    return std::move(data.mesh);
}

DiscreteDelaunay glDiscreteDelaunay(const std::vector<glm::dvec2>& sites,
                                    const DiscreteDelaunayOptions& options) {
    const gl::ShaderLibrary shaders;
    GlDiscreteDelaunay backend(shaders);
    return backend.run(sites, options);
}

} // namespace fl::geom
