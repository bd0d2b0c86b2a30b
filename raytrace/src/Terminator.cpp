#include <raytrace/Terminator.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace fl::rt {

namespace {

// 1 - cos of the largest angle between a vertex normal and the plane's normal that still counts
// as flat: 1.4e-3 rad, far above float rounding in a normal (1e-7) and far below any curvature a
// mesh means to show.
constexpr float kFlat = 1e-6f;

} // namespace

std::optional<SmoothPoint> terminatorOffset(glm::vec3 p, const std::array<glm::vec3, 3>& corner,
                                            const std::array<glm::vec3, 3>& normals, float u,
                                            float v, glm::vec3 side) {
    const glm::vec3 cross = glm::cross(corner[1] - corner[0], corner[2] - corner[0]);
    const float area = glm::length(cross);
    if (!(area > 0.0f) || !std::isfinite(area)) return std::nullopt;
    // Only unit normals describe a surface (a node scaled to zero turns them into NaN).
    for (const glm::vec3& n : normals)
        if (!(std::abs(glm::length(n) - 1.0f) < 1e-3f)) return std::nullopt;
    glm::vec3 plane = cross / area;
    if (glm::dot(plane, side) < 0.0f) plane = -plane;
    const std::array<float, 3> weight{1.0f - u - v, u, v};
    glm::vec3 smooth(0.0f);
    for (int i = 0; i < 3; ++i) smooth += weight[i] * normals[i];
    // The normals as seen from `side`: a back face seen through a double-sided material has its
    // smooth surface on that side too.
    const float flip = glm::dot(smooth, plane) < 0.0f ? -1.0f : 1.0f;
    bool flat = true;
    for (const glm::vec3& n : normals) flat = flat && flip * glm::dot(n, plane) >= 1.0f - kFlat;
    if (flat || !(glm::length(smooth) > 0.0f)) return std::nullopt;
    // Hanika's listing: the move towards each vertex's tangent plane, outward only, blended.
    glm::vec3 move(0.0f);
    for (int i = 0; i < 3; ++i) {
        const glm::vec3 n = flip * normals[i];
        move -= weight[i] * std::min(glm::dot(p - corner[i], n), 0.0f) * n;
    }
    if (glm::dot(move, plane) < 0.0f) move = glm::vec3(0.0f);
    return SmoothPoint{p + move, glm::normalize(flip * smooth)};
}

float offsetAmount(float shadingL, float planeL, float cutoff) {
    if (!(cutoff > 0.0f)) return 0.0f;
    const float amount =
        shadingL < cutoff ? 2.0f - (planeL + shadingL) / cutoff : 1.0f - planeL / cutoff;
    return std::clamp(amount, 0.0f, 1.0f);
}

} // namespace fl::rt
