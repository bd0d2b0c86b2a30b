#pragma once
// The shadow map's receiver target and how to read it: the CPU twin of
// shaders/shadow_map_decode.glsl (keep the two in step). A texel's world position is not stored;
// the target keeps the light's unbiased NDC depth (R32F, 4 bytes a texel instead of an RGBA32F
// position's 16) and the position comes back through the map's matrices. The unbiased depth is
// kept because the map's own depth carries the depth bias, which moves a receiver along the
// light's ray by up to slopeBias texels' worth of its depth slope: far at grazing angles.

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>

namespace fl::shadowmap {

/// The receiver target's value where the light sees nothing (the clear value; NDC depth is in
/// [-1, 1]).
inline constexpr float kNoReceiver = -4.0f;

/// A silhouette seed's w: the tag of texel (x, y) of a map `width` texels wide (the bits of 1.0
/// plus its row-major index; a normal float in [1, 256) for maps up to 8192²). The same as
/// mapSeedTag() in GLSL.
float seedTag(int x, int y, int width);
/// The texel index (y * width + x) of a seed tag: seedTag's inverse.
std::uint32_t seedIndex(float tag);

/// The inverse of a provider's warp (light clip -> map clip) on x, y and w, computed in double:
/// both providers' warps leave z out of x, y and w (TSM's N_T is a 2D projective map with its z
/// row zero). Throws std::invalid_argument for a warp that mixes z in or is singular.
glm::mat3 unwarp(const glm::mat4& warp);
/// The inverse of the light's view-projection, computed in double.
glm::mat4 inverseLightViewProj(const glm::mat4& lightViewProj);

/// The light's clip-space ray (x, y, w) through map coordinate `tc` (texels; texel t's centre
/// is t + 0.5) of a `size` x `size` map. The same operations as mapClipRay() in GLSL.
glm::vec3 clipRay(glm::vec2 tc, int size, const glm::mat3& unwarp);

/// The world position at map coordinate `tc` and the light's NDC depth `depth`. The same
/// operations as mapUnproject() in GLSL.
glm::vec3 unproject(glm::vec2 tc, float depth, int size, const glm::mat3& unwarp,
                    const glm::mat4& inverseLightViewProj);

/// The world position texel `texel` of a `size` x `size` map sees: (xyz, 1), or (0, 0, 0, 0)
/// where its receiver depth is kNoReceiver. The same operations as mapReceiver() in GLSL.
glm::vec4 receiverPosition(float depth, glm::ivec2 texel, int size, const glm::mat3& unwarp,
                           const glm::mat4& inverseLightViewProj);

/// The map coordinates of `world` for a map made with `lightViewProj` and `warp`: xy on the map
/// in [0, 1]², z the light's depth in [0, 1]; nullopt behind the light. Not clipped to the map
/// (shadowCoordWith() in shadow_lookup.glsl is this and the test that uvz lies in [0, 1]³).
std::optional<glm::vec3> mapCoord(const glm::mat4& lightViewProj, const glm::mat4& warp,
                                  glm::vec3 world);

} // namespace fl::shadowmap
