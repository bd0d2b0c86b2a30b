// Node graph, transforms, scene traversal, cameras and the KHR_lights_punctual light.
// tinygltf accepts child indices that loop back (a cycle would make a naive traversal recurse
// forever) and nodes with two parents (instanced twice, against the spec), so the graph is
// checked as a whole before anything walks it; the walk itself is iterative so that a deep but
// valid hierarchy cannot overflow the stack.

#include "GltfInternal.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace fl::gltf {
namespace {

bool allFinite(const std::vector<double>& values) {
    return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

bool allFinite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

/// A node property array of `expected` finite numbers, or empty (= absent).
void checkArray(const Context& ctx, const std::string& element, std::string_view name,
                const std::vector<double>& values, std::size_t expected) {
    if (values.empty()) return;
    if (values.size() != expected)
        ctx.fail(element, cat(name, " has ", values.size(), " values (expected ", expected, ")"));
    if (!allFinite(values)) ctx.fail(element, cat(name, " is not finite"));
}

glm::mat4 localTransform(const Context& ctx, std::size_t index) {
    const tinygltf::Node& node = ctx.model().nodes[index];
    const std::string element = elem("nodes", index);
    if (!node.matrix.empty()) {
        checkArray(ctx, element, "matrix", node.matrix, 16);
        glm::dmat4 m;
        std::copy(node.matrix.begin(), node.matrix.end(), glm::value_ptr(m)); // column-major
        return glm::mat4(m);
    }
    checkArray(ctx, element, "translation", node.translation, 3);
    checkArray(ctx, element, "rotation", node.rotation, 4);
    checkArray(ctx, element, "scale", node.scale, 3);
    glm::dmat4 m(1.0);
    if (!node.translation.empty())
        m[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1.0);
    if (!node.rotation.empty()) {
        const auto& r = node.rotation; // glTF order x, y, z, w
        glm::dquat q(r[3], r[0], r[1], r[2]);
        const double len = glm::length(q);
        if (len > 1e-12 && std::isfinite(len))
            m *= glm::mat4_cast(q / len);
        else
            ctx.warn(element, "zero rotation quaternion replaced by identity");
    }
    if (!node.scale.empty())
        m = glm::scale(m, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
    return glm::mat4(m);
}

/// parents[i] = the node listing i as a child, or -1; fails on bad child indices, on a node with
/// two parents and on a node that is its own child (longer cycles: checkAcyclic).
std::vector<int> checkedParents(const Context& ctx) {
    const auto& nodes = ctx.model().nodes;
    if (nodes.size() > kMaxNodes)
        ctx.fail("nodes", cat("absurd node count ", nodes.size(), " (limit ", kMaxNodes, ")"));
    std::vector<int> parents(nodes.size(), -1);
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        const std::string element = elem("nodes", i);
        for (std::size_t k = 0; k < nodes[i].children.size(); ++k) {
            const int child = nodes[i].children[k];
            ctx.lookup(nodes, child, cat(element, ".children[", k, "]"), "node", "nodes");
            const auto c = static_cast<std::size_t>(child);
            if (c == i) ctx.fail(element, "node cycle: node is its own child");
            if (parents[c] != -1)
                ctx.fail(elem("nodes", c),
                         cat("node has two parents: nodes[", parents[c], "] and nodes[", i, "]"));
            parents[c] = static_cast<int>(i);
        }
    }
    return parents;
}

/// With at most one parent per node, a cycle in the child graph is a cycle in the parent
/// chain; each chain is walked once (0 = unseen, 1 = on the current walk, 2 = done).
void checkAcyclic(const Context& ctx, const std::vector<int>& parents) {
    std::vector<char> state(parents.size(), 0);
    std::vector<int> walk;
    for (std::size_t start = 0; start < parents.size(); ++start) {
        walk.clear();
        int cur = static_cast<int>(start);
        while (cur != -1 && state[static_cast<std::size_t>(cur)] == 0) {
            state[static_cast<std::size_t>(cur)] = 1;
            walk.push_back(cur);
            cur = parents[static_cast<std::size_t>(cur)];
        }
        if (cur != -1 && state[static_cast<std::size_t>(cur)] == 1) {
            // walk ends ... cur's child, cur's parent chain returns to cur: print parent->child.
            std::string loop = elem("nodes", static_cast<std::size_t>(cur));
            const auto from = std::find(walk.begin(), walk.end(), cur);
            int shown = 0;
            for (auto it = walk.end(); it != from; --it, ++shown) {
                if (shown == 8) { // a million-node loop needs no million-entry message
                    loop += " -> ...";
                    break;
                }
                loop += cat(" -> nodes[", *(it - 1), "]");
            }
            ctx.fail(elem("nodes", static_cast<std::size_t>(cur)), "node cycle: " + loop);
        }
        for (int n : walk) state[static_cast<std::size_t>(n)] = 2;
    }
}

/// The root nodes to draw: the default scene, else scene 0, else every node without a parent.
std::vector<int> sceneRoots(const Context& ctx, const std::vector<int>& parents) {
    const auto& model = ctx.model();
    std::vector<int> roots;
    if (model.scenes.empty() && model.defaultScene < 0) {
        for (std::size_t i = 0; i < parents.size(); ++i)
            if (parents[i] == -1) roots.push_back(static_cast<int>(i));
        return roots;
    }
    const int sceneIndex = model.defaultScene >= 0 ? model.defaultScene : 0;
    const auto& scene = ctx.lookup(model.scenes, sceneIndex, "scene", "scene", "scenes");
    const std::string element = elem("scenes", static_cast<std::size_t>(sceneIndex));
    std::vector<char> listed(parents.size(), 0);
    for (std::size_t k = 0; k < scene.nodes.size(); ++k) {
        const std::string ref = cat(element, ".nodes[", k, "]");
        const int n = scene.nodes[k];
        ctx.lookup(model.nodes, n, ref, "node", "nodes");
        const auto u = static_cast<std::size_t>(n);
        if (parents[u] != -1)
            ctx.fail(ref,
                     cat("nodes[", n, "] is not a root node (child of nodes[", parents[u], "])"));
        if (listed[u]) {
            ctx.warn(ref, cat("nodes[", n, "] listed twice; drawn once"));
            continue;
        }
        listed[u] = 1;
        roots.push_back(n);
    }
    return roots;
}

/// Index of the KHR_lights_punctual light a node places, or -1.
int nodeLight(const Context& ctx, std::size_t nodeIndex) {
    const tinygltf::Node& node = ctx.model().nodes[nodeIndex];
    const auto it = node.extensions.find("KHR_lights_punctual");
    if (it == node.extensions.end()) return -1;
    const std::string element = elem("nodes", nodeIndex) + ".extensions.KHR_lights_punctual";
    const tinygltf::Value& ext = it->second;
    if (!ext.IsObject() || !ext.Has("light") || !ext.Get("light").IsNumber())
        ctx.fail(element, "no light index");
    // Read as double: Value::GetNumberAsInt casts out-of-range doubles to int (UB).
    const double light = ext.Get("light").GetNumberAsDouble();
    const auto count = ctx.model().lights.size();
    if (!(light >= 0.0 && light < static_cast<double>(count)) || light != std::floor(light))
        ctx.fail(element, cat("light ", light, " does not exist (", count, " in lights)"));
    return static_cast<int>(light);
}

std::optional<Camera> convertCamera(const Context& ctx, const PlacedNode& placed,
                                    const geom::Aabb& bounds) {
    const auto& model = ctx.model();
    const std::string nodeElement = elem("nodes", static_cast<std::size_t>(placed.node));
    const int index = model.nodes[static_cast<std::size_t>(placed.node)].camera;
    const auto& cam = ctx.lookup(model.cameras, index, nodeElement, "camera", "cameras");
    const std::string element = elem("cameras", static_cast<std::size_t>(index));
    if (cam.type != "perspective") {
        // Every shadow pass assumes a perspective eye; an approximation would mislead.
        ctx.warn(element, cat(cam.type, " camera skipped (only perspective cameras are used)"));
        return std::nullopt;
    }
    const auto& p = cam.perspective;
    if (!(p.yfov > 0.0 && p.yfov < glm::pi<double>()) || !(p.znear > 0.0) ||
        !std::isfinite(p.znear) ||
        !(p.zfar == 0.0 || (p.zfar > p.znear && std::isfinite(p.zfar)))) {
        ctx.warn(element, cat("invalid perspective (yfov ", p.yfov, ", znear ", p.znear, ", zfar ",
                              p.zfar, "); camera skipped"));
        return std::nullopt;
    }
    const glm::mat4 view = glm::inverse(placed.world);
    if (!allFinite(view) || std::abs(glm::determinant(placed.world)) < 1e-20f) {
        ctx.warn(element, cat("placed by ", nodeElement, " with a singular transform; skipped"));
        return std::nullopt;
    }
    if (!inWorld(glm::vec3(placed.world[3]))) {
        ctx.warn(element, cat("placed by ", nodeElement, " beyond ", kMaxWorldCoordinate,
                              " from the origin; skipped"));
        return std::nullopt;
    }
    Camera out;
    out.view = view;
    out.yfov = static_cast<float>(p.yfov);
    out.znear = static_cast<float>(p.znear);
    if (p.aspectRatio > 0.0 && std::isfinite(p.aspectRatio))
        out.aspectRatio = static_cast<float>(p.aspectRatio);
    if (p.zfar > 0.0) {
        out.zfar = static_cast<float>(p.zfar);
    } else {
        // Infinite far plane: reach past the far side of the scene with room to move around.
        const glm::vec3 eye(placed.world[3]);
        const float reach = glm::length(eye - bounds.center()) + bounds.radius();
        out.zfar = std::max(2.0f * reach, 2.0f * out.znear);
    }
    // Finite doubles can still overflow a float, or round zfar onto znear.
    if (!std::isfinite(out.znear) || !std::isfinite(out.zfar) || !(out.zfar > out.znear)) {
        ctx.warn(element, cat("znear ", p.znear, " and zfar ", p.zfar,
                              " do not fit a float projection; camera skipped"));
        return std::nullopt;
    }
    out.name =
        !cam.name.empty() ? cam.name : model.nodes[static_cast<std::size_t>(placed.node)].name;
    return out;
}

/// extras.radius of a light, if it is a positive number.
std::optional<float> extrasRadius(const Context& ctx, const tinygltf::Light& light,
                                  const std::string& element) {
    if (!light.extras.IsObject() || !light.extras.Has("radius")) return std::nullopt;
    const tinygltf::Value& v = light.extras.Get("radius");
    const double r = v.IsNumber() ? v.GetNumberAsDouble() : -1.0;
    if (r >= 0.0 && r <= kMaxWorldCoordinate) return static_cast<float>(r);
    ctx.warn(element + ".extras.radius",
             cat("not a number in [0, ", kMaxWorldCoordinate, "]; ignored"));
    return std::nullopt;
}

float lightRadius(const Context& ctx, const tinygltf::Light& light, const std::string& element,
                  const geom::Aabb& bounds) {
    if (const auto& r = ctx.options().lightRadius) {
        if (std::isfinite(*r) && *r >= 0.0f) return *r;
        ctx.warn(element, cat("light radius override ", *r, " ignored (must be finite and >= 0)"));
    }
    if (auto r = extrasRadius(ctx, light, element)) return *r;
    const float sceneRadius = bounds.radius();
    return sceneRadius > 0.0f && std::isfinite(sceneRadius) ? kDefaultLightSize * sceneRadius
                                                            : Light{}.radius;
}

std::optional<Light> makeLight(const Context& ctx, const PlacedNode& placed, int index,
                               const geom::Aabb& bounds) {
    const tinygltf::Light& src = ctx.model().lights[static_cast<std::size_t>(index)];
    const std::string element = cat("extensions.KHR_lights_punctual.lights[", index, "]");
    Light light;
    if (src.type == "directional")
        light.type = Light::Type::Directional;
    else if (src.type == "point")
        light.type = Light::Type::Point;
    else if (src.type == "spot")
        light.type = Light::Type::Spot;
    else {
        ctx.warn(element, cat("unknown light type '", src.type, "'; light skipped"));
        return std::nullopt;
    }
    light.position = glm::vec3(placed.world * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    const glm::dvec3 dir = glm::dmat3(placed.world) * glm::dvec3(0.0, 0.0, -1.0);
    const double len = glm::length(dir);
    if (!allFinite(placed.world) || !(len > 1e-20) || !std::isfinite(len) ||
        !inWorld(light.position)) {
        ctx.warn(element, cat("placed by nodes[", placed.node,
                              "] with an unusable transform; "
                              "light skipped"));
        return std::nullopt;
    }
    light.direction = glm::vec3(dir / len);
    // Checked as floats: a finite double such as 1e300 is infinite as a float.
    const glm::vec3 color = src.color.size() == 3
                                ? glm::vec3(src.color[0], src.color[1], src.color[2])
                                : glm::vec3(std::nanf(""));
    if (std::isfinite(color.r) && std::isfinite(color.g) && std::isfinite(color.b))
        light.color = glm::max(color, 0.0f);
    else if (!src.color.empty())
        ctx.warn(element, "color is not 3 finite numbers; white used");
    if (const auto intensity = static_cast<float>(src.intensity);
        std::isfinite(intensity) && intensity >= 0.0f)
        light.intensity = intensity;
    else
        ctx.warn(element, "intensity is not a finite number >= 0; 1 used");
    const double cone = src.spot.outerConeAngle;
    if (light.type == Light::Type::Spot) {
        if (cone > 0.0 && cone <= glm::half_pi<double>())
            light.outerConeAngle = static_cast<float>(cone);
        else
            ctx.warn(element, "spot.outerConeAngle outside (0, pi/2]; 45 degrees used");
    }
    light.radius = lightRadius(ctx, src, element, bounds);
    light.name = src.name;
    return light;
}

} // namespace

std::vector<PlacedNode> placeSceneNodes(const Context& ctx) {
    const std::vector<int> parents = checkedParents(ctx);
    checkAcyclic(ctx, parents);
    const std::vector<int> roots = sceneRoots(ctx, parents);

    std::vector<PlacedNode> placed;
    std::vector<PlacedNode> stack;
    for (auto it = roots.rbegin(); it != roots.rend(); ++it)
        stack.push_back({*it, glm::mat4(1.0f)});
    while (!stack.empty()) {
        PlacedNode top = stack.back();
        stack.pop_back();
        const auto index = static_cast<std::size_t>(top.node);
        top.world = top.world * localTransform(ctx, index); // stack holds the parent's world
        placed.push_back(top);
        const auto& children = ctx.model().nodes[index].children;
        for (auto it = children.rbegin(); it != children.rend(); ++it)
            stack.push_back({*it, top.world});
    }
    return placed;
}

std::vector<Camera> convertCameras(const Context& ctx, const std::vector<PlacedNode>& placed,
                                   const geom::Aabb& bounds) {
    std::vector<Camera> cameras;
    for (const PlacedNode& p : placed) {
        if (ctx.model().nodes[static_cast<std::size_t>(p.node)].camera == -1) continue;
        if (auto camera = convertCamera(ctx, p, bounds)) cameras.push_back(std::move(*camera));
    }
    return cameras;
}

std::optional<Light> convertLight(const Context& ctx, const std::vector<PlacedNode>& placed,
                                  const geom::Aabb& bounds) {
    for (const PlacedNode& p : placed) {
        const int index = nodeLight(ctx, static_cast<std::size_t>(p.node));
        if (index < 0) continue;
        if (auto light = makeLight(ctx, p, index, bounds)) return light;
    }
    return std::nullopt;
}

} // namespace fl::gltf
