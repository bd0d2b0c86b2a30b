#pragma once
// Steps G1-G6 of the thesis' Delaunay pipeline (ch. 6, §6.3.2) on the GPU through OpenGL 4.5
// compute shaders (shaders/delaunay_*.glsl), producing exactly what the CPU backend
// discreteDelaunay() (geometry/DiscreteDelaunay.h) produces, every stage equal byte for byte.
// run() makes one upload and one read-back: the host maps and snaps the sites (double
// precision, as snapSites) and uploads their pixels; no step reads anything back; one mapped
// read-back of one result buffer brings the triangles, the keepers (S' and the missing sites)
// and the cleaned texture (C1 walks its border):
//   G1 a compute pass lets every site claim its pixel with imageAtomicMin, so the lowest index
//      keeps it, and writes each site's keeper into the result;
//   G2 jfa::GlFloodKernel (fragment or compute) runs the same plan with the same integer
//      NearestSite criterion;
//   G3 a queue of island-removal passes, ping-pong, each followed by a one-invocation pass that
//      reads the pass' counter of recoloured pixels and, once it is 0, sets the next passes'
//      indirect dispatch to zero groups; a last pass copies the result into `cleaned`;
//   G4 corner classification with per-case atomic counts (in the result header);
//   G5 the one-sided 1D JFA along rows, ping-pong;
//   G6 one invocation per row counts its chain's vertices and triangles, a one-group prefix sum
//      gives every row its first record, a second walk writes them there: the CPU's order.
// Should the queued G3 passes end before the loop did, or G6 need more room than estimated, the
// result says so and run() runs G1-G6 again with the full bounds: a second read-back, counted.
// It needs a current GL 4.5 context (no windowing here) and throws gl::GlError on GL failures.

#include <geometry/DiscreteDelaunay.h>
#include <jfa_gl/GlKernel.h>

#include <glm/glm.hpp>

#include <cstddef>
#include <memory>
#include <vector>

namespace fl::geom {

/// Where the GL backend spent the time that DiscreteTimings does not show, and its transfers
/// between host and GPU, for the last call (run, removeIslands or buildTriangles).
struct GlDiscreteExtras {
    double snapMs = 0.0;     // run(): mapping and snapping the sites on the host (part of G1)
    double readbackMs = 0.0; // the result read-back, plus the stage read-backs when asked for
    int uploads = 0;         // host -> GPU data transfers (buffer and texture uploads)
    int readbacks = 0;       // GPU -> host transfers (buffer maps and gets, texture gets)
    int attempts = 0;        // run(): runs of G1-G6 (2 when the first one's bounds were short)
};

/// How much work run() queues before it learns from the read-back whether it was enough.
struct GlDiscreteBounds {
    // G3 passes queued; 0: max(32, N / 8), more after a run that needed more. Queued passes
    // after the loop has ended run zero work groups: on llvmpipe at 256^2, 512 queued passes
    // took 4.5 ms more than 1 (about 9 us each, with their control pass). 1+JFA floods of
    // uniform, gaussian or grid points need 1-2 passes; 5000 points on a circle at 256^2, 19.
    int islandPasses = 0;
    double meshPerSite = 2.0;     // G6 room: vertices and triangles per site (a Delaunay
                                  // triangulation has fewer than 2 triangles per site) ...
    std::size_t meshSlack = 1024; // ... plus this many
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
    /// for compute), and the stages: `voronoi` only with countIslands or setReadStages(true),
    /// `corners` and `chain` only with setReadStages(true) (each one more read-back).
    /// `threads` runs G1's host part (the snap). Throws std::invalid_argument as
    /// discreteDelaunay does.
    DiscreteDelaunay run(const std::vector<glm::dvec2>& sites,
                         const DiscreteDelaunayOptions& options = {});

    /// G3 alone on any W x H texture: the GL twin of removeIslands(ids, pixels).
    IslandStats removeIslands(IdTexture& ids, const std::vector<glm::ivec2>& pixels);

    /// G4-G6 alone on any W x H texture (after G3): the GL twin of classifyCorners,
    /// chainRowsJfa and buildTriangles; `corners` and `chain` receive G4's and G5's results.
    DiscreteTriangles buildTriangles(const IdTexture& ids, const std::vector<glm::ivec2>& pixels,
                                     CornerTexture* corners = nullptr,
                                     VertexChain* chain = nullptr);

    /// Whether run() also reads back the voronoi, corner and chain textures (for the step
    /// pictures, the visualiser and the tests); off by default.
    void setReadStages(bool read);
    /// The bounds of run()'s first attempt (tests shrink them to exercise the second).
    void setBounds(const GlDiscreteBounds& bounds);

    /// What the last call spent outside its step timings, and its transfers.
    [[nodiscard]] const GlDiscreteExtras& extras() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

/// One-off convenience: compiles the programs from the embedded shaders and runs G1-G6 (hold a
/// GlDiscreteDelaunay to run repeatedly), reading no stages back. Same signature as
/// discreteDelaunay, so it can serve as DelaunayOptions::discreteBackend.
DiscreteDelaunay glDiscreteDelaunay(const std::vector<glm::dvec2>& sites,
                                    const DiscreteDelaunayOptions& options = {});

} // namespace fl::geom
