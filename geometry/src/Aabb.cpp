#include <geometry/Aabb.h>

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

} // namespace fl::geom
