#include "SceneGenShapes.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace fl::gen {

namespace {

std::uint64_t splitmix64(std::uint64_t& x) {
    std::uint64_t z = (x += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

constexpr float kTwoPi = 2.0f * std::numbers::pi_v<float>;
constexpr float kHalfPi = 0.5f * std::numbers::pi_v<float>;

/// cos/sin of the `segments` equally spaced angles around the axis; index `segments` wraps.
struct Circle {
    std::vector<float> c, s;
    explicit Circle(int segments) : c(static_cast<std::size_t>(segments)), s(c.size()) {
        for (int j = 0; j < segments; ++j) {
            const float a = kTwoPi * static_cast<float>(j) / static_cast<float>(segments);
            c[static_cast<std::size_t>(j)] = std::cos(a);
            s[static_cast<std::size_t>(j)] = std::sin(a);
        }
    }
};

glm::vec2 safeNormalize(glm::vec2 v) {
    const float len = std::sqrt(glm::dot(v, v));
    return len > 0.0f ? v / len : glm::vec2(0.0f);
}

glm::vec3 safeNormalize(glm::vec3 v) {
    const float len = std::sqrt(glm::dot(v, v));
    return len > 0.0f ? v / len : glm::vec3(0.0f, 1.0f, 0.0f);
}

/// Per profile point, the 2D outward normal: the mean of the normals of the bands it belongs
/// to. A band's normal is its tangent turned clockwise, which points away from the axis when
/// the profile climbs, so bottom-to-top profiles face outward. Poles get an axial normal.
std::vector<glm::vec2> profileNormals(std::span<const ProfilePoint> profile) {
    const std::size_t n = profile.size();
    std::vector<glm::vec2> normals(n, glm::vec2(0.0f));
    for (std::size_t k = 1; k < n; ++k) {
        if (profile[k].hard) continue;
        const glm::vec2 t(profile[k].r - profile[k - 1].r, profile[k].y - profile[k - 1].y);
        const glm::vec2 bandNormal = safeNormalize(glm::vec2(t.y, -t.x));
        normals[k - 1] += bandNormal;
        normals[k] += bandNormal;
    }
    for (std::size_t k = 0; k < n; ++k) {
        if (profile[k].r == 0.0f) {
            normals[k] = glm::vec2(0.0f, normals[k].y < 0.0f ? -1.0f : 1.0f);
        } else {
            normals[k] = safeNormalize(normals[k]);
        }
    }
    return normals;
}

/// Emits the vertices and triangles of a surface of revolution; `place` maps a local position
/// and normal to the stored ones.
template <typename Place>
void revolve(MeshBuilder& b, std::span<const ProfilePoint> profile, int segments, Place place) {
    if (segments < 3) throw std::logic_error("revolve: fewer than 3 segments");
    const std::vector<glm::vec2> normals = profileNormals(profile);
    const Circle circle(segments);
    const auto segs = static_cast<std::uint32_t>(segments);

    std::vector<std::uint32_t> first(profile.size());
    for (std::size_t k = 0; k < profile.size(); ++k) {
        first[k] = b.vertexCount();
        const ProfilePoint& p = profile[k];
        const glm::vec2 n = normals[k];
        if (p.r == 0.0f) {
            const auto [pos, nrm] = place(glm::vec3(0.0f, p.y, 0.0f), glm::vec3(0.0f, n.y, 0.0f));
            b.vertex(pos, nrm);
            continue;
        }
        for (std::size_t j = 0; j < segs; ++j) {
            // Angle runs clockwise seen from +Y so that (a, b, c) below winds outward.
            const glm::vec3 local(p.r * circle.c[j], p.y, -p.r * circle.s[j]);
            const glm::vec3 localN(n.x * circle.c[j], n.y, -n.x * circle.s[j]);
            const auto [pos, nrm] = place(local, localN);
            b.vertex(pos, nrm);
        }
    }
    for (std::size_t k = 1; k < profile.size(); ++k) {
        if (profile[k].hard) continue;
        const bool pole0 = profile[k - 1].r == 0.0f;
        const bool pole1 = profile[k].r == 0.0f;
        if (pole0 && pole1) continue;
        for (std::uint32_t j = 0; j < segs; ++j) {
            const std::uint32_t j1 = (j + 1) % segs;
            const std::uint32_t a = first[k - 1] + (pole0 ? 0 : j);
            const std::uint32_t bb = first[k - 1] + (pole0 ? 0 : j1);
            const std::uint32_t c = first[k] + (pole1 ? 0 : j1);
            const std::uint32_t d = first[k] + (pole1 ? 0 : j);
            if (!pole0) b.triangle(a, bb, c);
            if (!pole1) b.triangle(a, c, d);
        }
    }
}

glm::mat3 normalMatrix(const glm::mat4& xf) {
    return glm::transpose(glm::inverse(glm::mat3(xf)));
}

std::vector<ProfilePoint> sphereProfile(int stacks) {
    std::vector<ProfilePoint> profile;
    profile.push_back({0.0f, -1.0f});
    for (int i = 1; i < stacks; ++i) {
        const float a = -kHalfPi + std::numbers::pi_v<float> * static_cast<float>(i) /
                                       static_cast<float>(stacks);
        profile.push_back({std::cos(a), std::sin(a)});
    }
    profile.push_back({0.0f, 1.0f});
    return profile;
}

} // namespace

Rng::Rng(std::uint64_t seed) {
    std::uint64_t sm = seed;
    const std::uint64_t initState = splitmix64(sm);
    const std::uint64_t initSeq = splitmix64(sm);
    inc_ = (initSeq << 1u) | 1u;
    next();
    state_ += initState;
    next();
}

std::uint32_t Rng::next() {
    const std::uint64_t old = state_;
    state_ = old * 6364136223846793005ull + inc_;
    const auto xorShifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
    const auto rot = static_cast<std::uint32_t>(old >> 59u);
    return (xorShifted >> rot) | (xorShifted << ((32u - rot) & 31u));
}

float Rng::unit() {
    return static_cast<float>(next() >> 8) * (1.0f / 16777216.0f);
}

Rng Rng::fork() {
    const std::uint64_t hi = next();
    return Rng((hi << 32u) | next());
}

std::uint32_t MeshBuilder::vertex(const glm::vec3& p, const glm::vec3& n) {
    positions_.push_back(p);
    normals_.push_back(n);
    return static_cast<std::uint32_t>(positions_.size() - 1);
}

void MeshBuilder::triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    indices_.insert(indices_.end(), {a, b, c});
    ++triangles_;
}

void MeshBuilder::smoothNormals(std::uint32_t firstVertex, std::size_t firstIndex) {
    for (std::size_t v = firstVertex; v < normals_.size(); ++v) normals_[v] = glm::vec3(0.0f);
    for (std::size_t i = firstIndex; i + 2 < indices_.size(); i += 3) {
        const glm::vec3& p0 = positions_[indices_[i]];
        const glm::vec3 faceN =
            glm::cross(positions_[indices_[i + 1]] - p0, positions_[indices_[i + 2]] - p0);
        for (std::size_t k = 0; k < 3; ++k) normals_[indices_[i + k]] += faceN;
    }
    for (std::size_t v = firstVertex; v < normals_.size(); ++v)
        normals_[v] = safeNormalize(normals_[v]);
}

void MeshBuilder::moveInto(Mesh& mesh) {
    mesh.positions = std::move(positions_);
    mesh.normals = std::move(normals_);
    mesh.indices = std::move(indices_);
    mesh.texcoords.clear();
}

std::size_t latheTriangles(std::span<const ProfilePoint> profile, int segments) {
    std::size_t n = 0;
    const auto segs = static_cast<std::size_t>(segments);
    for (std::size_t k = 1; k < profile.size(); ++k) {
        if (profile[k].hard) continue;
        const bool pole0 = profile[k - 1].r == 0.0f;
        const bool pole1 = profile[k].r == 0.0f;
        if (pole0 && pole1) continue;
        n += (pole0 || pole1) ? segs : 2 * segs;
    }
    return n;
}

void addLathe(MeshBuilder& b, const glm::mat4& xf, std::span<const ProfilePoint> profile,
              int segments) {
    if (b.countOnly()) {
        b.countTriangles(latheTriangles(profile, segments));
        return;
    }
    const glm::mat3 nm = normalMatrix(xf);
    revolve(b, profile, segments, [&](const glm::vec3& p, const glm::vec3& n) {
        return std::pair{glm::vec3(xf * glm::vec4(p, 1.0f)), safeNormalize(nm * n)};
    });
}

void addCapsule(MeshBuilder& b, const glm::mat4& xf, float r, float length, int segments,
                int capRings) {
    std::vector<ProfilePoint> profile;
    profile.push_back({0.0f, 0.0f});
    if (capRings <= 0) {
        profile.push_back({r, 0.5f * length});
    } else {
        if (length <= 2.0f * r) throw std::logic_error("addCapsule: length must exceed 2r");
        for (int i = 1; i <= capRings; ++i) { // bottom hemisphere, pole excluded, equator last
            const float a =
                -kHalfPi + kHalfPi * static_cast<float>(i) / static_cast<float>(capRings);
            profile.push_back({r * std::cos(a), r + r * std::sin(a)});
        }
        for (int i = 0; i < capRings; ++i) { // top hemisphere, equator first, pole excluded
            const float a = kHalfPi * static_cast<float>(i) / static_cast<float>(capRings);
            profile.push_back({r * std::cos(a), length - r + r * std::sin(a)});
        }
    }
    profile.push_back({0.0f, length});
    addLathe(b, xf, profile, segments);
}

void addSphere(MeshBuilder& b, const glm::mat4& xf, int segments, int stacks) {
    if (b.countOnly()) {
        b.countTriangles(2 * static_cast<std::size_t>(segments) *
                         static_cast<std::size_t>(stacks - 1));
        return;
    }
    addLathe(b, xf, sphereProfile(stacks), segments);
}

float Bumps::operator()(const glm::vec3& unitDir) const {
    float sum = 0.0f;
    for (int i = 0; i < kWaves; ++i)
        sum += amp[i] * std::sin(freq[i] * glm::dot(dir[i], unitDir) + phase[i]);
    return sum;
}

Bumps Bumps::random(Rng& rng, float roughness) {
    Bumps bumps;
    float total = 0.0f;
    for (int i = 0; i < kWaves; ++i) {
        bumps.dir[i] = randomDirection(rng);
        bumps.freq[i] = rng.uniform(2.0f, 5.0f);
        bumps.phase[i] = rng.uniform(0.0f, kTwoPi);
        bumps.amp[i] = rng.uniform(0.5f, 1.0f) / static_cast<float>(i + 1);
        total += bumps.amp[i];
    }
    for (float& a : bumps.amp) a *= roughness / total;
    return bumps;
}

void addBlob(MeshBuilder& b, const glm::mat4& xf, int segments, int stacks, const Bumps& bumps) {
    if (b.countOnly()) {
        addSphere(b, xf, segments, stacks);
        return;
    }
    const std::uint32_t firstVertex = b.vertexCount();
    const std::size_t firstIndex = b.indexCount();
    const std::vector<ProfilePoint> profile = sphereProfile(stacks);
    revolve(b, profile, segments, [&](const glm::vec3& p, const glm::vec3& n) {
        const glm::vec3 displaced = p * (1.0f + bumps(p));
        return std::pair{glm::vec3(xf * glm::vec4(displaced, 1.0f)), n};
    });
    b.smoothNormals(firstVertex, firstIndex);
}

void addBox(MeshBuilder& b, const glm::mat4& xf, const glm::vec3& halfExtent) {
    if (b.countOnly()) {
        b.countTriangles(12);
        return;
    }
    // (normal, u, v) with u x v = normal, so the corners below run counter-clockwise.
    static constexpr glm::vec3 kFaces[6][3] = {
        {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
        {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}}, {{0, 0, -1}, {0, 1, 0}, {1, 0, 0}},
    };
    const glm::mat3 nm = normalMatrix(xf);
    for (const auto& face : kFaces) {
        const glm::vec3 c = face[0] * halfExtent;
        const glm::vec3 u = face[1] * halfExtent;
        const glm::vec3 v = face[2] * halfExtent;
        const glm::vec3 n = safeNormalize(nm * face[0]);
        const glm::vec3 corners[4] = {c - u - v, c + u - v, c + u + v, c - u + v};
        const std::uint32_t first = b.vertexCount();
        for (const glm::vec3& p : corners) b.vertex(glm::vec3(xf * glm::vec4(p, 1.0f)), n);
        b.triangle(first, first + 1, first + 2);
        b.triangle(first, first + 2, first + 3);
    }
}

glm::mat4 frameAlong(const glm::vec3& origin, const glm::vec3& axis) {
    const glm::vec3 helper = std::abs(axis.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 x = safeNormalize(glm::cross(axis, helper));
    const glm::vec3 z = glm::cross(x, axis);
    return glm::mat4(glm::vec4(x, 0.0f), glm::vec4(axis, 0.0f), glm::vec4(z, 0.0f),
                     glm::vec4(origin, 1.0f));
}

glm::mat4 placeYaw(const glm::vec3& origin, float yaw, const glm::vec3& scale) {
    const float c = std::cos(yaw);
    const float s = std::sin(yaw);
    return glm::mat4(glm::vec4(c * scale.x, 0.0f, -s * scale.x, 0.0f),
                     glm::vec4(0.0f, scale.y, 0.0f, 0.0f),
                     glm::vec4(s * scale.z, 0.0f, c * scale.z, 0.0f), glm::vec4(origin, 1.0f));
}

glm::vec3 randomDirection(Rng& rng) {
    for (;;) {
        const glm::vec3 v(rng.uniform(-1.0f, 1.0f), rng.uniform(-1.0f, 1.0f),
                          rng.uniform(-1.0f, 1.0f));
        const float len2 = glm::dot(v, v);
        if (len2 > 1e-4f && len2 <= 1.0f) return v / std::sqrt(len2);
    }
}

} // namespace fl::gen
