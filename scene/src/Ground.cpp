#include <scene/Ground.h>

#include <scene/Pose.h>

#include <base/Finite.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

namespace fl {

namespace {

constexpr int kCells = 32;              // per side of the footprint's grid
constexpr float kMinUpward = 0.7071f;   // cos 45 degrees
constexpr float kLowShare = 0.2f;       // the bottom fifth of the scene's height
constexpr double kGroundCoverage = 0.5; // of the cells
constexpr float kReach = 0.75f;         // the ground past the footprint, x the scene's height

// Twice the signed area of (a, b, c) in the xz plane.
float edge(glm::vec2 a, glm::vec2 b, glm::vec2 c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

} // namespace

std::optional<GroundMode> parseGroundMode(std::string_view text) {
    const auto it = std::find(kGroundModeNames.begin(), kGroundModeNames.end(), text);
    if (it == kGroundModeNames.end()) return std::nullopt;
    return static_cast<GroundMode>(it - kGroundModeNames.begin());
}

double groundCoverage(const Scene& scene) {
    const geom::Aabb& b = scene.bounds;
    if (!b.valid()) return 0.0;
    const glm::vec2 lo(b.min.x, b.min.z), size(b.max.x - b.min.x, b.max.z - b.min.z);
    const float height = b.max.y - b.min.y;
    // A flat scene (all at one height) is its own ground if its surfaces face up.
    const float low = b.min.y + kLowShare * height + 1e-6f * std::max(b.radius(), 1e-6f);
    const glm::vec2 cell = glm::max(size / float(kCells), glm::vec2(1e-12f));
    std::vector<float> lowest(kCells * kCells, std::numeric_limits<float>::infinity());
    for (const Instance& inst : scene.instances) {
        const Mesh& mesh = scene.meshes.at(static_cast<std::size_t>(inst.mesh));
        const bool twoSided =
            mesh.material >= 0 &&
            scene.materials.at(static_cast<std::size_t>(mesh.material)).doubleSided;
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            glm::vec3 p[3];
            for (int k = 0; k < 3; ++k)
                p[k] = glm::vec3(inst.world * glm::vec4(mesh.positions[mesh.indices[t + k]], 1.0f));
            const glm::vec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
            const float len = glm::length(n);
            if (!(len > 0.0f)) continue;
            const float up = n.y / len;
            if (up < kMinUpward && !(twoSided && -up >= kMinUpward)) continue;
            const glm::vec2 q[3] = {{p[0].x, p[0].z}, {p[1].x, p[1].z}, {p[2].x, p[2].z}};
            const float area = edge(q[0], q[1], q[2]);
            if (area == 0.0f) continue;
            // The cells whose centres the triangle covers, and its height there.
            const glm::vec2 tmin = glm::min(q[0], glm::min(q[1], q[2]));
            const glm::vec2 tmax = glm::max(q[0], glm::max(q[1], q[2]));
            const int x0 = std::max(0, int(std::ceil((tmin.x - lo.x) / cell.x - 0.5f)));
            const int x1 = std::min(kCells - 1, int(std::floor((tmax.x - lo.x) / cell.x - 0.5f)));
            const int z0 = std::max(0, int(std::ceil((tmin.y - lo.y) / cell.y - 0.5f)));
            const int z1 = std::min(kCells - 1, int(std::floor((tmax.y - lo.y) / cell.y - 0.5f)));
            for (int z = z0; z <= z1; ++z)
                for (int x = x0; x <= x1; ++x) {
                    const glm::vec2 c = lo + (glm::vec2(x, z) + 0.5f) * cell;
                    const float w0 = edge(q[1], q[2], c) / area, w1 = edge(q[2], q[0], c) / area,
                                w2 = edge(q[0], q[1], c) / area;
                    if (w0 < 0.0f || w1 < 0.0f || w2 < 0.0f) continue;
                    float& l = lowest[std::size_t(z) * kCells + std::size_t(x)];
                    l = std::min(l, w0 * p[0].y + w1 * p[1].y + w2 * p[2].y);
                }
        }
    }
    const auto covered =
        std::count_if(lowest.begin(), lowest.end(), [&](float y) { return y <= low; });
    return double(covered) / double(lowest.size());
}

bool hasGround(const Scene& scene) {
    return groundCoverage(scene) >= kGroundCoverage;
}

void addGround(Scene& scene) {
    const geom::Aabb b = scene.bounds;
    // The loader refuses such scenes (restHasArea); a ground must never come out at NaN.
    if (!b.valid() || !geom::allFinite(b.min) || !geom::allFinite(b.max))
        throw std::invalid_argument(scene.source + ": no ground under bounds that are empty or "
                                                   "not finite");
    const glm::vec3 c = b.center(), e = b.extent();
    // The default light (sceneLight) stands 58 degrees above the horizon: a shadow reaches
    // 0.61 x the height past the footprint; 0.75 x leaves a margin. The first view frames the
    // model and its shadow, not this square (modelAndShadowPoints).
    const float half =
        0.5f * std::max(e.x, e.z) + kReach * std::max(e.y, 0.25f * std::max(e.x, e.z));
    // Just below the lowest point, so that a model's flat underside does not fight it for depth.
    const float y = b.min.y - 1e-4f * std::max(b.radius(), 1e-6f);
    Mesh ground;
    ground.name = "floodlight ground";
    ground.positions = {{c.x - half, y, c.z - half},
                        {c.x + half, y, c.z - half},
                        {c.x + half, y, c.z + half},
                        {c.x - half, y, c.z + half}};
    ground.normals.assign(4, glm::vec3(0.0f, 1.0f, 0.0f));
    ground.indices = {0, 2, 1, 0, 3, 2}; // counter-clockwise seen from above
    Material grey;
    grey.name = "floodlight ground";
    grey.baseColorFactor = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
    ground.material = static_cast<int>(scene.materials.size());
    scene.materials.push_back(grey);
    std::uint32_t id = 0;
    for (const Instance& inst : scene.instances) id = std::max(id, inst.objectId);
    Instance inst;
    inst.mesh = static_cast<int>(scene.meshes.size());
    inst.objectId = id + 1;
    inst.nodeName = "floodlight ground";
    scene.meshes.push_back(std::move(ground));
    scene.addedGround = static_cast<int>(scene.instances.size());
    scene.instances.push_back(inst);
    scene.computeBounds();
}

std::vector<glm::vec3> modelAndShadowPoints(const Scene& scene, const Light& light,
                                            const Pose* pose) {
    if (scene.addedGround < 0 || scene.addedGround >= static_cast<int>(scene.instances.size()))
        return {};
    const Instance& g = scene.instances[static_cast<std::size_t>(scene.addedGround)];
    geom::Aabb ground;
    for (const glm::vec3& p : scene.meshes.at(static_cast<std::size_t>(g.mesh)).positions)
        ground.extend(glm::vec3(g.world * glm::vec4(p, 1.0f)));
    const float y = ground.max.y; // the ground is flat: its top is its plane
    std::vector<glm::vec3> out;
    bool offGround = false;
    // Posed vertices in `pose`; without one, a skinned or morphed instance's at rest (its mesh
    // positions are not where it is drawn), a rigid one's moved by its `world`.
    std::optional<Pose> rest;
    std::vector<glm::vec3> posed;
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        if (static_cast<int>(i) == scene.addedGround) continue;
        const Instance& inst = scene.instances[i];
        const Mesh& mesh = scene.meshes.at(static_cast<std::size_t>(inst.mesh));
        const Pose* at = pose;
        if (!at && (isSkinned(inst, mesh) || !mesh.targets.empty())) {
            if (!rest) rest = evaluatePose(scene, {}, 0.0);
            at = &*rest;
        }
        if (at) posedVertices(scene, *at, i, posed);
        const std::vector<glm::vec3>& vertices = at ? posed : mesh.positions;
        const glm::mat4 world = at ? glm::mat4(1.0f) : inst.world;
        for (const glm::vec3& p : vertices) {
            const glm::vec3 w(world * glm::vec4(p, 1.0f));
            out.push_back(w);
            // The shadow of a triangle is the triangle of its corners' shadows (each corner
            // below the light meets the plane once): the hull of these holds the model's.
            const glm::vec3 d =
                light.type == Light::Type::Directional ? light.direction : w - light.position;
            if (d.y < 0.0f)
                out.push_back(glm::clamp(w + d * ((y - w.y) / d.y), ground.min, ground.max));
            else
                offGround = true; // level with or above the light: runs off the ground
        }
    }
    if (offGround)
        for (int k = 0; k < 4; ++k)
            out.emplace_back((k & 1) ? ground.max.x : ground.min.x, y,
                             (k & 2) ? ground.max.z : ground.min.z);
    return out;
}

bool applyGround(Scene& scene, GroundMode mode) {
    if (mode == GroundMode::Off || (mode == GroundMode::Auto && hasGround(scene))) return false;
    addGround(scene);
    return true;
}

} // namespace fl
