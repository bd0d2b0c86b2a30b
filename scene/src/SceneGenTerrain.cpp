// The generated scene's ground: gentle hills, tessellated to an exact triangle count.

#include "SceneGenObjects.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace fl::gen {

namespace {

using GridPlan = Terrain::GridPlan;

GridPlan planGrid(std::size_t triangles) {
    // Try column counts near a square grid, alternating above and below: a count fails only
    // when T = 1 (mod 2 nx), and T - 1 cannot be a multiple of 2 nx for many nx in a row.
    const auto square = static_cast<std::size_t>(std::sqrt(static_cast<double>(triangles) / 2.0));
    for (std::size_t step = 0; step < 2 * square + 2; ++step) {
        const std::size_t offset = (step + 1) / 2;
        if (step % 2 == 0 && offset > square) continue;
        const std::size_t nx = step % 2 == 1 ? square + offset : square - offset;
        if (nx < 2) continue;
        const std::size_t rows = (triangles - 2) / (2 * nx);  // nz - 1
        const std::size_t strips = triangles - 2 * nx * rows; // m0 + m1, >= 2
        if (rows < 1 || strips > 2 * nx) continue;
        GridPlan plan;
        plan.nx = static_cast<int>(nx);
        plan.nz = static_cast<int>(rows + 1);
        plan.m0 = static_cast<int>(strips / 2);
        plan.m1 = static_cast<int>(strips - strips / 2);
        return plan;
    }
    throw std::logic_error("terrain: no grid for " + std::to_string(triangles) + " triangles");
}

/// A vertex of a band: index into the lower or the upper polyline.
struct BandVertex {
    bool upper;
    int i;
};

/// Triangulates the band between a lower grid line (smaller z) with `lowerSegs` segments and
/// an upper one with `upperSegs`, both spanning the same x range, into lowerSegs + upperSegs
/// upward-facing (counter-clockwise from +Y) triangles by merging the two in x order.
template <typename Emit>
void stitch(int lowerSegs, int upperSegs, Emit emit) {
    int i = 0;
    int j = 0;
    while (i < lowerSegs || j < upperSegs) {
        // Compare the next x on each line, i+1 / lowerSegs against j+1 / upperSegs, exactly.
        const bool advanceLower =
            j == upperSegs || (i < lowerSegs && static_cast<long long>(i + 1) * upperSegs <=
                                                    static_cast<long long>(j + 1) * lowerSegs);
        if (advanceLower) {
            emit(BandVertex{false, i}, BandVertex{true, j}, BandVertex{false, i + 1});
            ++i;
        } else {
            emit(BandVertex{false, i}, BandVertex{true, j}, BandVertex{true, j + 1});
            ++j;
        }
    }
}

} // namespace

Terrain::Terrain(Rng& rng) {
    // Long, low waves first: the largest slope stays near 0.3, hills for curved receivers
    // without making objects lean.
    static constexpr float kWavelength[kWaves] = {17.0f, 11.0f, 7.0f, 4.5f};
    static constexpr float kAmplitude[kWaves] = {0.40f, 0.22f, 0.10f, 0.04f};
    constexpr float kTwoPi = 2.0f * std::numbers::pi_v<float>;
    for (int i = 0; i < kWaves; ++i) {
        const float angle = rng.uniform(0.0f, kTwoPi);
        dir_[static_cast<std::size_t>(i)] = glm::vec2(std::cos(angle), std::sin(angle));
        k_[static_cast<std::size_t>(i)] = kTwoPi / kWavelength[i];
        amp_[static_cast<std::size_t>(i)] = kAmplitude[i];
        phase_[static_cast<std::size_t>(i)] = rng.uniform(0.0f, kTwoPi);
    }
}

float Terrain::height(float x, float z) const {
    float h = 0.0f;
    for (std::size_t i = 0; i < kWaves; ++i)
        h += amp_[i] * std::sin(k_[i] * (dir_[i].x * x + dir_[i].y * z) + phase_[i]);
    return h;
}

glm::vec3 Terrain::normal(float x, float z) const {
    glm::vec2 grad(0.0f);
    for (std::size_t i = 0; i < kWaves; ++i)
        grad += amp_[i] * k_[i] * std::cos(k_[i] * (dir_[i].x * x + dir_[i].y * z) + phase_[i]) *
                dir_[i];
    const glm::vec3 n(-grad.x, 1.0f, -grad.y);
    return n / std::sqrt(glm::dot(n, n));
}

void Terrain::tessellate(std::size_t triangles) {
    if (triangles < kMinTriangles) throw std::logic_error("terrain: budget below minimum");
    plan_ = planGrid(triangles);
    triangles_ = triangles;
}

int Terrain::lineSegments(int line) const {
    return line == 0 ? plan_.m0 : line == plan_.nz ? plan_.m1 : plan_.nx;
}

glm::vec3 Terrain::linePoint(int line, int i) const {
    const float half = 0.5f * kSize;
    const float z = -half + kSize * static_cast<float>(line) / static_cast<float>(plan_.nz);
    const float x = -half + kSize * static_cast<float>(i) / static_cast<float>(lineSegments(line));
    return {x, height(x, z), z};
}

float Terrain::surfaceHeight(float x, float z) const {
    if (plan_.nx == 0) return height(x, z);
    const float half = 0.5f * kSize;
    const float fz = (std::clamp(z, -half, half) + half) / kSize * static_cast<float>(plan_.nz);
    const int row = std::clamp(static_cast<int>(fz), 0, plan_.nz - 1);
    float result = height(x, z);
    bool found = false;
    stitch(lineSegments(row), lineSegments(row + 1), [&](BandVertex a, BandVertex b, BandVertex c) {
        if (found) return;
        const glm::vec3 p0 = linePoint(row + (a.upper ? 1 : 0), a.i);
        const glm::vec3 p1 = linePoint(row + (b.upper ? 1 : 0), b.i);
        const glm::vec3 p2 = linePoint(row + (c.upper ? 1 : 0), c.i);
        const float det = (p1.x - p0.x) * (p2.z - p0.z) - (p2.x - p0.x) * (p1.z - p0.z);
        const float u = ((x - p0.x) * (p2.z - p0.z) - (p2.x - p0.x) * (z - p0.z)) / det;
        const float v = ((p1.x - p0.x) * (z - p0.z) - (x - p0.x) * (p1.z - p0.z)) / det;
        constexpr float kEps = 1e-5f;
        if (u >= -kEps && v >= -kEps && u + v <= 1.0f + kEps) {
            result = p0.y + u * (p1.y - p0.y) + v * (p2.y - p0.y);
            found = true;
        }
    });
    return result;
}

float Terrain::groundUnder(glm::vec2 centre, float radius) const {
    static constexpr float kDiag = 0.70710678f;
    static constexpr glm::vec2 kAround[8] = {{1, 0},  {kDiag, kDiag},   {0, 1},  {-kDiag, kDiag},
                                             {-1, 0}, {-kDiag, -kDiag}, {0, -1}, {kDiag, -kDiag}};
    float lowest = surfaceHeight(centre.x, centre.y);
    for (const glm::vec2& d : kAround) {
        const glm::vec2 p = centre + radius * d;
        lowest = std::min(lowest, surfaceHeight(p.x, p.y));
    }
    return lowest;
}

void Terrain::build(MeshBuilder& b) const {
    if (plan_.nx == 0) throw std::logic_error("terrain: build before tessellate");
    if (b.countOnly()) {
        b.countTriangles(triangles_);
        return;
    }
    // Vertex ids of grid lines `line` and `line + 1`, reused as the band moves up.
    auto emitLine = [&](int line) {
        std::vector<std::uint32_t> ids;
        for (int i = 0; i <= lineSegments(line); ++i) {
            const glm::vec3 p = linePoint(line, i);
            ids.push_back(b.vertex(p, normal(p.x, p.z)));
        }
        return ids;
    };
    std::vector<std::uint32_t> lower = emitLine(0);
    for (int row = 0; row < plan_.nz; ++row) {
        std::vector<std::uint32_t> upper = emitLine(row + 1);
        auto id = [&](BandVertex v) {
            return (v.upper ? upper : lower)[static_cast<std::size_t>(v.i)];
        };
        stitch(lineSegments(row), lineSegments(row + 1),
               [&](BandVertex v0, BandVertex v1, BandVertex v2) {
                   b.triangle(id(v0), id(v1), id(v2));
               });
        lower = std::move(upper);
    }
}

} // namespace fl::gen
