#pragma once
// Axis-aligned bounding boxes: scene bounds, light-frustum fitting and camera framing start here.

#include <glm/glm.hpp>

#include <limits>
#include <span>

namespace fl::geom {

struct Aabb {
    glm::vec3 min{std::numeric_limits<float>::max()};
    glm::vec3 max{std::numeric_limits<float>::lowest()};

    /// True once at least one point has been added.
    [[nodiscard]] bool valid() const { return min.x <= max.x && min.y <= max.y && min.z <= max.z; }
    /// Grows the box to contain p.
    void extend(const glm::vec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    /// Grows the box to contain another box.
    void extend(const Aabb& o) {
        if (o.valid()) {
            extend(o.min);
            extend(o.max);
        }
    }
    [[nodiscard]] glm::vec3 center() const { return 0.5f * (min + max); }
    [[nodiscard]] glm::vec3 extent() const { return max - min; }
    /// Radius of the sphere around center() that contains the box.
    [[nodiscard]] float radius() const { return 0.5f * glm::length(max - min); }
    /// The box around the 8 transformed corners of this box: it holds every point of the box
    /// moved, but is loose around what the box held once `m` rotates (see around()).
    [[nodiscard]] Aabb transformed(const glm::mat4& m) const;
    /// The tight box around `points`, each moved by the affine `m` exactly as the vertex stage
    /// and scene/Pose.h place a vertex (vec3(m * vec4(p, 1)), no divide by w): its faces touch
    /// moved points, whatever the rotation. Invalid for no points.
    [[nodiscard]] static Aabb around(std::span<const glm::vec3> points, const glm::mat4& m);
};

} // namespace fl::geom
