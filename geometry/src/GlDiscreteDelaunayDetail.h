#pragma once
// Private to the GL backend of G1-G6 (GlDiscreteDelaunay*.cpp): the compiled programs, the
// textures and buffers a run works in, and one member per step.

#include <geometry/GlDiscreteDelaunay.h>

#include <gpu/Gl.h>
#include <gpu/Program.h>
#include <jfa/GlKernel.h>
#include <jfa/Plan.h>

#include <array>
#include <cstdint>
#include <vector>

namespace fl::geom {

// Names private to the GL backend, kept out of fl::geom proper.
namespace gl_stages {

/// Corners per CornerCase value (CornerTexture::counts).
using CornerCounts = std::array<std::int64_t, kCornerCaseCount>;

/// Uploads an IdTexture into an r32ui texture of the same size.
void uploadIds(const gl::Texture& texture, const IdTexture& ids);
/// Reads an r32ui texture back as an IdTexture.
IdTexture readIds(const gl::Texture& texture);
/// Reads G4's r8ui texture back, with the counts G4 made.
CornerTexture readCorners(const gl::Texture& texture, const CornerCounts& counts);
/// Reads G5's r32i texture back.
VertexChain readChain(const gl::Texture& texture);

} // namespace gl_stages

using gl_stages::CornerCounts;

struct GlDiscreteDelaunay::Impl {
    Impl(const gl::ShaderLibrary& shaders, jfa::GlKernelKind flood);

    /// (Re)allocates the textures for a W x H run; keeps them when the size is unchanged.
    void resize(int w, int h);
    /// Uploads the sites' pixels (the G1, G3 and G6 kernels look sites up by id).
    void uploadPixels(const std::vector<glm::ivec2>& pixels);

    /// G1: claims every uploaded site's pixel (lowest index keeps it) into `owner`, writes the
    /// keepers' jfa seeds into `seeds`; returns each site's keeper (itself if it kept its pixel).
    std::vector<std::uint32_t> claimPixels(std::size_t count);
    /// G2: floods `seeds` with `plan` and converts the cells into site ids in `voronoi`.
    void flood(const jfa::Plan& plan);
    /// G3: island-removal passes on `in` until one changes nothing; returns the final texture
    /// (`in` itself if the first pass changed nothing).
    const gl::Texture& removeIslands(const gl::Texture& in, IslandStats& stats);
    /// G4: classifies the corners of `ids` into `corners`; returns the per-case counts.
    CornerCounts classifyCorners(const gl::Texture& ids);
    /// G5: the row chains of `corners`; returns the final ping-pong texture.
    const gl::Texture& chainRows();
    /// G6: the triangles of the vertices G4 counted in `counts`, in the CPU's order.
    DiscreteTriangles buildTriangles(const gl::Texture& ids, const gl::Texture& chain,
                                     const CornerCounts& counts);

    gl::Program sitesProgram, idsProgram, islandsProgram, cornersProgram, chainProgram,
        trianglesProgram;
    jfa::GlFloodKernel<jfa::NearestSite> floodKernel;

    int width = 0;
    int height = 0;
    gl::Texture owner;      // G1: r32ui, the lowest site index per pixel
    gl::Texture seeds;      // G1: rgba32f jfa cells, the flood's input
    gl::Texture voronoi;    // G2: r32ui site ids
    gl::Texture islands[2]; // G3: r32ui ping-pong
    gl::Texture corners;    // G4: r8ui CornerCase per corner
    gl::Texture chain[2];   // G5: r32i ping-pong

    gl::Buffer pixels;       // ivec2 per site
    gl::Buffer keepers;      // G1: uint per site
    gl::Buffer changed;      // G3: atomic counter of recoloured pixels
    gl::Buffer cornerCounts; // G4: uint per CornerCase
    gl::Buffer meshCounters; // G6: vertices, triangles, TriangleStats
    gl::Buffer rows;         // G6: uvec4 per corner row
    gl::Buffer vertices;     // G6: 6 uints per vertex
    gl::Buffer triangles;    // G6: uvec4 per triangle

    GlDiscreteExtras extras;
};

} // namespace fl::geom
