#pragma once
// CPU mirror of shaders/overlay_colour.glsl and of the per-mode colouring in
// shaders/overlay_grid.frag.glsl: the tests compute the picture an overlay should draw with these
// and compare it with the pixels the GPU drew.

#include <glm/glm.hpp>

#include <cstdint>

namespace fl::overlay {

/// Colour of an id (64..191 per channel, never black or red), in [0, 1].
glm::vec3 idColour(std::uint32_t id);
/// Sequential ramp for t in [0, 1] (clamped): dark blue, purple, orange, pale yellow.
glm::vec3 ramp(float t);
/// Colour of texels without data (empty cells, outside the map).
inline constexpr glm::vec3 kEmptyColour{0.12f};
/// Colour of wrong texels (errors, differences).
inline constexpr glm::vec3 kErrorColour{1.0f, 0.0f, 0.0f};
/// Colour of equal non-empty cells in the diff mode.
inline constexpr glm::vec3 kSameColour{0.45f};

/// A colour as the 8-bit value a UNORM8 framebuffer stores (round to nearest).
glm::u8vec3 toBytes(glm::vec3 c);

} // namespace fl::overlay
