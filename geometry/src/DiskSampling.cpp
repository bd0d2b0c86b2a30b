#include <geometry/DiskSampling.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

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

DiskPattern diskPatternNamed(std::string_view name) {
    for (const DiskPatternName& p : kDiskPatterns)
        if (p.name == name) return p.pattern;
    throw std::invalid_argument("unknown disk pattern \"" + std::string(name) + "\"");
}

namespace {
// A fixed hash of the cell index to [0, 1) (splitmix64's finaliser): the jitter is the same on
// every run and machine.
double hashUnit(std::uint64_t x) {
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    x ^= x >> 31;
    return static_cast<double>(x >> 11) * 0x1.0p-53;
}
} // namespace

std::vector<glm::dvec2> diskPattern(DiskPattern pattern, int samples) {
    if (samples < 1)
        throw std::invalid_argument("disk samples must be >= 1, got " + std::to_string(samples));
    if (samples == 1) return {glm::dvec2(0.0)};
    std::vector<glm::dvec2> out;
    out.reserve(static_cast<std::size_t>(samples));
    if (pattern == DiskPattern::Spiral) {
        const double golden = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
        for (int k = 0; k < samples; ++k) {
            const double r = std::sqrt((k + 0.5) / samples), a = golden * k;
            out.emplace_back(r * std::cos(a), r * std::sin(a));
        }
        return out;
    }
    const glm::ivec2 grid = stratifiedGrid(samples);
    for (int j = 0; j < grid.y; ++j)
        for (int i = 0; i < grid.x; ++i) {
            const std::uint64_t cell = static_cast<std::uint64_t>(j * grid.x + i);
            const double a = pattern == DiskPattern::Jittered ? hashUnit(2 * cell) : 0.5;
            const double b = pattern == DiskPattern::Jittered ? hashUnit(2 * cell + 1) : 0.5;
            out.push_back(
                concentricDisk(2.0 * (i + a) / grid.x - 1.0, 2.0 * (j + b) / grid.y - 1.0));
        }
    return out;
}

DiskFrame diskFrame(glm::vec3 normal) {
    const glm::vec3 n = glm::normalize(normal);
    const glm::vec3 helper = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    const glm::vec3 t = glm::normalize(glm::cross(n, helper));
    return {t, glm::cross(n, t)};
}

} // namespace fl::geom
