#pragma once
// The surfaces pass's packed targets and how to read them: the CPU twin of
// shaders/surface_decode.glsl (keep the two in step). A pixel's world position is not stored;
// it comes back from the reversed-Z depth through the inverse of the matrix that wrote it.
// Normals are octahedral (Cigolle et al., "A Survey of Efficient Representations for
// Independent Unit Vectors", JCGT 2014) and the base colour is sRGB-encoded in 8 bits.

#include <glm/glm.hpp>

namespace fl::surface {

/// The depth of a pixel where nothing was drawn: reversed Z, so the far plane is 0.
inline constexpr float kBackgroundDepth = 0.0f;

/// `proj * view` with depth reversed into [0, 1] (near 1, far 0), for glClipControl's
/// GL_ZERO_TO_ONE. Built in double from a GL projection (depth in [-1, 1]): float keeps about
/// the same relative precision at every distance this way, where a [-1, 1] depth loses it with
/// distance from the near plane.
glm::mat4 reversedViewProj(const glm::mat4& proj, const glm::mat4& view);
/// The inverse of reversedViewProj(proj, view), computed in double.
glm::mat4 inverseReversedViewProj(const glm::mat4& proj, const glm::mat4& view);

/// The world position at pixel `pixel` (GL window coordinates, row 0 at the bottom) of a
/// `size` frame whose depth target holds `depth`: (xyz, 1), or (0, 0, 0, 0) for background.
glm::vec4 position(float depth, glm::ivec2 pixel, glm::ivec2 size,
                   const glm::mat4& inverseViewProj);

/// A unit vector as two numbers in [-1, 1] (octahedral map).
glm::vec2 octEncode(glm::vec3 n);
/// The unit vector of octEncode's two numbers.
glm::vec3 octDecode(glm::vec2 e);

/// The point every shadow-map lookup of a pixel starts from (surfaceLookupPoint() in
/// surface_lookup.glsl): its position lifted along its shading normal by its lift (the lift
/// target, TerminatorLift.h).
inline glm::vec3 lookupPoint(glm::vec3 world, float lift, glm::vec3 shadingNormal) {
    return lift > 0.0f ? world + lift * shadingNormal : world;
}

/// The sRGB transfer function and its inverse, per channel, for values in [0, 1].
glm::vec3 linearToSrgb(glm::vec3 c);
glm::vec3 srgbToLinear(glm::vec3 c);

} // namespace fl::surface
