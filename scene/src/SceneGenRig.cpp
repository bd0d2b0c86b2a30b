// The generated characters' skeletons, skins and walk / wave cycles (SceneGenRig.h).

#include "SceneGenRig.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fl::gen {

namespace {

/// Keys per cycle: LINEAR keys every 1/16 of the period follow the sine closely enough that the
/// swing shows no corners.
constexpr int kKeys = 16;

constexpr const char* kJointNames[kJointCount] = {"hips",  "spine", "head", "arm.L",
                                                  "arm.R", "leg.L", "leg.R"};
constexpr int kParent[kJointCount] = {-1, kHips, kSpine, kSpine, kSpine, kHips, kHips};

glm::vec3 unit(const glm::vec3& v) {
    return v / std::sqrt(glm::dot(v, v));
}

/// The direction a limb leaves its joint at rest (zero for the body's joints): the same
/// geometry buildCharacter tessellates.
glm::vec3 limbDirection(const CharacterDesign& c, int joint) {
    if (joint == kLegL || joint == kLegR) {
        const float side = joint == kLegL ? -1.0f : 1.0f;
        const glm::vec3 foot(side * (0.1f * c.s + c.legSplay * c.hip), -kSink, 0.0f);
        return unit(foot - c.joints[static_cast<std::size_t>(joint)]);
    }
    if (joint == kArmL || joint == kArmR) {
        const int i = joint == kArmL ? 0 : 1;
        const float side = i == 0 ? -1.0f : 1.0f;
        const float swing = (c.waving && i == 1) ? 2.6f : c.armSwing[i];
        return unit({side * std::sin(swing), -std::cos(swing), 0.15f});
    }
    return glm::vec3(0.0f);
}

/// Key k's phase: k == kKeys wraps to exactly phase 0, so the last key equals the first and the
/// cycle loops without a jump.
float phaseOf(int k) {
    return 2.0f * kPi * static_cast<float>(k % kKeys) / static_cast<float>(kKeys);
}

std::vector<float> keyTimes() {
    std::vector<float> t(kKeys + 1);
    for (int k = 0; k <= kKeys; ++k)
        t[static_cast<std::size_t>(k)] =
            kCyclePeriod * static_cast<float>(k) / static_cast<float>(kKeys);
    return t;
}

/// A LINEAR channel of `width` floats a key on `node`'s `path`, key k's values from
/// values(phase of k) appended to the sampler.
template <typename Values>
void linearChannel(Animation& a, int node, Animation::Path path, int width, Values values) {
    Animation::Sampler s;
    s.interpolation = Animation::Interpolation::Linear;
    s.times = keyTimes();
    s.width = width;
    for (int k = 0; k <= kKeys; ++k) values(phaseOf(k), s.values);
    a.channels.push_back({node, path, static_cast<int>(a.samplers.size())});
    a.samplers.push_back(std::move(s));
}

/// A LINEAR rotation channel about `axis` (x or z, unit) by angle(phase): at phase 0 the angle
/// must be 0, the rest pose.
template <typename Angle>
void rotationChannel(Animation& a, int node, const glm::vec3& axis, Angle angle) {
    linearChannel(a, node, Animation::Path::Rotation, 4, [&](float phase, std::vector<float>& out) {
        const float half = 0.5f * angle(phase);
        const float sinHalf = std::sin(half);
        out.insert(out.end(),
                   {axis.x * sinHalf, axis.y * sinHalf, axis.z * sinHalf, std::cos(half)});
    });
}

/// A LINEAR translation channel: rest + offset(phase), offset(0) = 0.
template <typename Offset>
void translationChannel(Animation& a, int node, const glm::vec3& rest, Offset offset) {
    linearChannel(a, node, Animation::Path::Translation, 3,
                  [&](float phase, std::vector<float>& out) {
                      const glm::vec3 p = rest + offset(phase);
                      out.insert(out.end(), {p.x, p.y, p.z});
                  });
}

/// Walking in place: each leg swings about the hip (left and right in opposition), each arm
/// against its leg, and the hips dip at double stance, when both feet are off the vertical,
/// by half of what the swing lifts the feet, so a foot never sinks below its rest height.
void addWalk(Animation& walk, const CharacterDesign& c, int node0) {
    const glm::vec3 x(1.0f, 0.0f, 0.0f);
    const float stride = c.stride;
    const float armStride = 0.6f * stride;
    rotationChannel(walk, node0 + kLegL, x, [=](float p) { return stride * std::sin(p); });
    rotationChannel(walk, node0 + kLegR, x, [=](float p) { return -stride * std::sin(p); });
    rotationChannel(walk, node0 + kArmL, x, [=](float p) { return -armStride * std::sin(p); });
    rotationChannel(walk, node0 + kArmR, x, [=](float p) { return armStride * std::sin(p); });
    const float dip = 0.5f * c.hip * (1.0f - std::cos(stride));
    translationChannel(walk, node0 + kHips, c.joints[kHips], [=](float p) {
        return glm::vec3(0.0f, -dip * 0.5f * (1.0f - std::cos(2.0f * p)), 0.0f);
    });
}

/// Waving: the raised right arm swings about the forward axis at the shoulder, and the head
/// tilts a little with it.
void addWave(Animation& wave, const CharacterDesign& c, int node0) {
    const glm::vec3 z(0.0f, 0.0f, 1.0f);
    const float amplitude = c.waveAmplitude;
    rotationChannel(wave, node0 + kArmR, z, [=](float p) { return amplitude * std::sin(p); });
    rotationChannel(wave, node0 + kHead, z,
                    [=](float p) { return 0.25f * amplitude * std::sin(p); });
}

} // namespace

CharacterDesign designCharacter(const ObjectDesign& d) {
    Rng rng(d.seed);
    CharacterDesign c;
    c.s = d.scale;
    c.hip = 0.8f * c.s;
    c.armSwing[0] = rng.uniform(0.1f, 0.45f);
    c.armSwing[1] = rng.uniform(0.1f, 0.45f);
    c.waving = rng.unit() < 0.5f;
    c.legSplay = rng.uniform(0.02f, 0.12f);
    c.stride = rng.uniform(0.3f, 0.45f);
    c.waveAmplitude = rng.uniform(0.3f, 0.45f);
    const float s = c.s;
    c.joints[kHips] = {0.0f, c.hip, 0.0f};
    c.joints[kSpine] = {0.0f, 1.1f * s, 0.0f};
    c.joints[kHead] = {0.0f, 1.46f * s, 0.0f}; // the neck, below the head sphere at 1.6
    c.joints[kArmL] = {-0.24f * s, 1.4f * s, 0.0f};
    c.joints[kArmR] = {0.24f * s, 1.4f * s, 0.0f};
    c.joints[kLegL] = {-0.1f * s, c.hip, 0.0f};
    c.joints[kLegR] = {0.1f * s, c.hip, 0.0f};
    return c;
}

void rigCharacter(Scene& scene, const ObjectDesign& design, std::size_t instance,
                  const std::vector<RigPart>& parts, CharacterAnimations& animations) {
    const CharacterDesign c = designCharacter(design);
    Instance& inst = scene.instances.at(instance);

    // The root carries the placement (never animated, so a matrix: the very one the instance
    // had); the joints hang under it with their rest offsets and no rotation.
    const int root = static_cast<int>(scene.nodes.size());
    Node rootNode;
    rootNode.name = design.name + ".skeleton";
    rootNode.matrix = inst.world;
    scene.nodes.push_back(rootNode);
    const int node0 = root + 1;
    Skin skin;
    skin.name = design.name;
    for (int j = 0; j < kJointCount; ++j) {
        Node n;
        n.name = design.name + "." + kJointNames[j];
        const glm::vec3 rest = c.joints[static_cast<std::size_t>(j)];
        n.parent = kParent[j] < 0 ? root : node0 + kParent[j];
        n.translation =
            kParent[j] < 0 ? rest : rest - c.joints[static_cast<std::size_t>(kParent[j])];
        scene.nodes.push_back(n);
        skin.joints.push_back(node0 + j);
        // The mesh is in the character's frame: the inverse of the joint's rest place in it.
        glm::mat4 inverseBind(1.0f);
        inverseBind[3] = glm::vec4(-rest, 1.0f);
        skin.inverseBind.push_back(inverseBind);
    }
    inst.skin = static_cast<int>(scene.skins.size());
    scene.skins.push_back(std::move(skin));

    // Limbs blend into their parent over the first part of their length, so the shoulder and
    // hip bend instead of shearing; weights are multiples of 1/64, so the two sum to exactly 1.
    Mesh& mesh = scene.meshes.at(static_cast<std::size_t>(inst.mesh));
    mesh.joints.assign(mesh.positions.size(), glm::uvec4(kSpine, 0, 0, 0));
    mesh.weights.assign(mesh.positions.size(), glm::vec4(1.0f, 0.0f, 0.0f, 0.0f));
    const float blendLength = 0.12f * c.s;
    for (const RigPart& part : parts) {
        const glm::vec3 dir = limbDirection(c, part.joint);
        const glm::vec3 at = c.joints[static_cast<std::size_t>(part.joint)];
        const bool limb = glm::dot(dir, dir) > 0.0f;
        for (std::uint32_t v = part.first; v < part.end; ++v) {
            float parentWeight = 0.0f;
            if (limb) {
                const float along = glm::dot(mesh.positions[v] - at, dir);
                const float t = std::clamp(1.0f - along / blendLength, 0.0f, 1.0f);
                parentWeight = std::round(32.0f * t) / 64.0f; // 0 .. 1/2
            }
            if (parentWeight > 0.0f) {
                mesh.joints[v] = glm::uvec4(part.joint, kParent[part.joint], 0, 0);
                mesh.weights[v] = glm::vec4(1.0f - parentWeight, parentWeight, 0.0f, 0.0f);
            } else {
                mesh.joints[v] = glm::uvec4(part.joint, 0, 0, 0);
                mesh.weights[v] = glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
            }
        }
    }

    if (c.waving)
        addWave(animations.wave, c, node0);
    else
        addWalk(animations.walk, c, node0);
}

void addCharacterAnimations(Scene& scene, CharacterAnimations& animations) {
    animations.walk.name = "walk";
    animations.wave.name = "wave";
    for (Animation* a : {&animations.walk, &animations.wave}) {
        if (a->channels.empty()) continue;
        a->duration = kCyclePeriod;
        scene.animations.push_back(std::move(*a));
    }
}

} // namespace fl::gen
