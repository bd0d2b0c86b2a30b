#pragma once
// Steps G1-G6 of the thesis' Delaunay pipeline (ch. 6, §6.3.2) on the GPU through OpenGL 4.5
// compute shaders (shaders/delaunay_*.glsl), producing exactly what the CPU backend
// discreteDelaunay() (geometry/DiscreteDelaunay.h) produces, every stage equal byte for byte:
//   G1 the host maps and snaps the sites (double precision, as snapSites); a compute pass lets
//      every site claim its pixel with imageAtomicMin, so the lowest index keeps it;
//   G2 jfa::GlFloodKernel (fragment or compute) runs the same plan with the same integer
//      NearestSite criterion;
//   G3 island-removal passes, ping-pong, with an atomic counter of recoloured pixels, until 0;
//   G4 corner classification with per-case atomic counts;
//   G5 the one-sided 1D JFA along rows, ping-pong;
//   G6 one invocation per row walks its chain and scatters its vertices and triangles into
//      buffers in blocks reserved by atomic counters; the host puts the blocks in row order.
// It needs a current GL 4.5 context (no windowing here) and throws gl::GlError on GL failures.

#include <geometry/DiscreteDelaunay.h>
#include <jfa/GlKernel.h>

#include <glm/glm.hpp>

#include <memory>
#include <vector>

namespace fl::geom {

/// Where the GL backend spent the time that DiscreteTimings does not show.
struct GlDiscreteExtras {
    double readbackMs = 0.0; // reading the voronoi, cleaned, corner and chain textures back
};

/// The compiled G1-G6 programs and their textures and buffers, kept between runs so that
/// repeated runs neither recompile nor reallocate (textures are resized when N changes).
class GlDiscreteDelaunay {
  public:
    /// Builds the step programs from `shaders` (needs a current GL 4.5 context); G2 floods with
    /// the `flood` kernel (fragment: never slower on llvmpipe, docs/BENCHMARKS.md).
    explicit GlDiscreteDelaunay(const gl::ShaderLibrary& shaders,
                                jfa::GlKernelKind flood = jfa::GlKernelKind::Fragment);
    ~GlDiscreteDelaunay();
    GlDiscreteDelaunay(GlDiscreteDelaunay&&) noexcept;
    GlDiscreteDelaunay& operator=(GlDiscreteDelaunay&&) noexcept;

    /// G1-G6 on `sites`: the same result as discreteDelaunay(sites, options) except the
    /// timings, which are GPU wall times per step (glFinish; llvmpipe's timer queries read 0
    /// for compute). `threads` is validated and otherwise unused. Throws std::invalid_argument
    /// as discreteDelaunay does.
    DiscreteDelaunay run(const std::vector<glm::dvec2>& sites,
                         const DiscreteDelaunayOptions& options = {});

    /// G3 alone on any W x H texture: the GL twin of removeIslands(ids, pixels).
    IslandStats removeIslands(IdTexture& ids, const std::vector<glm::ivec2>& pixels);

    /// G4-G6 alone on any W x H texture (after G3): the GL twin of classifyCorners,
    /// chainRowsJfa and buildTriangles; `corners` and `chain` receive G4's and G5's results.
    DiscreteTriangles buildTriangles(const IdTexture& ids, const std::vector<glm::ivec2>& pixels,
                                     CornerTexture* corners = nullptr,
                                     VertexChain* chain = nullptr);

    /// What the last run() spent outside its step timings.
    [[nodiscard]] const GlDiscreteExtras& extras() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

/// One-off convenience: compiles the programs from the embedded shaders and runs G1-G6 (hold a
/// GlDiscreteDelaunay to run repeatedly). Same signature as discreteDelaunay, so it can serve as
/// DelaunayOptions::discreteBackend.
DiscreteDelaunay glDiscreteDelaunay(const std::vector<glm::dvec2>& sites,
                                    const DiscreteDelaunayOptions& options = {});

} // namespace fl::geom
