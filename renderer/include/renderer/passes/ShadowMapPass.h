#pragma once
// Step 1 of a frame: depth from the light into a square depth texture, through one of two
// shadow-map providers:
// - uniform: the light's frustum fitted to the scene bounds, mapped straight onto the square;
// - tsm: Trapezoidal Shadow Maps (Martin & Tan 2004): a projective warp N_T of the light's
//   post-perspective space that spends most texels near the eye (geom::fitTrapezoid).
// Either way a texel's *position* comes from mapViewProj = warp * lightViewProj and its stored
// *depth* is the light's post-perspective depth from lightViewProj alone (TSM's warp would
// distort depth; its z row is zero). Every shadow method reads the map through
// shaders/shadow_lookup.glsl, which applies the same split, so every method takes either
// provider.

#include <gpu/BindScope.h>
#include <gpu/Gl.h>
#include <gpu/Program.h>
#include <gpu/ShaderLibrary.h>
#include <gpu/Uniform.h>
#include <renderer/scene/GpuScene.h>

#include <base/Aabb.h>
#include <base/Framing.h>
#include <geometry/Trapezoid.h>

#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace fl {

class ShadowMapPass;

/// The shadow map's receiver target and what reads it (shaders/shadow_map_decode.glsl's
/// mapReceiver(); CPU twin renderer/passes/ShadowMapDecode.h): per texel the light's unbiased
/// NDC depth, from which the world position of the surface the texel sees comes back.
struct MapPositions {
    const gl::Texture* depth = nullptr; // R32F; shadowmap::kNoReceiver where nothing is seen
    glm::mat3 unwarp{1.0f};             // shadowmap::unwarp(warp)
    glm::mat4 inverseLightViewProj{1.0f};
    const ShadowMapPass* pass = nullptr; // made it (decoded())
    [[nodiscard]] int size() const { return depth->width(); }
    /// Its pass's decodedReceivers(): every position as the shaders decode it, RGBA32F.
    [[nodiscard]] const gl::Texture& decoded() const;
    /// For mapReceiver(): the target on texture `unit` (the shader's sampler binding) in
    /// `scope` and the uMapUnwarp / uMapInverseLightViewProj uniforms of `program`.
    void bind(gl::BindScope& scope, const gl::Program& program, gl::TextureUnit unit) const;
    /// Binds the uniforms bind() sets on `program`, built with shadow_map_decode.glsl.
    static void bindUniforms(gl::Program& program);
    /// Every texel's position, decoded on the CPU (the twin of mapReceiver()), in GL's row
    /// order (row 0 at the bottom): (xyz, 1), or all 0 where the light sees nothing.
    [[nodiscard]] std::vector<glm::vec4> read() const;
};

enum class ShadowMapProvider { Uniform, Tsm };

/// "uniform" or "tsm".
std::string_view providerName(ShadowMapProvider p);
/// Parses "uniform" or "tsm"; nullopt for anything else.
std::optional<ShadowMapProvider> parseProvider(std::string_view name);

/// A TSM stability option (geom::TrapezoidParams' quantize, snapTexels, hysteresis), declared
/// once for the CLI, the capture scripts and tsm_bench.
struct TsmOption {
    std::string_view flag; // CLI flag: "--tsm-quantize"
    std::string_view key;  // capture-script key inside "shadowMap": "quantize"
    std::string_view help;
    double min = 0.0, max = 0.0; // the closed range; 0 turns the measure off
    float geom::TrapezoidParams::*field = nullptr;
};
/// The table of TSM stability options.
std::span<const TsmOption> tsmOptions();

struct ShadowMapSettings {
    int size = 1024; // texels per side
    ShadowMapProvider provider = ShadowMapProvider::Uniform;
    geom::TrapezoidParams tsm; // used by the tsm provider
    // Depth bias, applied in the light's post-perspective depth (the space depths are compared
    // in) by the shadow pass' fragment shader, with glPolygonOffset's meaning: slopeBias times
    // the larger screen-space depth slope of the fragment (per shadow-map texel), plus
    // constantBias times the smallest representable depth step at that depth (float32).
    float slopeBias = 2.0f;
    float constantBias = 2.0f;
};

class ShadowMapPass {
  public:
    explicit ShadowMapPass(const gl::ShaderLibrary& shaders);
    /// (Re)allocates the depth texture at size x size.
    void resize(int size);

    struct Inputs {
        const GpuScene& scene;
        const geom::ViewVolume& light; // light frustum fitted to the scene
        const ShadowMapSettings& settings;
        const glm::mat4& eyeView; // the camera, for the TSM fit
        const glm::mat4& eyeProj;
        const geom::Aabb& sceneBounds; // clamps the eye frustum's depth range for the TSM fit
        bool writeReceivers = false;   // also write the receiver target (JFA-L, JFA-E)
    };
    struct Outputs {
        const gl::Texture& depth; // DEPTH_COMPONENT32F, compare mode set for sampler2DShadow
        glm::mat4 lightViewProj;  // world -> light clip space (depth is compared here)
        glm::mat4 warp;           // light clip -> shadow-map clip (identity for uniform)
        const geom::TrapezoidFit* trapezoid; // the fit (tsm only; nullptr for uniform)
        ShadowMapProvider provider;
        /// With writeReceivers: the receiver target, from which every reader rebuilds the world
        /// position of the surface each texel sees. nullptr otherwise.
        const MapPositions* receivers;
        /// world -> shadow-map clip space (texel positions).
        [[nodiscard]] glm::mat4 mapViewProj() const { return warp * lightViewProj; }
    };
    /// Renders the scene's depth as seen from the light.
    Outputs execute(const Inputs& in);
    /// The last execute()'s receiver positions decoded on the GPU into an RGBA32F texture
    /// (xyz, w = 1; 0 where nothing is seen): the very bits every shader's mapReceiver() reads,
    /// for the overlays and the tests that feed the CPU kernels. Throws std::logic_error when
    /// the last execute() did not write the receiver target.
    [[nodiscard]] const gl::Texture& decodedReceivers() const;
    /// Forgets the previous frame's TSM fit (what hysteresis keeps): the next frame refits as
    /// a single frame would. The pass also forgets it by itself when the light, the map size or
    /// the TSM parameters change.
    void resetHistory() { history_.reset(); }

  private:
    gl::Program program_, decodeProgram_;
    gl::Texture depth_, receiverDepth_;
    gl::Framebuffer fbo_, receiversFbo_;
    geom::TrapezoidFit fit_;
    MapPositions positions_;
    bool receiversWritten_ = false;
    mutable gl::Texture decoded_; // decodedReceivers(): made on demand
    // What fit_ was made for; a frame with other inputs does not read fit_ as its previous.
    struct History {
        glm::mat4 lightViewProj;
        geom::TrapezoidParams params;
    };
    std::optional<History> history_;
};

/// shaders/shadow_depth.*.glsl's uniforms: every pass that draws depths from a light sets these
/// (the shadow map, the maps truth's per-sample maps, JFA-E's occluder ids).
struct ShadowDepthUniforms {
    gl::Uniform<glm::mat4> lightViewProj{"uLightViewProj"};
    gl::Uniform<glm::mat4> warp{"uShadowWarp"};
    gl::Uniform<float> slopeBias{"uSlopeBias"};
    gl::Uniform<float> constantBias{"uConstantBias"};
};
inline constexpr ShadowDepthUniforms kShadowDepthUniforms;

/// shaders/shadow_lookup.glsl's uniforms (bindShadowMap sets them from a map; the maps truth
/// sets them per sample).
struct ShadowLookupUniforms {
    gl::Uniform<glm::mat4> lightViewProj{"uLightViewProj"};
    gl::Uniform<glm::mat4> warp{"uShadowWarp"};
    gl::Uniform<glm::vec4> light{"uShadowLight"};
};
inline constexpr ShadowLookupUniforms kShadowLookupUniforms;

/// Binds the map for shaders/shadow_lookup.glsl: the depth texture on gl::bind::ShadowMap in
/// `scope` and the uLightViewProj / uShadowWarp / uShadowLight uniforms of `program`.
void bindShadowMap(gl::BindScope& scope, const gl::Program& program,
                   const ShadowMapPass::Outputs& shadow);
/// Binds the uniforms bindShadowMap sets on `program`, built with shadow_lookup.glsl.
void bindShadowMapUniforms(gl::Program& program);

/// shadow_lookup.glsl's uShadowLight: inverse(lightViewProj) * (0, 0, 1, 0), the light's
/// position (homogeneous, w != 0) or, for an orthographic map, its travel direction (w = 0).
glm::vec4 shadowLight(const glm::mat4& lightViewProj);

/// A size x size depth map sampled as the hard test reads it (NEAREST, LEQUAL comparison):
/// the shadow pass's own, and the ground truth's point-light maps.
gl::Texture makeShadowDepthTexture(int size);

} // namespace fl
