#pragma once
// The Voronoi criterion: the nearest site wins; equal distances go to the smaller id, then the
// smaller y, then the smaller x, so results are deterministic and order-independent.

#include <jfa/Grid.h>

#include <cmath>
#include <cstdint>

namespace fl::jfa {

struct NearestSite {
    /// Integer sites (cell x, y integral): distances are exact 64-bit integer squares. Otherwise
    /// float: d = dx*dx + dy*dy evaluated in float without fused multiply-add (the GLSL side
    /// marks it `precise`), so CPU and GL agree bit for bit.
    bool integerSites = true;
    static constexpr const char* glslFile = "jfa_nearest_site.glsl";

    [[nodiscard]] bool empty(const Cell& c) const { return c.z < 0.0f; }

    [[nodiscard]] bool better(int px, int py, const Cell& a, const Cell& b) const {
        if (integerSites) {
            const std::int64_t da = squaredInt(px, py, a), db = squaredInt(px, py, b);
            if (da != db) return da < db;
        } else {
            const float da = squaredFloat(px, py, a), db = squaredFloat(px, py, b);
            if (da != db) return da < db;
        }
        if (a.z != b.z) return a.z < b.z;
        if (a.y != b.y) return a.y < b.y;
        return a.x < b.x;
    }

    /// The full-resolution pixel the cell's site was seeded at: floor(v + 0.5) per coordinate
    /// (as seedPoints rounds). The half-resolution expansion uses it to find the sites a
    /// representative stands for (thesis §4.3.2, "Halve Resolution").
    [[nodiscard]] static GridPoint seedPixel(const Cell& c) {
        return {int(std::floor(double(c.x) + 0.5)), int(std::floor(double(c.y) + 0.5))};
    }

    static std::int64_t squaredInt(int px, int py, const Cell& c) {
        const std::int64_t dx = std::int64_t(c.x) - px, dy = std::int64_t(c.y) - py;
        return dx * dx + dy * dy;
    }
    static float squaredFloat(int px, int py, const Cell& c) {
        const float dx = c.x - float(px), dy = c.y - float(py);
        return dx * dx + dy * dy; // no FMA: the project builds with -ffp-contract=off
    }
};

static_assert(Criterion<NearestSite>);

} // namespace fl::jfa
