#pragma once
// Private to the GL backend of G1-G6 (GlDiscreteDelaunay*.cpp): the compiled programs, the
// textures and buffers a run works in, and one member per step.

#include <geometry_gl/GlDiscreteDelaunay.h>

#include <gpu/Gl.h>
#include <gpu/Program.h>
#include <jfa/Plan.h>
#include <jfa_gl/GlKernel.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace fl::geom {

// Names private to the GL backend, kept out of fl::geom proper.
namespace gl_stages {

/// Corners per CornerCase value (CornerTexture::counts).
using CornerCounts = std::array<std::int64_t, kCornerCaseCount>;

// The result header's and G3's loop state's word indices (kHead*, kHeaderWords, kCtl*): one
// definition, shared with the kernels.
using uint = std::uint32_t;
#include "delaunay_result.glsl" // on the include path through floodlight_gpu (shaders/)

static_assert(kHeadCorners + kCornerCaseCount <= kHeaderWords, "the header holds the counts");

/// Where each part of the one result buffer lies (byte offsets, each aligned for binding as a
/// shader storage range) and how many records each part holds.
struct ResultLayout {
    std::size_t sites = 0;       // keepers: one uint per site (G1)
    std::size_t texels = 0;      // cleaned: one uint per texel (G3)
    std::size_t vertexCap = 0;   // vertices: six uints each (G6)
    std::size_t triangleCap = 0; // triangles: three uints, plus one in triangleVertex (G6)
    std::size_t keepers = 0, cleaned = 0, vertices = 0, triangles = 0, triangleVertex = 0;
    std::size_t end = 0; // bytes in all
};

/// The layout for these counts, every part starting at a multiple of `alignment` bytes.
ResultLayout layoutResult(std::size_t sites, std::size_t texels, std::size_t vertexCap,
                          std::size_t triangleCap, std::size_t alignment);

/// What one read-back of the result buffer holds.
struct ResultData {
    std::array<std::uint32_t, kHeaderWords> header{};
    std::vector<std::uint32_t> keepers; // per site: the site that kept its pixel
    DiscreteTriangles mesh;             // empty when the capacities overflowed
    IdTexture cleaned;                  // empty when the layout has no texels
    /// Whether the vertices and triangles fitted their capacities.
    [[nodiscard]] bool meshFits(const ResultLayout& layout) const {
        return header[kHeadVertices] <= layout.vertexCap &&
               header[kHeadTriangles] <= layout.triangleCap;
    }
    [[nodiscard]] CornerCounts cornerCounts(int width, int height) const;
    [[nodiscard]] IslandStats islandStats() const;
    /// Throws std::logic_error unless G6's totals agree with G4's vertex counts.
    void checkMeshCounts() const;
};

/// Uploads an IdTexture into an r32ui texture of the same size.
void uploadIds(const gl::Texture& texture, const IdTexture& ids);
/// Reads an r32ui texture back as an IdTexture.
IdTexture readIds(const gl::Texture& texture);
/// Reads G4's r8ui texture back, with the counts G4 made.
CornerTexture readCorners(const gl::Texture& texture, const CornerCounts& counts);
/// Reads G5's r32i texture back.
VertexChain readChain(const gl::Texture& texture);
/// Maps `buffer` once and parses the parts `layout` names (a W x H cleaned texture).
ResultData readResult(const gl::Buffer& buffer, const ResultLayout& layout, int width, int height);

} // namespace gl_stages

using gl_stages::CornerCounts;
using gl_stages::ResultLayout;

struct GlDiscreteDelaunay::Impl {
    Impl(const gl::ShaderLibrary& shaders, jfa::GlKernelKind flood);

    /// (Re)allocates the textures for a W x H run; keeps them when the size is unchanged.
    void resize(int w, int h);
    /// Uploads the sites' pixels (the G1, G3 and G6 kernels look sites up by id): one upload.
    /// A step run alone on a caller's texture: the extras reset, the textures sized, the site
    /// pixels and the ids uploaded (one upload); `what` names the step in a shape error.
    void startFromIds(const IdTexture& ids, const std::vector<glm::ivec2>& sitePixels,
                      const char* what);
    void uploadPixels(const std::vector<glm::ivec2>& pixels);
    /// Lays out and (re)allocates the result buffer and zeroes its header (a clear, no upload).
    void prepareResult(std::size_t sites, std::size_t texels, std::size_t vertexCap,
                       std::size_t triangleCap);

    /// G1: claims every uploaded site's pixel (lowest index keeps it) into `owner`, writes the
    /// keepers' jfa seeds into `seeds` and each site's keeper into the result's keepers part.
    void claimPixels(std::size_t count);
    /// G2: floods `seeds` with `plan` and converts the cells into site ids in `voronoi`.
    void flood(const jfa::Plan& plan);
    /// G3: queues `bound` island-removal passes on `in` (at most the CPU's 2 N cap) that stop
    /// themselves once one changes nothing, then copies the result into `cleaned` and the loop's
    /// IslandStats into the result header. Nothing is read back.
    void removeIslands(const gl::Texture& in, int bound);
    /// G4: classifies the corners of `ids` into `corners`, counting them in the result header.
    void classifyCorners(const gl::Texture& ids);
    /// G5: the row chains of `corners`; returns the final ping-pong texture.
    const gl::Texture& chainRows();
    /// G6: the triangles of `ids` along `chain`, written in the CPU's order into the result.
    void buildTriangles(const gl::Texture& ids, const gl::Texture& chain);
    /// Copies `cleaned` into the result's cleaned part (on the GPU: a pixel-pack copy).
    void packCleaned();
    /// The one read-back of the result buffer (counted in `extras`).
    gl_stages::ResultData readResult();
    /// One attempt of run(): G1 (GPU part) to G6 on the uploaded pixels with these bounds, each
    /// step's time added to `timings`, then the one read-back.
    gl_stages::ResultData runSteps(const jfa::Plan& plan, std::size_t sites, int islandPasses,
                                   std::size_t vertexCap, std::size_t triangleCap,
                                   DiscreteTimings& timings);

    gl::Program sitesProgram, idsProgram, islandsProgram, controlProgram, resolveProgram,
        cornersProgram, chainProgram, trianglesProgram, scanProgram;
    jfa::GlFloodKernel<jfa::NearestSite> floodKernel;
    std::size_t storageAlignment = 256; // shader storage range offsets (at least 256 bytes)

    int width = 0;
    int height = 0;
    gl::Texture owner;                       // G1: r32ui, the lowest site index per pixel
    gl::Texture seeds;                       // G1: rgba32f jfa cells, the flood's input
    gl::Texture voronoi;                     // G2: r32ui site ids
    gl::Texture islands[2];                  // G3: r32ui ping-pong
    gl::Texture cleaned;                     // G3: r32ui, the loop's result
    gl::Texture corners;                     // G4: r8ui CornerCase per corner
    gl::Texture chain[2];                    // G5: r32i ping-pong
    const gl::Texture* finalChain = nullptr; // G5: the one of `chain` holding the result

    gl::Buffer pixels;  // ivec2 per site
    gl::Buffer control; // G3: the loop's state and indirect dispatch (kCtl* words)
    gl::Buffer rows;    // G6: uvec4 per corner row
    gl::Buffer result;  // header, keepers, cleaned, vertices, triangles: read back once
    ResultLayout layout;

    GlDiscreteExtras extras;
    GlDiscreteBounds bounds;
    bool readStages = false;
    int neededPasses = 0; // G3 passes the last run needed (the next one queues at least these)
};

} // namespace fl::geom
