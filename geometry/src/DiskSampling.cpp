#include <geometry/DiskSampling.h>

#include <glm/geometric.hpp>

#include <cmath>

namespace fl::geom {

glm::dvec2 concentricDisk(double u, double v) {
    constexpr double kQuarterPi = 0.78539816339744830962;
    if (u == 0.0 && v == 0.0) return {0.0, 0.0};
    double r = 0.0, phi = 0.0;
    if (std::abs(u) > std::abs(v)) {
        r = u;
        phi = kQuarterPi * (v / u);
    } else {
        r = v;
        phi = 2.0 * kQuarterPi - kQuarterPi * (u / v);
    }
    return {r * std::cos(phi), r * std::sin(phi)};
}

glm::ivec2 stratifiedGrid(int samples) {
    int rows = 1;
    for (int d = 1; d * d <= samples; ++d)
        if (samples % d == 0) rows = d;
    return {samples / rows, rows};
}

DiskFrame diskFrame(glm::vec3 normal) {
    const glm::vec3 n = glm::normalize(normal);
    const glm::vec3 helper = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    const glm::vec3 t = glm::normalize(glm::cross(n, helper));
    return {t, glm::cross(n, t)};
}

} // namespace fl::geom
