#pragma once
// Step 5 of a frame, with the overlays: the window's heads-up display. Lines of text
// (stb_easy_font's segment font, no textures) on a translucent box in the top-left corner, drawn
// over whatever the framebuffer shows. The layout is pure CPU (testable without GL); the pass
// only uploads it and blends it.

#include <gpu/Gl.h>
#include <gpu/Program.h>
#include <gpu/ShaderLibrary.h>
#include <io/ImageIO.h>

#include <glm/glm.hpp>

#include <span>
#include <string>
#include <vector>

namespace fl {

struct HudStyle {
    int scale = 1;   // font pixels per stb_easy_font unit (integer, so glyph edges hit pixel edges)
    int margin = 6;  // box distance from the window's top-left corner, in pixels
    int padding = 4; // text distance from the box edge, in pixels
    /// The window's width in pixels: lines wrap at spaces so that the box fits it (continuations
    /// indented); 0 = no limit (layoutHud), the window's width (HudPass::draw); < 0: no limit.
    int maxWidth = 0;
    glm::vec4 text{1.0f, 1.0f, 1.0f, 1.0f};
    glm::vec4 warning{1.0f, 0.45f, 0.35f, 1.0f}; // lines that start with "!"
    glm::vec4 background{0.0f, 0.0f, 0.0f, 0.6f};
};

/// One vertex in window pixels (origin top-left, y down) with a straight-alpha colour.
struct HudVertex {
    glm::vec2 pos;
    glm::vec4 color;
};

struct HudGeometry {
    std::vector<HudVertex> triangles; // background box first, then glyph segments; 6 per quad
    glm::ivec2 boxMin{0}, boxMax{0};  // the background box (empty lines -> no box, no triangles)
};

/// Lays out `lines` top to bottom: one 12-unit row per line; a tab splits a line into two
/// columns (the second aligned over all lines); other characters outside ' '..'~' show as '?'.
/// With style.maxWidth, a line without a tab that would reach past it wraps at spaces (a word
/// wider than the window is cut where it reaches the edge).
HudGeometry layoutHud(std::span<const std::string> lines, const HudStyle& style = {});

/// CPU reference of HudPass::draw: blends every quad of `geometry` (axis-aligned, as layoutHud
/// makes them) over an 8-bit RGBA image (row 0 at the top) with src-alpha / one-minus-src-alpha,
/// covering the pixels whose centres are inside the quad.
void rasterizeHud(const HudGeometry& geometry, ByteImage& image);

class HudPass {
  public:
    explicit HudPass(const gl::ShaderLibrary& shaders);
    /// Blends the HUD for `lines` into `framebuffer` (0 = the window) of width x height pixels.
    /// Every GL state it changes (blend, depth, cull, scissor, viewport, bindings) is restored.
    /// Lines wrap to the window's width unless style.maxWidth says otherwise.
    void draw(std::span<const std::string> lines, int width, int height, const HudStyle& style = {},
              GLuint framebuffer = 0);

  private:
    gl::Program program_;
    gl::VertexArray vao_;
};

} // namespace fl
