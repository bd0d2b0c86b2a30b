#include <renderer/soft/OccluderEdge.h>

#include <cmath>
#include <cstdint>

namespace fl {

namespace {
float silhouetteDepth(const DiskLight& l, glm::vec3 p) {
    return (p.x - l.center.x) * l.normal.x + (p.y - l.center.y) * l.normal.y +
           (p.z - l.center.z) * l.normal.z;
}
} // namespace

bool acrossSilhouette(const DiskLight& light, glm::vec4 self, glm::vec4 n, float threshold) {
    const float deeper = silhouetteDepth(light, glm::vec3(n)) - silhouetteDepth(light, self);
    const float ax = (n.x - self.x) - deeper * light.normal.x;
    const float ay = (n.y - self.y) - deeper * light.normal.y;
    const float az = (n.z - self.z) - deeper * light.normal.z;
    const float lateral2 = ax * ax + ay * ay + az * az;
    const float allowed = threshold + kSilhouetteSlope * std::sqrt(lateral2);
    return n.w == 0.0f || deeper > allowed;
}

std::uint32_t occluderEdgeCode(const ReceiverGrid& r, const DiskLight& light, int x, int y,
                               float threshold) {
    const glm::vec4 self = r.at(x, y);
    std::uint32_t code = 0;
    if (self.w == 0.0f) return code;
    // Out-of-grid neighbours read as the texel itself, as the shader's clamped fetch does.
    const auto at = [&](int qx, int qy) {
        return (qx < 0 || qy < 0 || qx >= r.width || qy >= r.height) ? self : r.at(qx, qy);
    };
    for (int axis = 0; axis < 2; ++axis) {
        const int ax = axis == 0 ? 1 : 0, ay = axis == 0 ? 0 : 1;
        const bool inLo = x - ax >= 0 && y - ay >= 0;
        const bool inHi = x + ax < r.width && y + ay < r.height;
        const bool edgeLo = inLo && acrossSilhouette(light, self, at(x - ax, y - ay), threshold);
        const bool edgeHi = inHi && acrossSilhouette(light, self, at(x + ax, y + ay), threshold);
        if (edgeHi && !edgeLo && inLo) code |= 1u << (2 * axis);
        if (edgeLo && !edgeHi && inHi) code |= 2u << (2 * axis);
    }
    return code;
}

glm::vec3 occluderEdgeApply(const ReceiverGrid& r, int x, int y, std::uint32_t code) {
    const glm::vec4 self = r.at(x, y);
    glm::vec3 o(self);
    for (int axis = 0; axis < 2; ++axis) {
        const std::uint32_t c = (code >> (2 * axis)) & 3u;
        if (c == 0) continue;
        const int s = c == 1 ? -1 : 1;
        const glm::vec4 n = axis == 0 ? r.at(x + s, y) : r.at(x, y + s);
        o = {o.x + 0.5f * (self.x - n.x), o.y + 0.5f * (self.y - n.y), o.z + 0.5f * (self.z - n.z)};
    }
    return o;
}

glm::vec3 occluderEdgePoint(const ReceiverGrid& r, const DiskLight& light, int x, int y,
                            float threshold) {
    return occluderEdgeApply(r, x, y, occluderEdgeCode(r, light, x, y, threshold));
}

} // namespace fl
