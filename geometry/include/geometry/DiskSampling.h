#pragma once
// Points on a disk from points on a square: Shirley and Chiu's concentric map (1997). It is
// area-preserving, so equal cells of the square stay equal-area strata on the disk; both ground
// truths (the shadow maps' point lights and the ray tracer's shadow rays) place their samples
// with it.

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace fl::geom {

/// The point of the unit disk for (u, v) in [-1, 1]^2; (0, 0) maps exactly to the centre.
glm::dvec2 concentricDisk(double u, double v);

/// The grid the disk's N stratified samples use: the most square rows x cols with rows * cols = N
/// (rows <= cols).
glm::ivec2 stratifiedGrid(int samples);

/// Two unit vectors spanning the plane of a disk with normal `normal` (any length > 0): with the
/// normal they form a right-handed orthonormal basis. The same for every caller, so both ground
/// truths place a sample at the same point.
struct DiskFrame {
    glm::vec3 tangent, bitangent;
};
DiskFrame diskFrame(glm::vec3 normal);

} // namespace fl::geom
