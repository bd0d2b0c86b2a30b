#pragma once
// JFA-E's packed eye cells (phase 2's one R32UI target) and how to read them: the CPU twin of
// shaders/eye_decode.glsl (keep the two in step). A cell holds a pixel's hard-shadow state, the
// shadow-map texel its lookup reads and that texel's silhouette-edge code, 4 bytes where phase 2
// used to write two RGBA32F images (32 bytes). The receiver's world position comes back from
// the surfaces' depth (SurfaceDecode.h), the occluder's from the map's receiver target
// (ShadowMapDecode.h, occluderEdgeApply) and its object id from the light-space id pass.

#include <renderer/passes/ShadowMapPass.h>
#include <renderer/soft/PenumbraCriterion.h>

#include <gpu/BindScope.h>
#include <gpu/Gl.h>
#include <gpu/Program.h>

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace fl {

/// Phase 2's output decoded, row-major width x height (row 0 = bottom, as GL).
struct EyeImage {
    int width = 0;
    int height = 0;
    /// xyz world position; w = 1 in hard shadow, 0 lit, 2 lit because outside the shadow map
    /// (no evidence of a shadow edge for phase 3), -1 no surface (background).
    std::vector<glm::vec4> points;
    /// xyz the occluder point (shadow-map receiver at the pixel's texel); w its object id, -1
    /// when unknown (no surface, outside the map, or the object-ID fix is off).
    std::vector<glm::vec4> occluders;
    [[nodiscard]] std::size_t index(int x, int y) const {
        return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
               static_cast<std::size_t>(x);
    }
};

namespace eyecell {

/// A pixel's hard-shadow state (bits 0-1 of its cell).
enum class State : std::uint32_t { Background = 0, Shadowed = 1, Lit = 2, OutsideMap = 3 };
/// The largest shadow map a cell can address: texel x and y take 13 bits each.
inline constexpr int kMaxMapSize = 8192;

/// The cell of a pixel in `state` whose lookup reads map texel `texel` with edge code `edgeCode`
/// (occluderEdgeCode; 0 for the texel's centre). The same as eyeCellPack() in GLSL.
std::uint32_t pack(State state, glm::ivec2 texel, std::uint32_t edgeCode);
[[nodiscard]] State state(std::uint32_t cell);
[[nodiscard]] glm::ivec2 texel(std::uint32_t cell);
[[nodiscard]] std::uint32_t edgeCode(std::uint32_t cell);

/// A pixel's receiver (EyeImage::points) from its cell and its surface position
/// (surface::position): the same as eyePoint() in GLSL.
glm::vec4 point(std::uint32_t cell, glm::vec4 surfacePosition);
/// A pixel's occluder (EyeImage::occluders) from its cell, the map's decoded receivers and the
/// object id per map texel (nullptr: ids unknown, -1): the same as eyeOccluder() in GLSL.
glm::vec4 occluder(std::uint32_t cell, const ReceiverGrid& receivers,
                   const std::vector<float>* ids);

} // namespace eyecell

class EyeSoftShadowPass;

/// Phase 2's packed cells and everything eye_decode.glsl decodes them with.
struct EyeCells {
    const gl::Texture* cells = nullptr; // R32UI, frame-sized
    const gl::Texture* depth = nullptr; // the surfaces' depth (SurfacePositions)
    glm::mat4 inverseViewProj{1.0f};    // SurfacePositions::inverseViewProj
    MapPositions map;                   // the shadow map's receiver target
    const gl::Texture* ids = nullptr;   // R32F object id per map texel, read when objectIds
    bool objectIds = false;
    const EyeSoftShadowPass* pass = nullptr; // made them (decoded())
    /// Phase 3's occluder per seed pixel (RGBA32F, eyeSeedOccluder; gl::bind::SeedOccluders),
    /// once it has run: the flood and the composite read a seed's occluder there instead of
    /// decoding it.
    const gl::Texture* seedOccluders = nullptr;

    [[nodiscard]] int width() const { return cells->width(); }
    [[nodiscard]] int height() const { return cells->height(); }
    /// eye_decode.glsl's textures (gl::bind::Eye*, SeedOccluders) in `scope` and uniforms on
    /// `program`, for a grid `factor` times coarser than the frame (1: the frame itself).
    void bind(gl::BindScope& scope, const gl::Program& program, int factor = 1) const;
    /// Binds the uniforms bind() sets on `program`, built with eye_decode.glsl.
    static void bindUniforms(gl::Program& program);
    /// Every pixel decoded on the GPU by eye_decode.glsl (the bits the phases read), as two
    /// RGBA32F textures in EyeImage layout: points and occluders. Made on first use after a
    /// frame, outside it (overlays, tests).
    [[nodiscard]] std::pair<const gl::Texture&, const gl::Texture&> decoded() const;
    /// Every pixel decoded on the CPU (the twin of eye_decode.glsl).
    [[nodiscard]] EyeImage read() const;
    /// The packed cells themselves, EyeImage's layout (eyecell::state, texel, edgeCode).
    [[nodiscard]] std::vector<std::uint32_t> words() const;
};

} // namespace fl
