#pragma once
// Small triangle scenes for the ray-traced truth's tests (raytrace/ShadowRays.h): a low-poly
// smooth-shaded sphere, a flat ground, and points spread over their triangles.

#include <raytrace/ShadowRays.h>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

namespace fl::test {

/// A UV sphere, `rings` x `segments`, shared vertices with the sphere's normals: the low-poly
/// smooth-shaded object whose terminator the offset is for. The poles' zero-area triangles are
/// left out.
inline rt::Triangles lowPolySphere(int rings, int segments, glm::vec3 centre = glm::vec3(0.0f),
                                   float radius = 1.0f) {
    rt::Triangles t;
    const float pi = glm::pi<float>();
    for (int r = 0; r <= rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const float theta = pi * static_cast<float>(r) / static_cast<float>(rings);
            const float phi = 2.0f * pi * static_cast<float>(s) / static_cast<float>(segments);
            const glm::vec3 p(std::sin(theta) * std::cos(phi), std::cos(theta),
                              std::sin(theta) * std::sin(phi));
            t.vertices.push_back(centre + radius * p);
            t.normals.push_back(glm::normalize(p));
        }
    const auto index = [&](int r, int s) {
        return static_cast<std::uint32_t>(r * segments + (s % segments));
    };
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            if (r > 0)
                t.indices.insert(t.indices.end(), {index(r, s), index(r, s + 1), index(r + 1, s)});
            if (r + 1 < rings)
                t.indices.insert(t.indices.end(),
                                 {index(r, s + 1), index(r + 1, s + 1), index(r + 1, s)});
        }
    return t;
}

/// Appends `more` to `to` (both with normals, or both without).
inline void append(rt::Triangles& to, const rt::Triangles& more) {
    const auto base = static_cast<std::uint32_t>(to.vertices.size());
    to.vertices.insert(to.vertices.end(), more.vertices.begin(), more.vertices.end());
    to.normals.insert(to.normals.end(), more.normals.begin(), more.normals.end());
    for (std::uint32_t i : more.indices) to.indices.push_back(base + i);
}

/// A flat square at height y over [lo, hi] in x and z, facing up, with its normals.
inline rt::Triangles flatGround(float y, glm::vec2 lo, glm::vec2 hi) {
    rt::Triangles t;
    t.vertices = {{lo.x, y, lo.y}, {hi.x, y, lo.y}, {hi.x, y, hi.y}, {lo.x, y, hi.y}};
    t.normals.assign(4, glm::vec3(0.0f, 1.0f, 0.0f));
    t.indices = {0, 2, 1, 0, 3, 2};
    return t;
}

/// Points on every triangle of `t` at barycentrics i/n, j/n (corners and edges included), each
/// with its triangle's plane normal turned to the side `outside` says (the normal n with
/// outside(p, n) true; e.g. away from a sphere's centre).
template <class Outside>
std::vector<rt::Receiver> pointsOn(const rt::Triangles& t, int n, Outside outside) {
    std::vector<rt::Receiver> out;
    for (std::size_t i = 0; i + 2 < t.indices.size(); i += 3) {
        const glm::vec3 a = t.vertices[t.indices[i]], b = t.vertices[t.indices[i + 1]],
                        c = t.vertices[t.indices[i + 2]];
        const glm::vec3 normal = glm::normalize(glm::cross(b - a, c - a));
        for (int u = 0; u <= n; ++u)
            for (int v = 0; u + v <= n; ++v) {
                const float fu = static_cast<float>(u) / static_cast<float>(n);
                const float fv = static_cast<float>(v) / static_cast<float>(n);
                const glm::vec3 p = (1.0f - fu - fv) * a + fu * b + fv * c;
                out.push_back({p, outside(p, normal) ? normal : -normal, true});
            }
    }
    return out;
}

} // namespace fl::test
