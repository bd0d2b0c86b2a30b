#include <base/Aabb.h>

namespace fl::geom {

Aabb Aabb::transformed(const glm::mat4& m) const {
    Aabb out;
    if (!valid()) return out;
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner{(i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y,
                               (i & 4) ? max.z : min.z};
        const glm::vec4 p = m * glm::vec4(corner, 1.0f);
        out.extend(glm::vec3(p) / p.w);
    }
    return out;
}

Aabb Aabb::around(std::span<const glm::vec3> points, const glm::mat4& m) {
    const bool affine = m[0][3] == 0.0f && m[1][3] == 0.0f && m[2][3] == 0.0f && m[3][3] == 1.0f;
    // No turn (a scale and a shift per axis): each moved coordinate follows one coordinate
    // monotonically, and so does its float rounding, so the moved box's corners are the moved
    // points' extremes, bit for bit. Only the box is moved: the usual node costs nothing more.
    const bool turns = m[0][1] != 0.0f || m[0][2] != 0.0f || m[1][0] != 0.0f || m[1][2] != 0.0f ||
                       m[2][0] != 0.0f || m[2][1] != 0.0f;
    if (affine && !turns) {
        Aabb local;
        for (const glm::vec3& p : points) local.extend(p);
        return local.transformed(m);
    }
    // Each point as glm's m * vec4(p, 1) computes it, in the same order: (c0 x + c1 y) +
    // (c2 z + c3), spelt out so the loop stays in registers.
    Aabb out;
    for (const glm::vec3& p : points) {
        glm::vec3 q;
        for (int a = 0; a < 3; ++a)
            q[a] = (m[0][a] * p.x + m[1][a] * p.y) + (m[2][a] * p.z + m[3][a] * 1.0f);
        out.extend(q);
    }
    return out;
}

} // namespace fl::geom
