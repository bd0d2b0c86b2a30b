#include <renderer/soft/OccluderEdge.h>

#include <cmath>

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

glm::vec3 occluderEdgePoint(const ReceiverGrid& r, const DiskLight& light, int x, int y,
                            float threshold) {
    const glm::vec4 self = r.at(x, y);
    glm::vec3 o(self);
    if (self.w == 0.0f) return o;
    const auto step = [&](bool inLo, bool inHi, glm::vec4 lo, glm::vec4 hi) {
        const bool edgeLo = inLo && acrossSilhouette(light, self, lo, threshold);
        const bool edgeHi = inHi && acrossSilhouette(light, self, hi, threshold);
        if (edgeHi && !edgeLo && inLo)
            o = {o.x + 0.5f * (self.x - lo.x), o.y + 0.5f * (self.y - lo.y),
                 o.z + 0.5f * (self.z - lo.z)};
        if (edgeLo && !edgeHi && inHi)
            o = {o.x + 0.5f * (self.x - hi.x), o.y + 0.5f * (self.y - hi.y),
                 o.z + 0.5f * (self.z - hi.z)};
    };
    // Out-of-grid neighbours read as the texel itself, as the shader's clamped fetch does.
    const auto at = [&](int qx, int qy) {
        return (qx < 0 || qy < 0 || qx >= r.width || qy >= r.height) ? self : r.at(qx, qy);
    };
    step(x > 0, x + 1 < r.width, at(x - 1, y), at(x + 1, y));
    step(y > 0, y + 1 < r.height, at(x, y - 1), at(x, y + 1));
    return o;
}

} // namespace fl
