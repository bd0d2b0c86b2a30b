// Smooth vertex normals that keep creases (MeshImport.h computeCreaseNormals): angle-weighted
// face normals summed over the faces around a position that lie within the crease angle of the
// corner's own face; corners whose sums differ get vertices of their own.

#include "MeshImport.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <unordered_map>

namespace fl::bench {

namespace {

struct PositionHash {
    std::size_t operator()(const std::array<std::uint32_t, 3>& p) const {
        return (std::size_t{p[0]} * 73856093u) ^ (std::size_t{p[1]} * 19349663u) ^
               (std::size_t{p[2]} * 83492791u);
    }
};

// One id per distinct position (exactly equal coordinates; -0 and +0 the same).
std::vector<std::uint32_t> weldPositions(const std::vector<glm::vec3>& positions) {
    std::unordered_map<std::array<std::uint32_t, 3>, std::uint32_t, PositionHash> idOf;
    std::vector<std::uint32_t> id(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
        const glm::vec3 p = positions[i] + glm::vec3(0.0f);
        const std::array<std::uint32_t, 3> key = {std::bit_cast<std::uint32_t>(p.x),
                                                  std::bit_cast<std::uint32_t>(p.y),
                                                  std::bit_cast<std::uint32_t>(p.z)};
        id[i] = idOf.try_emplace(key, static_cast<std::uint32_t>(idOf.size())).first->second;
    }
    return id;
}

// The triangle's angle at corner k, in radians.
float cornerAngle(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b) {
    const glm::vec3 u = glm::normalize(a - p), v = glm::normalize(b - p);
    return std::acos(std::clamp(glm::dot(u, v), -1.0f, 1.0f));
}

// Drops the triangles whose face normal is zero or not finite; returns their unit normals.
std::vector<glm::vec3> keepFacets(Mesh& mesh, std::size_t& dropped) {
    std::vector<glm::vec3> normals;
    std::vector<std::uint32_t> kept;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const glm::vec3 &a = mesh.positions[mesh.indices[t]],
                        &b = mesh.positions[mesh.indices[t + 1]],
                        &c = mesh.positions[mesh.indices[t + 2]];
        const glm::dvec3 n = glm::cross(glm::dvec3(b - a), glm::dvec3(c - a));
        const double len = glm::length(n);
        if (!(len > 0.0) || !std::isfinite(len) || a == b || b == c || a == c) {
            ++dropped;
            continue;
        }
        normals.emplace_back(n / len);
        kept.insert(kept.end(), {mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]});
    }
    mesh.indices = std::move(kept);
    return normals;
}

} // namespace

std::size_t computeCreaseNormals(Mesh& mesh, float creaseDegrees) {
    std::size_t dropped = 0;
    const std::vector<glm::vec3> faceN = keepFacets(mesh, dropped);
    const std::vector<std::uint32_t> weld = weldPositions(mesh.positions);
    const std::size_t corners = mesh.indices.size();
    // The corners around each welded position (CSR: start[id] .. start[id + 1]).
    std::vector<std::uint32_t> start(mesh.positions.size() + 1, 0), around(corners);
    for (std::uint32_t v : mesh.indices) ++start[weld[v] + 1];
    for (std::size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::size_t c = 0; c < corners; ++c)
        around[fill[weld[mesh.indices[c]]]++] = static_cast<std::uint32_t>(c);
    std::vector<float> angle(corners);
    for (std::size_t c = 0; c < corners; ++c) {
        const std::size_t t = c / 3 * 3;
        angle[c] = cornerAngle(mesh.positions[mesh.indices[c]],
                               mesh.positions[mesh.indices[t + (c + 1) % 3]],
                               mesh.positions[mesh.indices[t + (c + 2) % 3]]);
    }
    const float cosCrease = std::cos(glm::radians(creaseDegrees));
    // Each corner's normal, then one vertex per (position, normal, texcoord, colour).
    Mesh out = mesh;
    out.positions.clear();
    out.normals.clear();
    out.texcoords.clear();
    out.colors.clear();
    std::vector<std::vector<std::uint32_t>> made(mesh.positions.size()); // new ones per position
    for (std::size_t c = 0; c < corners; ++c) {
        const std::uint32_t v = mesh.indices[c], w = weld[v];
        const glm::vec3 own = faceN[c / 3];
        glm::vec3 sum(0.0f);
        for (std::uint32_t k = start[w]; k < start[w + 1]; ++k) {
            const std::uint32_t other = around[k];
            if (glm::dot(faceN[other / 3], own) >= cosCrease)
                sum += angle[other] * faceN[other / 3];
        }
        const float len = glm::length(sum);
        const glm::vec3 n = len > 0.0f && std::isfinite(len) ? sum / len : own;
        const auto same = std::find_if(made[w].begin(), made[w].end(), [&](std::uint32_t i) {
            return out.normals[i] == n &&
                   (mesh.texcoords.empty() || out.texcoords[i] == mesh.texcoords[v]) &&
                   (mesh.colors.empty() || out.colors[i] == mesh.colors[v]);
        });
        if (same != made[w].end()) {
            out.indices[c] = *same;
            continue;
        }
        out.indices[c] = static_cast<std::uint32_t>(out.positions.size());
        made[w].push_back(out.indices[c]);
        out.positions.push_back(mesh.positions[v]);
        out.normals.push_back(n);
        if (!mesh.texcoords.empty()) out.texcoords.push_back(mesh.texcoords[v]);
        if (!mesh.colors.empty()) out.colors.push_back(mesh.colors[v]);
    }
    mesh = std::move(out);
    return dropped;
}

} // namespace fl::bench
