#pragma once
// The drawing primitives of the overlays: a grid shown texel by texel through one of the colour
// modes of shaders/overlay_grid.frag.glsl, and coloured lines and points. Both draw into the
// currently bound framebuffer inside a given viewport and restore the GL state they change.

#include <gpu/Gl.h>
#include <gpu/Program.h>
#include <gpu/ShaderLibrary.h>
#include <scene/DiskLight.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace fl::overlay {

/// The colour modes of shaders/overlay_grid.frag.glsl (see there).
enum class GridMode { Depth = 0, Seeds = 1, Occluder = 2, Voronoi = 3, Distance = 4, Diff = 5 };

struct GridDraw {
    GridMode mode = GridMode::Depth;
    const gl::Texture* a = nullptr; // the grid (its size sets the texel mapping)
    const gl::Texture* b = nullptr; // Occluder: receivers / points; Diff: the other grid
    const gl::Texture* c = nullptr; // Voronoi / Distance: error mask (nonzero = error), optional
    float scale = 1.0f;             // Distance: the distance drawn at the top of the ramp
    bool lightSpace = false;        // Depth: the viewport spans light NDC, warped by `warp`
    bool eyeSpace = false;          // Occluder: b holds EyeImage::points (w = 1: hard shadow)
    glm::mat4 warp{1.0f};
    const DiskLight* light = nullptr; // Occluder
};

/// A line or point vertex in viewport NDC ([-1, 1]^2) with its colour.
struct Vertex {
    glm::vec2 ndc;
    glm::vec4 colour;
};

/// The largest centred square in a w x h framebuffer: {x, y, side, side}.
glm::ivec4 squareViewport(int w, int h);

/// Uploads a 0/1 mask (row-major, row 0 at y = 0) as an R8 texture.
gl::Texture uploadMask(const std::vector<std::uint8_t>& mask, int width, int height);

class OverlayCanvas {
  public:
    /// Compiles the overlay programs (needs a current context).
    explicit OverlayCanvas(const gl::ShaderLibrary& shaders);
    /// Draws a grid into `viewport` ({x, y, width, height} of the bound framebuffer).
    void drawGrid(const GridDraw& grid, glm::ivec4 viewport) const;
    /// Draws vertices as GL_LINES, GL_LINE_STRIP, GL_LINE_LOOP or GL_POINTS into `viewport`.
    void drawVertices(std::span<const Vertex> vertices, GLenum primitive, glm::ivec4 viewport,
                      float pointSize = 1.0f) const;

  private:
    gl::Program grid_, lines_;
    gl::VertexArray emptyVao_, linesVao_;
    gl::Handle<gl::detail::SamplerDeleter> nearest_; // texelFetch without depth comparison
};

} // namespace fl::overlay
