#pragma once
// Alpha cut-outs on the CPU: whether a point of a triangle blocks light, decided exactly as the GL
// passes decide it (shaders/alpha_coverage.glsl). The ray-traced truth and the tests' ray caster
// ask it, so that they see the same leaves and fences as the shadow maps.
//
// A point's alpha is the material's base-colour alpha x the base-colour texture's alpha (level 0,
// bilinear, REPEAT, as GL samples it) x COLOR_0's alpha, interpolated over the triangle. It
// blocks light when alpha >= shadowCutoff(material) (Scene.h: MASK's cutoff, 0.5 for BLEND);
// OPAQUE materials block everywhere.

#include <scene/Scene.h>

#include <cstddef>
#include <optional>
#include <vector>

namespace fl {

class AlphaCoverage {
  public:
    /// Reads the scene's materials; `scene` must outlive this object.
    explicit AlphaCoverage(const Scene& scene);

    /// True when some mesh of the scene can be cut out (its material is MASK or BLEND).
    [[nodiscard]] bool any() const { return any_; }
    /// True when meshes[mesh]'s material is MASK or BLEND.
    [[nodiscard]] bool cutsOut(int mesh) const;
    /// Whether the point (1-u-v) a + u b + v c of meshes[mesh]'s triangle `triangle` blocks light.
    [[nodiscard]] bool blocks(int mesh, std::size_t triangle, float u, float v) const;

  private:
    const Scene* scene_;
    std::vector<std::optional<float>> cutoff_; // per mesh
    bool any_ = false;
};

/// The alpha of `image` at `uv` as GL's GL_LINEAR / GL_REPEAT level-0 sample gives it: texel
/// centres at half-integers, the four nearest texels weighted bilinearly, 8-bit alpha / 255.
float sampleAlpha(const Image& image, glm::vec2 uv);

} // namespace fl
