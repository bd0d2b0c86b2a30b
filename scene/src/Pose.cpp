#include <scene/Pose.h>

#include <base/Finite.h>
#include <base/Text.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fl {

namespace {

/// A node's animated properties: the rest values with the channels' samples written over them.
struct NodeState {
    glm::vec3 translation;
    glm::quat rotation;
    glm::vec3 scale;
    bool animated = false;      // some T/R/S channel drove it (a matrix node becomes TRS then)
    std::vector<float> weights; // empty: not animated
};

/// Component c of key k's value (CUBICSPLINE keys hold in-tangent, value, out-tangent).
float keyValue(const Animation::Sampler& s, std::size_t k, int c, int part = 1) {
    const std::size_t w = static_cast<std::size_t>(s.width);
    const std::size_t stride = s.interpolation == Animation::Interpolation::CubicSpline ? 3 * w : w;
    const std::size_t offset = s.interpolation == Animation::Interpolation::CubicSpline
                                   ? static_cast<std::size_t>(part) * w
                                   : 0;
    return s.values[k * stride + offset + static_cast<std::size_t>(c)];
}

/// The sampler's `width` values at time t (spec 3.11.2 and Appendix C). Rotations (`rotation`)
/// interpolate by slerp in LINEAR; every interpolation's result is normalised for them.
std::vector<float> sample(const Animation::Sampler& s, double t, bool rotation) {
    const int w = s.width;
    std::vector<float> out(static_cast<std::size_t>(w));
    const std::size_t n = s.times.size();
    if (n == 0 || w <= 0) return out;
    auto key = [&](std::size_t k) {
        for (int c = 0; c < w; ++c) out[static_cast<std::size_t>(c)] = keyValue(s, k, c);
    };
    if (t <= s.times.front() || n == 1) {
        key(0);
    } else if (t >= s.times.back()) {
        key(n - 1);
    } else {
        const auto upper = std::upper_bound(s.times.begin(), s.times.end(), static_cast<float>(t));
        const std::size_t k1 = static_cast<std::size_t>(upper - s.times.begin());
        const std::size_t k0 = k1 - 1;
        const double t0 = s.times[k0], t1 = s.times[k1];
        const double td = t1 - t0;
        const auto u = static_cast<float>(td > 0.0 ? (t - t0) / td : 0.0);
        switch (s.interpolation) {
        case Animation::Interpolation::Step:
            key(k0);
            break;
        case Animation::Interpolation::Linear:
            if (rotation && w == 4) {
                const glm::quat a(keyValue(s, k0, 3), keyValue(s, k0, 0), keyValue(s, k0, 1),
                                  keyValue(s, k0, 2));
                const glm::quat b(keyValue(s, k1, 3), keyValue(s, k1, 0), keyValue(s, k1, 1),
                                  keyValue(s, k1, 2));
                const glm::quat q = glm::slerp(a, b, u); // glm takes the shorter arc
                out = {q.x, q.y, q.z, q.w};
            } else {
                for (int c = 0; c < w; ++c)
                    out[static_cast<std::size_t>(c)] =
                        (1.0f - u) * keyValue(s, k0, c) + u * keyValue(s, k1, c);
            }
            break;
        case Animation::Interpolation::CubicSpline: {
            // Hermite with the tangents scaled by the key interval (Appendix C).
            const float u2 = u * u, u3 = u2 * u, d = static_cast<float>(td);
            for (int c = 0; c < w; ++c)
                out[static_cast<std::size_t>(c)] = (2 * u3 - 3 * u2 + 1) * keyValue(s, k0, c, 1) +
                                                   (u3 - 2 * u2 + u) * d * keyValue(s, k0, c, 2) +
                                                   (-2 * u3 + 3 * u2) * keyValue(s, k1, c, 1) +
                                                   (u3 - u2) * d * keyValue(s, k1, c, 0);
            break;
        }
        }
    }
    if (rotation && w == 4) {
        const glm::quat q = glm::normalize(glm::quat(out[3], out[0], out[1], out[2]));
        out = {q.x, q.y, q.z, q.w};
    }
    return out;
}

glm::mat4 localMatrix(const Node& node, const NodeState& s) {
    if (node.matrix && !s.animated) return *node.matrix;
    return glm::translate(glm::mat4(1.0f), s.translation) * glm::mat4_cast(s.rotation) *
           glm::scale(glm::mat4(1.0f), s.scale);
}

} // namespace

bool isSkinned(const Instance& instance, const Mesh& mesh) {
    return instance.skin >= 0 && !mesh.joints.empty() && mesh.weights.size() == mesh.joints.size();
}

bool isAnimated(const Scene& scene) {
    if (!scene.animations.empty() || !scene.skins.empty()) return true;
    return std::any_of(scene.meshes.begin(), scene.meshes.end(),
                       [](const Mesh& m) { return !m.targets.empty(); });
}

std::vector<int> chooseAnimations(const Scene& scene, const std::string& choice) {
    std::vector<int> all(scene.animations.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
    if (choice == "all") return all;
    if (choice == "none") return {};
    for (std::size_t i = 0; i < scene.animations.size(); ++i)
        if (scene.animations[i].name == choice) return {static_cast<int>(i)};
    if (!choice.empty() && std::all_of(choice.begin(), choice.end(), ::isdigit) &&
        choice.size() < 10) {
        const int index = std::stoi(choice);
        if (index < static_cast<int>(scene.animations.size())) return {index};
    }
    std::string names;
    for (std::size_t i = 0; i < scene.animations.size(); ++i)
        names += cat(names.empty() ? "" : ", ", i, " '", scene.animations[i].name, "'");
    throw std::invalid_argument(cat("animation ", choice, ": not all, none, or one of the scene's ",
                                    scene.animations.size(), " animation(s)",
                                    names.empty() ? "" : ": ", names));
}

double animationDuration(const Scene& scene, std::span<const int> animations) {
    double d = 0.0;
    for (int a : animations)
        d = std::max<double>(d, scene.animations.at(static_cast<std::size_t>(a)).duration);
    return d;
}

namespace {

// Every node's local state at `time`: its rest TRS, overridden by the animations' channels.
std::vector<NodeState> animatedStates(const Scene& scene, std::span<const int> animations,
                                      double time) {
    std::vector<NodeState> state(scene.nodes.size());
    for (std::size_t i = 0; i < scene.nodes.size(); ++i)
        state[i] = {
            scene.nodes[i].translation, scene.nodes[i].rotation, scene.nodes[i].scale, false, {}};
    for (int a : animations) {
        const Animation& anim = scene.animations.at(static_cast<std::size_t>(a));
        for (const Animation::Channel& ch : anim.channels) {
            NodeState& s = state.at(static_cast<std::size_t>(ch.node));
            const Animation::Sampler& sm = anim.samplers.at(static_cast<std::size_t>(ch.sampler));
            const std::vector<float> v = sample(sm, time, ch.path == Animation::Path::Rotation);
            switch (ch.path) {
            case Animation::Path::Translation:
                s.translation = {v[0], v[1], v[2]};
                s.animated = true;
                break;
            case Animation::Path::Rotation:
                s.rotation = glm::quat(v[3], v[0], v[1], v[2]);
                s.animated = true;
                break;
            case Animation::Path::Scale:
                s.scale = {v[0], v[1], v[2]};
                s.animated = true;
                break;
            case Animation::Path::Weights:
                s.weights = v;
                break;
            }
        }
    }
    return state;
}

// World transforms, parents first (the graph is acyclic: the loader checked).
std::vector<glm::mat4> nodeWorlds(const Scene& scene, const std::vector<NodeState>& state) {
    std::vector<glm::mat4> world(scene.nodes.size(), glm::mat4(1.0f));
    std::vector<char> done(scene.nodes.size(), 0);
    std::vector<std::size_t> chain;
    for (std::size_t i = 0; i < scene.nodes.size(); ++i) {
        chain.clear();
        for (int n = static_cast<int>(i); n >= 0 && !done[static_cast<std::size_t>(n)];
             n = scene.nodes[static_cast<std::size_t>(n)].parent)
            chain.push_back(static_cast<std::size_t>(n));
        for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
            const Node& node = scene.nodes[*it];
            const glm::mat4 parent =
                node.parent >= 0 ? world[static_cast<std::size_t>(node.parent)] : glm::mat4(1.0f);
            world[*it] = parent * localMatrix(node, state[*it]);
            done[*it] = 1;
        }
    }
    return world;
}

// An instance's morph weights: the node's animated ones, else the node's, else the mesh's;
// as many as the mesh has targets (none without targets).
std::vector<float> instanceWeights(const Scene& scene, const Instance& inst, const Mesh& mesh,
                                   const std::vector<NodeState>& state) {
    std::vector<float> weights;
    if (mesh.targets.empty()) return weights;
    weights = mesh.morphWeights;
    if (inst.node >= 0) {
        const NodeState& s = state.at(static_cast<std::size_t>(inst.node));
        const Node& node = scene.nodes[static_cast<std::size_t>(inst.node)];
        if (!s.weights.empty())
            weights = s.weights;
        else if (!node.weights.empty())
            weights = node.weights;
    }
    weights.resize(mesh.targets.size(), 0.0f);
    return weights;
}

} // namespace

Pose evaluatePose(const Scene& scene, std::span<const int> animations, double time) {
    Pose pose;
    pose.time = time;
    const std::vector<NodeState> state = animatedStates(scene, animations, time);
    pose.nodeWorld = nodeWorlds(scene, state);
    for (const Skin& skin : scene.skins) {
        std::vector<glm::mat4> joints(skin.joints.size());
        for (std::size_t j = 0; j < skin.joints.size(); ++j)
            joints[j] = pose.nodeWorld.at(static_cast<std::size_t>(skin.joints[j])) *
                        skin.inverseBind.at(j);
        pose.joints.push_back(std::move(joints));
    }
    for (const Instance& inst : scene.instances) {
        const Mesh& mesh = scene.meshes.at(static_cast<std::size_t>(inst.mesh));
        glm::mat4 world = inst.world;
        if (isSkinned(inst, mesh))
            world = glm::mat4(1.0f);
        else if (inst.node >= 0)
            world = pose.nodeWorld.at(static_cast<std::size_t>(inst.node));
        pose.instanceWorld.push_back(world);
        pose.morphWeights.push_back(instanceWeights(scene, inst, mesh, state));
    }
    return pose;
}

void posedVertices(const Scene& scene, const Pose& pose, std::size_t instance,
                   std::vector<glm::vec3>& positions, std::vector<glm::vec3>* normals) {
    const Instance& inst = scene.instances.at(instance);
    const Mesh& mesh = scene.meshes.at(static_cast<std::size_t>(inst.mesh));
    const std::vector<float>& weights = pose.morphWeights.at(instance);
    const bool skinned = isSkinned(inst, mesh);
    const std::vector<glm::mat4>* joints =
        skinned ? &pose.joints.at(static_cast<std::size_t>(inst.skin)) : nullptr;
    const glm::mat4& world = pose.instanceWorld.at(instance);
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(world)));
    positions.resize(mesh.positions.size());
    if (normals) normals->resize(mesh.positions.size());
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        glm::vec3 p = mesh.positions[v];
        glm::vec3 n = v < mesh.normals.size() ? mesh.normals[v] : glm::vec3(0, 0, 1);
        for (std::size_t t = 0; t < mesh.targets.size() && t < weights.size(); ++t) {
            if (weights[t] == 0.0f) continue;
            const Mesh::MorphTarget& target = mesh.targets[t];
            if (!target.positions.empty()) p += weights[t] * target.positions[v];
            if (!target.normals.empty()) n += weights[t] * target.normals[v];
        }
        if (skinned) {
            const glm::uvec4 j = mesh.joints[v];
            const glm::vec4 w = mesh.weights[v];
            glm::mat4 m(0.0f);
            for (int k = 0; k < 4; ++k)
                if (w[k] != 0.0f) m += w[k] * joints->at(j[k]);
            positions[v] = glm::vec3(m * glm::vec4(p, 1.0f));
            if (normals) (*normals)[v] = glm::normalize(glm::mat3(m) * n);
        } else {
            positions[v] = glm::vec3(world * glm::vec4(p, 1.0f));
            if (normals) (*normals)[v] = glm::normalize(normalMatrix * n);
        }
    }
}

geom::Aabb posedBounds(const Scene& scene, const Pose& pose, int skipInstance) {
    geom::Aabb box;
    std::vector<glm::vec3> positions;
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        if (static_cast<int>(i) == skipInstance) continue;
        const Instance& inst = scene.instances[i];
        const Mesh& mesh = scene.meshes.at(static_cast<std::size_t>(inst.mesh));
        if (!isSkinned(inst, mesh) && mesh.targets.empty()) {
            // Rigid: the mesh's own box moved. Looser than its vertices where the node turns;
            // animatedBounds keeps that margin for the turns between the poses it samples.
            geom::Aabb local;
            for (const glm::vec3& p : mesh.positions) local.extend(p);
            box.extend(local.transformed(pose.instanceWorld[i]));
            continue;
        }
        posedVertices(scene, pose, i, positions);
        for (const glm::vec3& p : positions) box.extend(p);
    }
    return box;
}

namespace {

/// The scene at rest, posed on first use: only skinned and morphed instances need the pose.
class RestPose {
  public:
    explicit RestPose(const Scene& scene) : scene_(scene) {}
    /// Instance i's vertices at rest in world space, or nullptr for a rigid instance (its
    /// `world` moves its mesh's positions).
    const std::vector<glm::vec3>* posed(std::size_t i) {
        const Instance& inst = scene_.instances[i];
        const Mesh& mesh = scene_.meshes.at(static_cast<std::size_t>(inst.mesh));
        if (!isSkinned(inst, mesh) && mesh.targets.empty()) return nullptr;
        if (pose_.instanceWorld.empty()) pose_ = evaluatePose(scene_, {}, 0.0);
        posedVertices(scene_, pose_, i, vertices_);
        return &vertices_;
    }

  private:
    const Scene& scene_;
    Pose pose_;
    std::vector<glm::vec3> vertices_;
};

} // namespace

geom::Aabb restBounds(const Scene& scene, int skipInstance) {
    geom::Aabb box;
    RestPose rest(scene);
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        if (static_cast<int>(i) == skipInstance) continue;
        const Instance& inst = scene.instances[i];
        if (const std::vector<glm::vec3>* posed = rest.posed(i))
            box.extend(geom::Aabb::around(*posed, glm::mat4(1.0f)));
        else
            box.extend(geom::Aabb::around(
                scene.meshes.at(static_cast<std::size_t>(inst.mesh)).positions, inst.world));
    }
    return box;
}

bool restHasArea(const Scene& scene) {
    RestPose rest(scene);
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        const Instance& inst = scene.instances[i];
        const Mesh& mesh = scene.meshes.at(static_cast<std::size_t>(inst.mesh));
        const std::vector<glm::vec3>* posed = rest.posed(i);
        const std::vector<glm::vec3>& v = posed ? *posed : mesh.positions;
        const glm::mat4 world = posed ? glm::mat4(1.0f) : inst.world;
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            glm::vec3 p[3];
            for (int k = 0; k < 3; ++k)
                p[k] = glm::vec3(world * glm::vec4(v[mesh.indices[t + k]], 1.0f));
            // Not the cross product's length: squaring overflows for large triangles.
            const glm::vec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
            if (n != glm::vec3(0.0f) && geom::allFinite(n)) return true;
        }
    }
    return false;
}

geom::Aabb animatedBounds(const Scene& scene, std::span<const int> animations, int steps,
                          int skipInstance) {
    std::vector<double> times = {0.0};
    const double duration = animationDuration(scene, animations);
    for (int k = 1; k <= steps && duration > 0.0; ++k) times.push_back(duration * k / steps);
    for (int a : animations)
        for (const Animation::Sampler& s :
             scene.animations.at(static_cast<std::size_t>(a)).samplers)
            times.insert(times.end(), s.times.begin(), s.times.end());
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());
    // A long captured clip has thousands of keys: at most kMaxBoundsPoses evenly chosen ones
    // (each pose skins every vertex on the CPU).
    constexpr std::size_t kMaxBoundsPoses = 256;
    if (times.size() > kMaxBoundsPoses) {
        std::vector<double> kept;
        for (std::size_t k = 0; k < kMaxBoundsPoses; ++k)
            kept.push_back(times[k * (times.size() - 1) / (kMaxBoundsPoses - 1)]);
        times = std::move(kept);
    }
    geom::Aabb box;
    for (double t : times)
        box.extend(posedBounds(scene, evaluatePose(scene, animations, t), skipInstance));
    return box;
}

} // namespace fl
