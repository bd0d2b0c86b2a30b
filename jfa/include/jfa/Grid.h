#pragma once
// What a flood works on: a W x H grid of cells, each holding the best seed found so far. The
// layout is exactly that of the GL kernels' RGBA32F textures (row 0 at y = 0, no flips), so CPU
// and GL results compare texel for texel.

#include <concepts>
#include <cstdint>
#include <vector>

namespace fl::jfa {

/// One texel's record: four floats whose meaning the criterion defines. For the Voronoi
/// criteria: x, y = the site's position in full-resolution grid coordinates (integers for
/// integer sites, any float for sub-pixel sites), z = the site's id (>= 0; < 2^24 so that it is
/// exact in a float; -1 = empty), w = 0.
struct Cell {
    float x = 0.0f;
    float y = 0.0f;
    float z = -1.0f;
    float w = 0.0f;
    friend bool operator==(const Cell&, const Cell&) = default;
};

/// Row-major cells; cell (x, y) is cells[y * width + x].
struct Grid {
    int width = 0;
    int height = 0;
    std::vector<Cell> cells;

    Grid() = default;
    /// A width x height grid filled with `fill`.
    Grid(int w, int h, Cell fill = {})
        : width(w), height(h), cells(std::size_t(w) * std::size_t(h), fill) {}
    [[nodiscard]] Cell& at(int x, int y) {
        return cells[std::size_t(y) * std::size_t(width) + std::size_t(x)];
    }
    [[nodiscard]] const Cell& at(int x, int y) const {
        return cells[std::size_t(y) * std::size_t(width) + std::size_t(x)];
    }
    friend bool operator==(const Grid&, const Grid&) = default;
};

/// How a texel picks the best among the cells it reads. `better(px, py, a, b)` says whether
/// non-empty `a` is strictly better than non-empty `b` for the grid point (px, py) in
/// full-resolution coordinates; it must be a strict total order on distinct non-empty cells, so
/// that the result does not depend on the order the kernel reads the 9 candidates in.
/// `glslFile` names the GLSL file (in shaders/) defining the same two functions for the GL
/// kernel:  bool jfaEmpty(vec4 c);  bool jfaBetter(ivec2 p, vec4 a, vec4 b);
/// plus any uniforms they need, which the criterion's `apply(program)` (GL side) sets.
template <class C>
concept Criterion = requires(const C& c, int px, int py, const Cell& a, const Cell& b) {
    { c.empty(a) } -> std::convertible_to<bool>;
    { c.better(px, py, a, b) } -> std::convertible_to<bool>;
    { C::glslFile } -> std::convertible_to<const char*>;
};

/// Grid point (full-resolution coordinates) that texel (x, y) of a grid at `scale` (1 = full
/// resolution, 2 = the half-resolution stage) stands for: (x * scale, y * scale).
struct GridPoint {
    int x;
    int y;
};
inline GridPoint gridPoint(int x, int y, int scale) {
    return {x * scale, y * scale};
}

} // namespace fl::jfa
