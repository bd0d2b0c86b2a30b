#pragma once
// A visible shadow for any model: most glTF files are one object with no ground, so
// its shadow falls on nothing. `--ground auto` (the default) adds a plain ground plane under a
// scene that has no surface under it to receive the shadow; a scene with its own ground or
// terrain is left as it is.
//
// The rule (auto): look down on the scene's footprint through a 32 x 32 grid of cells. A cell
// is covered when the lowest upward-facing surface above it (a triangle whose normal points up
// by at least 45 degrees, or either way for a double-sided material) lies in the bottom fifth of
// the scene's height. The scene has a ground when at least half of the cells are covered: a
// floor, a terrain or a plinth; a model standing on nothing covers few (its lowest upward faces
// are high up, or small).

#include <scene/Scene.h>

#include <array>
#include <optional>
#include <string_view>
#include <vector>

namespace fl {

enum class GroundMode { Auto, On, Off };
/// The modes' names, in GroundMode's order: what --ground and capture scripts accept.
inline constexpr std::array<std::string_view, 3> kGroundModeNames = {"auto", "on", "off"};
/// The mode named `text` (kGroundModeNames); nullopt for anything else.
std::optional<GroundMode> parseGroundMode(std::string_view text);

/// The share of the footprint's cells covered by a low upward-facing surface (the rule above),
/// in [0, 1].
double groundCoverage(const Scene& scene);
/// Whether the scene has a ground of its own: groundCoverage >= 0.5.
bool hasGround(const Scene& scene);

/// Adds the ground plane to `scene` and recomputes its bounds: a neutral grey square at the
/// bottom of the bounds, centred under them, reaching past the footprint by 0.75 x the scene's
/// height (a shadow cast from 53 degrees above the horizon or higher lands on it whole; the
/// default light stands at 58), as one instance with its own object id and material named
/// "floodlight ground". Scene::addedGround names the instance. The bottom of the bounds is the
/// lowest vertex (Scene::bounds is tight), so the ground touches what stands on it. Throws
/// std::invalid_argument for bounds that are empty or not finite (the loader refuses those).
void addGround(Scene& scene);

/// What the first view of a scene with an added ground frames: the model's
/// vertices (every instance's but the ground's, at rest) and their shadows on the ground's plane,
/// each cast from `light` (along its direction for a directional light) and kept on the ground's
/// square; with the ground's four corners when a vertex is level with or above a point light
/// (that shadow runs off the ground). Their hull holds the model and its shadow. Empty for a
/// scene without an added ground: its view frames all of it, as before.
/// Skinned and morphed instances count where they are drawn: posed in `pose` when given, else
/// at rest (their mesh positions are not where they appear; a skinned model was cut off).
std::vector<glm::vec3> modelAndShadowPoints(const Scene& scene, const Light& light,
                                            const struct Pose* pose = nullptr);

/// Applies `mode`: adds the ground for On, and for Auto when the scene has none. Returns
/// whether it added one.
bool applyGround(Scene& scene, GroundMode mode);

} // namespace fl
