// Animations: each channel that drives a node's translation, rotation, scale or morph weights,
// and the samplers those channels use. A sampler's output layout depends on the channel (VEC3,
// quaternion, or one weight per morph target of the node's mesh), so samplers are read through
// the channels that use them; samplers no kept channel uses are not read (nothing would sample
// them), and a sampler two channels read in different layouts is rejected.

#include "GltfInternal.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>

namespace fl::gltf {
namespace {

using Path = Animation::Path;
using Interpolation = Animation::Interpolation;

std::optional<Path> parsePath(const std::string& path) {
    for (std::size_t i = 0; i < Animation::kPathNames.size(); ++i)
        if (path == Animation::kPathNames[i]) return static_cast<Path>(i);
    return std::nullopt;
}

std::string_view pathName(Path path) {
    return Animation::kPathNames[static_cast<std::size_t>(path)];
}

/// The output layout a channel reads: translation and scale share one (VEC3 FLOAT).
struct Layout {
    int type = TINYGLTF_TYPE_VEC3; // accessor type of the output
    int width = 3;                 // floats per key value
    bool operator==(const Layout&) const = default;
};

Layout layoutOf(Path path, std::size_t targets) {
    switch (path) {
    case Path::Rotation:
        return {TINYGLTF_TYPE_VEC4, 4};
    case Path::Weights:
        return {TINYGLTF_TYPE_SCALAR, static_cast<int>(targets)};
    default:
        return {TINYGLTF_TYPE_VEC3, 3};
    }
}

Interpolation interpolation(const Context& ctx, const std::string& element,
                            const std::string& name) {
    for (std::size_t i = 0; i < Animation::kInterpolationNames.size(); ++i)
        if (name == Animation::kInterpolationNames[i]) return static_cast<Interpolation>(i);
    ctx.warn(element, cat("unknown interpolation '", name, "'; LINEAR used"));
    return Interpolation::Linear;
}

/// Key times must be finite, >= 0 and strictly increasing (spec 3.11): sampling searches them.
void checkTimes(const Context& ctx, const std::string& element, const std::vector<float>& t) {
    if (t.empty()) ctx.fail(element, "input has no keys");
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (!std::isfinite(t[i]))
            ctx.fail(element, cat("input time ", i, " is not finite (", t[i], ")"));
        if (t[i] < 0.0f) ctx.fail(element, cat("input time ", i, " is negative (", t[i], ")"));
        if (i > 0 && !(t[i] > t[i - 1]))
            ctx.fail(element, cat("input times are not strictly increasing: time ", i, " (", t[i],
                                  ") after time ", i - 1, " (", t[i - 1], ")"));
    }
}

/// Normalises the quaternion values (not the CUBICSPLINE tangents); zero ones become identity.
void normaliseRotations(const Context& ctx, const std::string& element,
                        Animation::Sampler& sampler) {
    const std::size_t perKey = sampler.interpolation == Interpolation::CubicSpline ? 3 : 1;
    const std::size_t valueAt = perKey == 3 ? 1 : 0; // in-tangent, value, out-tangent
    std::size_t zero = 0;
    for (std::size_t k = 0; k < sampler.times.size(); ++k) {
        float* q = &sampler.values[(k * perKey + valueAt) * 4];
        const double len = glm::length(glm::dvec4(q[0], q[1], q[2], q[3]));
        if (!(len > 1e-12)) {
            q[0] = q[1] = q[2] = 0.0f;
            q[3] = 1.0f;
            ++zero;
            continue;
        }
        for (int c = 0; c < 4; ++c) q[c] = static_cast<float>(q[c] / len);
    }
    if (zero > 0) ctx.warn(element, cat(zero, " zero rotation key(s) replaced by identity"));
}

Animation::Sampler readSampler(const Context& ctx, const tinygltf::AnimationSampler& src,
                               const std::string& element, Path path, Layout layout) {
    Animation::Sampler out;
    out.interpolation = interpolation(ctx, element, src.interpolation);
    out.width = layout.width;
    out.times =
        readAnimationFloats(ctx, src.input, element + ".input", TINYGLTF_TYPE_SCALAR, false);
    checkTimes(ctx, element, out.times);
    // Rotations and weights may be normalized integers (spec 3.11); translations and scales not.
    const bool integers = path == Path::Rotation || path == Path::Weights;
    out.values = readAnimationFloats(ctx, src.output, element + ".output", layout.type, integers);

    const std::size_t perKey = out.interpolation == Interpolation::CubicSpline ? 3 : 1;
    const std::size_t components =
        layout.type == TINYGLTF_TYPE_SCALAR ? 1 : static_cast<std::size_t>(layout.width);
    const std::size_t elements = out.values.size() / components;
    const std::size_t expected =
        out.times.size() * perKey *
        (path == Path::Weights ? static_cast<std::size_t>(layout.width) : 1);
    if (elements != expected) {
        std::string need = cat(out.times.size(), " keys");
        if (perKey == 3) need += " x 3 (CUBICSPLINE)";
        if (path == Path::Weights) need += cat(" x ", layout.width, " morph targets");
        ctx.fail(element, cat("output has ", elements, " elements but ", need, " need ", expected));
    }
    for (std::size_t i = 0; i < out.values.size(); ++i)
        if (!std::isfinite(out.values[i]))
            ctx.fail(element, cat("output element ", i / components, " is not finite"));
    if (path == Path::Rotation) normaliseRotations(ctx, element, out);
    return out;
}

/// Replaces a node's matrix by the translation, rotation and scale it is made of, so that a
/// channel can drive one of them (a targeted node must not have a matrix, spec 3.11). Matrices
/// that are not T * R * S (shear, projection, zero scale) cannot be animated that way.
void decomposeMatrix(const Context& ctx, std::size_t index, Node& node, const std::string& by) {
    const glm::mat4& m = *node.matrix;
    const std::string element = elem("nodes", index);
    glm::vec3 axis[3], scale;
    for (int c = 0; c < 3; ++c) {
        scale[c] = glm::length(glm::vec3(m[c]));
        axis[c] = glm::vec3(m[c]) / scale[c];
    }
    bool ok = m[0][3] == 0.0f && m[1][3] == 0.0f && m[2][3] == 0.0f && m[3][3] == 1.0f;
    for (int c = 0; c < 3; ++c) ok = ok && scale[c] > 1e-12f && std::isfinite(scale[c]);
    constexpr float kOrthogonal = 1e-3f; // float matrices of exporters are not exactly so
    ok = ok && std::abs(glm::dot(axis[0], axis[1])) < kOrthogonal &&
         std::abs(glm::dot(axis[0], axis[2])) < kOrthogonal &&
         std::abs(glm::dot(axis[1], axis[2])) < kOrthogonal;
    if (!ok)
        ctx.fail(element, cat("animated by ", by,
                              " but its matrix is not a translation, rotation and scale "
                              "(sheared, projective or singular)"));
    if (glm::dot(glm::cross(axis[0], axis[1]), axis[2]) < 0.0f) { // a mirror: negative scale
        scale.x = -scale.x;
        axis[0] = -axis[0];
    }
    node.translation = glm::vec3(m[3]);
    node.rotation = glm::normalize(glm::quat_cast(glm::mat3(axis[0], axis[1], axis[2])));
    node.scale = scale;
    node.matrix.reset();
    ctx.warn(element, cat("matrix replaced by translation, rotation and scale because ", by,
                          " animates it"));
}

Animation convertAnimation(const Context& ctx, std::size_t index, std::vector<Node>& nodes,
                           MorphTargetCounts& targetCounts) {
    const tinygltf::Animation& src = ctx.model().animations[index];
    const std::string element = elem("animations", index);
    Animation out;
    out.name = src.name;
    struct Use {
        int sampler;   // index into out.samplers
        Layout layout; // as the first channel read it
        std::string by;
    };
    std::map<int, Use> used;                 // file sampler -> its use
    std::set<std::pair<int, Path>> targeted; // (node, path) already driven
    for (std::size_t c = 0; c < src.channels.size(); ++c) {
        const tinygltf::AnimationChannel& ch = src.channels[c];
        const std::string channel = cat(element, elem(".channels", c));
        if (ch.target_node == -1) {
            // An extension (KHR_animation_pointer) may target something other than a node.
            ctx.warn(channel, "no target node; channel skipped");
            continue;
        }
        ctx.lookup(ctx.model().nodes, ch.target_node, channel + ".target.node", "node", "nodes");
        const auto node = static_cast<std::size_t>(ch.target_node);
        const std::optional<Path> path = parsePath(ch.target_path);
        if (!path) {
            ctx.warn(channel, cat("target path '", ch.target_path,
                                  "' is not translation, rotation, scale or weights; "
                                  "channel skipped"));
            continue;
        }
        const auto& sampler = ctx.lookup(src.samplers, ch.sampler, channel + ".sampler", "sampler",
                                         element + ".samplers");
        std::size_t targets = 0;
        if (*path == Path::Weights) {
            targets = targetCounts(ctx.model().nodes[node].mesh);
            if (targets == 0) {
                ctx.warn(channel, cat("weights of nodes[", node,
                                      "], which has no mesh with morph targets; channel skipped"));
                continue;
            }
        }
        if (!targeted.insert({ch.target_node, *path}).second) {
            ctx.warn(channel, cat("nodes[", node, "].", pathName(*path),
                                  " is already animated by an earlier channel; channel skipped"));
            continue;
        }
        const Layout layout = layoutOf(*path, targets);
        auto it = used.find(ch.sampler);
        if (it == used.end()) {
            const std::string samplerElement =
                cat(element, elem(".samplers", static_cast<std::size_t>(ch.sampler)));
            out.samplers.push_back(readSampler(ctx, sampler, samplerElement, *path, layout));
            it = used.emplace(ch.sampler,
                              Use{static_cast<int>(out.samplers.size() - 1), layout, channel})
                     .first;
        } else if (!(it->second.layout == layout)) {
            ctx.fail(channel, cat("samplers[", ch.sampler, "] is read as ", pathName(*path),
                                  " here but differently by ", it->second.by));
        }
        if (*path != Path::Weights && nodes[node].matrix)
            decomposeMatrix(ctx, node, nodes[node], channel);
        out.channels.push_back({ch.target_node, *path, it->second.sampler});
    }
    for (const Animation::Sampler& s : out.samplers)
        out.duration = std::max(out.duration, s.times.back());
    return out;
}

} // namespace

std::vector<Animation> convertAnimations(const Context& ctx, std::vector<Node>& nodes) {
    MorphTargetCounts targetCounts(ctx);
    std::vector<Animation> out;
    out.reserve(ctx.model().animations.size());
    for (std::size_t a = 0; a < ctx.model().animations.size(); ++a)
        out.push_back(convertAnimation(ctx, a, nodes, targetCounts));
    return out;
}

} // namespace fl::gltf
