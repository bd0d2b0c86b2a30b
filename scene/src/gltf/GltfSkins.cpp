// Skinning attributes (JOINTS_0 / WEIGHTS_0), morph targets, skins and the node list that
// animation needs. Joint indices can only be checked against a skin, and the skin belongs to
// the node that places a mesh, so they are checked per instance (linkSkins); everything else is
// checked where it is read. The node list is only built for files with skins, morph targets or
// animations: a large static scene pays nothing for it.

#include "GltfInternal.h"

#include <base/Finite.h>

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <map>

namespace fl::gltf {
namespace {

// Weight sums within this of 1 are renormalised silently: normalized 8-bit weights cannot always
// sum to exactly 1 (rounding costs up to 2/255 over four weights). Farther off is an authoring
// error worth a warning.
constexpr float kWeightSumTolerance = 0.01f;

int attribute(const tinygltf::Primitive& prim, const char* name) {
    const auto it = prim.attributes.find(name);
    return it == prim.attributes.end() ? -1 : it->second;
}

/// Makes every vertex's weights usable: negative or non-finite weights become 0 (the spec
/// allows neither; dropping the influence is the least surprising repair), sums are normalised
/// to 1, and a vertex left with no weight follows its first listed joint.
void repairWeights(const Context& ctx, const std::string& element,
                   std::vector<glm::vec4>& weights) {
    std::size_t invalid = 0, unnormalised = 0, zero = 0;
    for (glm::vec4& w : weights) {
        for (int k = 0; k < 4; ++k)
            if (!(std::isfinite(w[k]) && w[k] >= 0.0f)) {
                w[k] = 0.0f;
                ++invalid;
            }
        // Summed in double: four floats near FLT_MAX overflow a float sum.
        const double sum = double(w.x) + double(w.y) + double(w.z) + double(w.w);
        if (!(sum > 0.0)) {
            w = glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
            ++zero;
            continue;
        }
        if (std::abs(sum - 1.0) > kWeightSumTolerance) ++unnormalised;
        if (sum != 1.0) w = glm::vec4(glm::dvec4(w) / sum);
    }
    if (invalid > 0)
        ctx.warn(element,
                 cat("WEIGHTS_0: ", invalid, " negative or non-finite weight(s) set to 0"));
    if (unnormalised > 0)
        ctx.warn(element,
                 cat("WEIGHTS_0: ", unnormalised, " vertex weight sum(s) not 1; normalised"));
    if (zero > 0)
        ctx.warn(element, cat("WEIGHTS_0: ", zero,
                              " vertex(es) with no weight; weight 1 given to their first joint"));
}

/// Same count as POSITION, or the file is inconsistent (spec 3.7.2.1).
void checkCount(const Context& ctx, const std::string& element, std::string_view attr,
                std::size_t count, std::size_t vertexCount) {
    if (count != vertexCount)
        ctx.fail(element, cat(attr, " has ", count, " elements but POSITION has ", vertexCount));
}

/// Fails on the first non-finite morph delta.
void checkDeltas(const Context& ctx, int accessor, const std::string& usage,
                 const std::vector<glm::vec3>& deltas) {
    for (std::size_t i = 0; i < deltas.size(); ++i)
        if (!geom::allFinite(deltas[i]))
            ctx.fail(elem("accessors", static_cast<std::size_t>(accessor)),
                     cat(usage, ": delta ", i, " is not finite"));
}

/// Where a node property of `n` floats can be read: `n` values that stay finite as floats.
bool floats(const std::vector<double>& values, std::size_t n, float* out) {
    if (values.size() != n) return false;
    for (std::size_t i = 0; i < n; ++i) {
        out[i] = static_cast<float>(values[i]);
        if (!std::isfinite(out[i])) return false;
    }
    return true;
}

/// scene.nodes[i] from the file's nodes[i]. Nodes the scene places already passed
/// localTransform's checks (array sizes, finite doubles; zero rotations warned about there);
/// the rest are repaired here with a warning, as are values a float cannot hold.
Node convertNode(const Context& ctx, std::size_t index, int parent, bool placed) {
    const tinygltf::Node& src = ctx.model().nodes[index];
    const std::string element = elem("nodes", index);
    Node node;
    node.name = src.name;
    node.parent = parent;
    if (!src.matrix.empty()) {
        glm::mat4 m;
        if (floats(src.matrix, 16, &m[0][0])) // both column-major
            node.matrix = m;
        else
            ctx.warn(element, "matrix is not 16 finite floats; identity used");
        return node;
    }
    glm::vec3 t(0.0f), s(1.0f);
    glm::vec4 r(0.0f, 0.0f, 0.0f, 1.0f);
    if (!src.translation.empty() && !floats(src.translation, 3, &t.x))
        ctx.warn(element, "translation is not 3 finite floats; zero used");
    if (!src.scale.empty() && !floats(src.scale, 3, &s.x))
        ctx.warn(element, "scale is not 3 finite floats; 1 used");
    if (!src.rotation.empty()) {
        // Normalised in double: components too large for a float still give a rotation.
        const auto& q = src.rotation;
        const glm::dvec4 d = q.size() == 4 ? glm::dvec4(q[0], q[1], q[2], q[3]) : glm::dvec4(0.0);
        const double len = glm::length(d);
        if (len > 1e-12 && std::isfinite(len)) {
            r = glm::vec4(d / len);
        } else if (!placed || q.size() != 4) {
            ctx.warn(element, "rotation is not a usable quaternion; identity used");
        }
    }
    node.translation = t;
    node.rotation = glm::quat(r.w, r.x, r.y, r.z); // glTF stores x, y, z, w
    node.scale = s;
    return node;
}

/// node.weights, when they fit the mesh's targets (else the mesh's weights apply).
std::vector<float> nodeWeights(const Context& ctx, std::size_t index,
                               MorphTargetCounts& targetCounts) {
    const tinygltf::Node& src = ctx.model().nodes[index];
    if (src.weights.empty()) return {};
    const std::string element = elem("nodes", index);
    const std::size_t targets = targetCounts(src.mesh);
    if (src.weights.size() != targets) {
        ctx.warn(element, cat("weights has ", src.weights.size(), " values but its mesh has ",
                              targets, " morph targets; the mesh's weights used"));
        return {};
    }
    std::vector<float> w(targets);
    if (!floats(src.weights, targets, w.data())) {
        ctx.warn(element, "weights are not finite floats; the mesh's weights used");
        return {};
    }
    return w;
}

/// Whether animation data is worth keeping: the file has skins, morph targets or animations.
bool needsNodes(const Context& ctx) {
    const auto& model = ctx.model();
    if (!model.skins.empty() || !model.animations.empty()) return true;
    for (const tinygltf::Mesh& mesh : model.meshes)
        for (const tinygltf::Primitive& prim : mesh.primitives)
            if (!prim.targets.empty()) return true;
    return false;
}

std::vector<Node> convertNodes(const Context& ctx, const std::vector<PlacedNode>& placed) {
    const auto& model = ctx.model();
    std::vector<int> parents(model.nodes.size(), -1); // the graph is valid (placeSceneNodes)
    for (std::size_t i = 0; i < model.nodes.size(); ++i)
        for (int child : model.nodes[i].children)
            parents[static_cast<std::size_t>(child)] = static_cast<int>(i);
    std::vector<char> isPlaced(model.nodes.size(), 0);
    for (const PlacedNode& p : placed) isPlaced[static_cast<std::size_t>(p.node)] = 1;
    MorphTargetCounts targetCounts(ctx);
    std::vector<Node> nodes;
    nodes.reserve(model.nodes.size());
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
        nodes.push_back(convertNode(ctx, i, parents[i], isPlaced[i] != 0));
        nodes.back().weights = nodeWeights(ctx, i, targetCounts);
    }
    return nodes;
}

Skin convertSkin(const Context& ctx, int index) {
    const tinygltf::Skin& src = ctx.model().skins[static_cast<std::size_t>(index)];
    const std::string element = elem("skins", static_cast<std::size_t>(index));
    if (src.joints.empty()) ctx.fail(element, "no joints");
    // A joint list can be long without any accessor behind it; its matrices count all the same.
    ctx.charge(src.joints.size() * 16, element);
    Skin skin;
    skin.name = src.name;
    for (std::size_t k = 0; k < src.joints.size(); ++k)
        ctx.lookup(ctx.model().nodes, src.joints[k], cat(element, ".joints[", k, "]"), "node",
                   "nodes");
    skin.joints = src.joints;
    if (src.inverseBindMatrices < 0) {
        skin.inverseBind.assign(src.joints.size(), glm::mat4(1.0f)); // spec 3.7.3.2
        return skin;
    }
    const std::string usage = element + ".inverseBindMatrices";
    skin.inverseBind = readMat4(ctx, src.inverseBindMatrices, usage);
    if (skin.inverseBind.size() != skin.joints.size())
        ctx.fail(element, cat("inverseBindMatrices has ", skin.inverseBind.size(),
                              " matrices but the skin has ", skin.joints.size(), " joints"));
    for (std::size_t i = 0; i < skin.inverseBind.size(); ++i)
        if (!geom::allFinite(skin.inverseBind[i]))
            ctx.fail(elem("accessors", static_cast<std::size_t>(src.inverseBindMatrices)),
                     cat(usage, ": matrix ", i, " is not finite"));
    return skin;
}

/// Gives each instance its node's skin (scene.skins holds the skins instances use, in order of
/// first use) and checks its mesh's joint indices against it. Skinning data no instance uses is
/// dropped, with a warning for the instances that ignore it.
void linkSkins(const Context& ctx, Scene& scene) {
    const auto& model = ctx.model();
    std::map<int, int> converted; // file skin -> index into scene.skins
    std::vector<char> skinned(scene.meshes.size(), 0);
    std::map<int, std::optional<std::uint32_t>> maxJoint; // mesh -> its highest joint index
    for (Instance& inst : scene.instances) {
        const auto nodeIndex = static_cast<std::size_t>(inst.node);
        const tinygltf::Node& node = model.nodes[nodeIndex];
        const std::string element = elem("nodes", nodeIndex);
        const std::string meshElement = elem("meshes", static_cast<std::size_t>(node.mesh));
        const Mesh& mesh = scene.meshes[static_cast<std::size_t>(inst.mesh)];
        if (node.skin == -1) {
            if (!mesh.joints.empty())
                ctx.warn(element,
                         cat(meshElement, " has JOINTS_0 and WEIGHTS_0 but the node has no skin; "
                                          "drawn unskinned"));
            continue;
        }
        ctx.lookup(model.skins, node.skin, element, "skin", "skins");
        const std::string skinElement = elem("skins", static_cast<std::size_t>(node.skin));
        if (mesh.joints.empty()) {
            ctx.warn(element, cat(skinElement, " ignored: ", meshElement,
                                  " has no JOINTS_0 and WEIGHTS_0; drawn unskinned"));
            continue;
        }
        auto it = converted.find(node.skin);
        if (it == converted.end()) {
            scene.skins.push_back(convertSkin(ctx, node.skin));
            it = converted.emplace(node.skin, static_cast<int>(scene.skins.size() - 1)).first;
        }
        const std::size_t jointCount =
            scene.skins[static_cast<std::size_t>(it->second)].joints.size();
        auto& highest = maxJoint[inst.mesh]; // once per mesh: instances can be many
        if (!highest) {
            highest = 0u;
            for (const glm::uvec4& j : mesh.joints)
                highest = std::max({*highest, j.x, j.y, j.z, j.w});
        }
        if (*highest >= jointCount)
            ctx.fail(element, cat(meshElement, " JOINTS_0: joint index ", *highest,
                                  " out of range (", skinElement, " has ", jointCount, " joints)"));
        inst.skin = it->second;
        skinned[static_cast<std::size_t>(inst.mesh)] = 1;
    }
    for (std::size_t m = 0; m < scene.meshes.size(); ++m)
        if (!skinned[m]) {
            scene.meshes[m].joints.clear();
            scene.meshes[m].weights.clear();
        }
}

} // namespace

void attachSkinning(const Context& ctx, const tinygltf::Primitive& prim, const std::string& element,
                    Mesh& mesh) {
    for (const auto& [name, accessor] : prim.attributes)
        if ((name.rfind("JOINTS_", 0) == 0 || name.rfind("WEIGHTS_", 0) == 0) &&
            name != "JOINTS_0" && name != "WEIGHTS_0")
            ctx.warn(element, cat(name, " ignored (at most 4 joint influences per vertex)"));
    const int joints = attribute(prim, "JOINTS_0"), weights = attribute(prim, "WEIGHTS_0");
    if (joints < 0 && weights < 0) return;
    if (joints < 0 || weights < 0) {
        ctx.warn(element,
                 cat(joints < 0 ? "WEIGHTS_0 without JOINTS_0" : "JOINTS_0 without WEIGHTS_0",
                     "; drawn unskinned"));
        return;
    }
    mesh.joints = readJoints(ctx, joints, element + ".attributes.JOINTS_0");
    checkCount(ctx, element, "JOINTS_0", mesh.joints.size(), mesh.positions.size());
    mesh.weights = readWeights(ctx, weights, element + ".attributes.WEIGHTS_0");
    checkCount(ctx, element, "WEIGHTS_0", mesh.weights.size(), mesh.positions.size());
    repairWeights(ctx, element, mesh.weights);
}

void attachMorphTargets(const Context& ctx, const tinygltf::Primitive& prim,
                        const std::string& element, Mesh& mesh) {
    const bool hasNormals = attribute(prim, "NORMAL") >= 0;
    // Beyond fl::kMaxMorphTargets the vertex stage applies none (morphTargetCount warned).
    for (std::size_t i = 0; i < prim.targets.size() && i < fl::kMaxMorphTargets; ++i) {
        // Only POSITION and NORMAL deltas matter: TANGENT, TEXCOORD_n and COLOR_n deltas
        // change nothing Floodlight draws.
        const auto& attributes = prim.targets[i];
        const std::string target = cat("targets[", i, "]");
        Mesh::MorphTarget out;
        if (const auto it = attributes.find("POSITION"); it != attributes.end()) {
            const std::string usage = cat(element, '.', target, ".POSITION");
            out.positions = readTargetPositionVec3(ctx, it->second, usage);
            checkCount(ctx, element, target + ".POSITION", out.positions.size(),
                       mesh.positions.size());
            checkDeltas(ctx, it->second, usage, out.positions);
        }
        if (const auto it = attributes.find("NORMAL"); it != attributes.end()) {
            const std::string usage = cat(element, '.', target, ".NORMAL");
            if (!hasNormals) {
                // Deltas of generated flat normals mean nothing (spec 3.7.2.2 requires the base
                // attribute).
                ctx.warn(element, cat(target, ".NORMAL ignored: the primitive has no NORMAL"));
            } else {
                out.normals = readNormalVec3(ctx, it->second, usage);
                checkCount(ctx, element, target + ".NORMAL", out.normals.size(),
                           mesh.positions.size());
                checkDeltas(ctx, it->second, usage, out.normals);
            }
        }
        mesh.targets.push_back(std::move(out));
    }
}

std::vector<float> defaultMorphWeights(const Context& ctx, int meshIndex, std::size_t targets) {
    const std::vector<double>& weights =
        ctx.model().meshes[static_cast<std::size_t>(meshIndex)].weights;
    const std::string element = elem("meshes", static_cast<std::size_t>(meshIndex));
    std::vector<float> out(targets, 0.0f);
    if (weights.empty()) return out; // spec 3.7.2.2: weights default to 0
    if (weights.size() != targets) {
        ctx.warn(element, cat("weights has ", weights.size(), " values but the mesh has ", targets,
                              " morph targets; zeros used"));
        return out;
    }
    if (!floats(weights, targets, out.data())) {
        ctx.warn(element, "weights are not finite floats; zeros used");
        std::fill(out.begin(), out.end(), 0.0f);
    }
    return out;
}

void convertRigging(const Context& ctx, const std::vector<PlacedNode>& placed, Scene& scene) {
    linkSkins(ctx, scene);
    if (!needsNodes(ctx)) {
        for (Instance& inst : scene.instances) inst.node = -1;
        return;
    }
    scene.nodes = convertNodes(ctx, placed);
    scene.animations = convertAnimations(ctx, scene.nodes);
}

} // namespace fl::gltf
