#pragma once
// Private: the generated characters' skeletons and animations (the thesis' fantasy scene has
// four animated characters). A character's shape is drawn once (CharacterDesign), tessellated by
// buildCharacter, which reports which vertices each body part made; rigCharacter then gives the
// mesh a skin on a seven-joint skeleton and adds the character's channels to the scene's "walk"
// or "wave" animation. Every cycle's key at t = 0 is the rest pose, so a scene shown at time 0
// looks exactly as it did before the characters were animated.

#include "SceneGenObjects.h"

#include <array>
#include <vector>

namespace fl::gen {

/// The skeleton's joints in skin order: hips -> spine -> head and arms, hips -> legs.
enum CharacterJoint : int { kHips, kSpine, kHead, kArmL, kArmR, kLegL, kLegR, kJointCount };

/// One loop of every cycle, seconds.
inline constexpr float kCyclePeriod = 1.0f;

/// Everything random about a character, drawn in a fixed order from its seed: first its shape
/// (what buildCharacter always drew, so the meshes did not change when the rig came), then its
/// motion.
struct CharacterDesign {
    float s = 1.0f;             // overall scale
    float hip = 0.8f;           // hip height
    float armSwing[2] = {};     // rest angle of each arm away from the body, radians
    bool waving = false;        // the right arm is raised and waves (else the character walks)
    float legSplay = 0.0f;      // how far the feet stand apart
    float stride = 0.4f;        // walk: the legs' swing each way, radians
    float waveAmplitude = 0.3f; // wave: the raised arm's swing each way, radians
    /// Rest position of each joint in the character's frame (origin on the ground, +Y up).
    std::array<glm::vec3, kJointCount> joints{};
};
[[nodiscard]] CharacterDesign designCharacter(const ObjectDesign& d);

/// Vertices [first, end) of a character's mesh belong to the body part carried by `joint`.
struct RigPart {
    std::uint32_t first = 0;
    std::uint32_t end = 0;
    int joint = kHips;
};

/// The scene's character animations, filled character by character.
struct CharacterAnimations {
    Animation walk;
    Animation wave;
};

/// Skins instance `instance` (a character built by buildCharacter, whose `parts` it reported):
/// adds the skeleton's nodes under a root placed like the instance, the skin (inverse binds from
/// the rest pose), the mesh's joints and weights (limbs blend into their parent joint near the
/// joint), and the character's channels to `animations`.
void rigCharacter(Scene& scene, const ObjectDesign& design, std::size_t instance,
                  const std::vector<RigPart>& parts, CharacterAnimations& animations);

/// Moves the animations that have channels into the scene ("walk", then "wave").
void addCharacterAnimations(Scene& scene, CharacterAnimations& animations);

} // namespace fl::gen
