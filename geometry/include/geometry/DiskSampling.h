#pragma once
// Points on a disk from points on a square: Shirley and Chiu's concentric map (1997). It is
// area-preserving, so equal cells of the square stay equal-area strata on the disk; both ground
// truths (the shadow maps' point lights and the ray tracer's shadow rays) place their samples
// with it.

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <string_view>
#include <vector>

namespace fl::geom {

/// The point of the unit disk for (u, v) in [-1, 1]^2; (0, 0) maps exactly to the centre.
glm::dvec2 concentricDisk(double u, double v);

/// The grid the disk's N stratified samples use: the most square rows x cols with rows * cols = N
/// (rows <= cols).
glm::ivec2 stratifiedGrid(int samples);

/// How N points are spread over the disk, when the same N points serve every pixel (the
/// shadow-map reference renders one map per point). A straight edge across the disk hides the
/// points on one side of a line, so what matters is how evenly every line splits them:
///  - Grid: the centres of the stratified grid's cells (Shirley-Chiu). Its points sit in rings
///    and rows, so a straight edge uncovers them in groups: visibility steps, and penumbrae band.
///  - Jittered: one point per cell at a fixed pseudo-random place (the same for every call).
///  - Spiral: Vogel's golden-angle spiral, r = sqrt((k + 1/2) / N), angle = k * 137.5 degrees:
///    no two points share a ring or a row, so every line's split is close to its area.
/// N = 1 is the disk's centre for every pattern.
enum class DiskPattern { Grid, Jittered, Spiral };
struct DiskPatternName {
    DiskPattern pattern;
    std::string_view name;
};
// The default (the shadow-map reference's) first, as --reference-pattern lists them.
inline constexpr DiskPatternName kDiskPatterns[] = {{DiskPattern::Spiral, "spiral"},
                                                    {DiskPattern::Grid, "grid"},
                                                    {DiskPattern::Jittered, "jittered"}};

/// The pattern named `name` (one of kDiskPatterns); throws std::invalid_argument otherwise.
DiskPattern diskPatternNamed(std::string_view name);

/// N >= 1 points of the unit disk in `pattern`.
std::vector<glm::dvec2> diskPattern(DiskPattern pattern, int samples);

/// Two unit vectors spanning the plane of a disk with normal `normal` (any length > 0): with the
/// normal they form a right-handed orthonormal basis. The same for every caller, so both ground
/// truths place a sample at the same point.
struct DiskFrame {
    glm::vec3 tangent, bitangent;
};
DiskFrame diskFrame(glm::vec3 normal);

} // namespace fl::geom
