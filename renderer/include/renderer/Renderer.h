#pragma once
// The frame, as numbered steps: 1. shadow map from the light (uniform or TSM provider);
// 2. (JFA-L, flood-L) silhouettes and 3. the flooded penumbra map, or (JFA-E, flood-E) the eye
// hard-shadow image, its boundary seeds, the eye-space flood and the visibility composite;
// or (PCF, PCSS) the filtered map per eye pixel, or (reference) N disk-sample maps accumulated;
// 4. forward shading with the method's visibility; 5. (optional) shadow-map diagnostics;
// 6. (window only) present. Owns the passes and the uploaded scene.

#include <gpu/PassTimer.h>
#include <gpu/ShaderLibrary.h>
#include <renderer/GpuScene.h>
#include <renderer/Scene.h>
#include <renderer/passes/ForwardPass.h>
#include <renderer/passes/ShadowDiagnosticsPass.h>
#include <renderer/passes/ShadowMapPass.h>
#include <renderer/soft/DiskLight.h>
#include <renderer/soft/EyeSoftShadow.h>
#include <renderer/soft/FilteredShadow.h>
#include <renderer/soft/PenumbraMap.h>
#include <renderer/soft/ReferenceShadow.h>

#include <geometry/Framing.h>

#include <optional>
#include <span>

namespace fl {

/// The shadow methods.
enum class ShadowMethod {
    Hard,      // one shadow-map test (the light's centre)
    JfaL,      // thesis §5.3: penumbra map by jump flooding in light space
    FloodL,    // the same phases with standard flooding (the reference for JFA-L)
    JfaE,      // thesis §5.4: occluders jump-flooded in eye space from the hard-shadow image
    FloodE,    // the same phases with standard flooding (the reference for JFA-E)
    Pcf,       // baseline: percentage-closer filtering, a k x k kernel (FilteredShadow.h)
    Pcss,      // baseline: percentage-closer soft shadows (FilteredShadow.h)
    Reference, // ground truth: N point-light shadow maps over the disk (ReferenceShadow.h)
};
/// "hard", "jfa-l", "flood-l", "jfa-e", "flood-e", "pcf", "pcss", "reference".
std::string_view methodName(ShadowMethod m);
/// Every method, in the order the window cycles through them.
std::span<const ShadowMethod> allShadowMethods();
/// Parses a method name; nullopt if unknown.
std::optional<ShadowMethod> parseMethod(std::string_view name);

struct RenderSettings {
    ShadowMapSettings shadow;
    ShadowMethod method = ShadowMethod::Hard;
    PenumbraSettings penumbra;       // JFA-L / flood-L (standardFlooding is set from the method);
                                     // JFA-E / flood-E take its pass count
    EyeSoftSettings eyeSoft;         // JFA-E / flood-E: the jump-too-far fixes, boundary threshold
    FilteredShadowSettings filtered; // PCF kernel, PCSS preset
    ReferenceSettings reference;     // ground truth: samples, map size
    TimingMode timing = TimingMode::Auto;
    bool diagnostics = false; // run step 3 (texel footprint and temporal continuity)
};

/// How to pick the camera: a glTF camera, automatic framing, or an explicit eye/target.
struct CameraSpec {
    enum class Kind { Default, Auto, Gltf, LookAt };
    Kind kind = Kind::Default; // Default: the scene's first camera if it has one, else Auto
    int gltfIndex = 0;
    glm::vec3 eye{0.0f}, target{0.0f};
    std::optional<float> yfovDegrees; // overrides the camera's field of view
};

/// The camera for `spec` at the given aspect ratio; throws std::invalid_argument for a glTF
/// camera index the scene does not have.
CameraView makeCameraView(const Scene& scene, const CameraSpec& spec, float aspect);

/// The scene's light, or the default one (above and to the side of the bounds) if it has none.
Light sceneLight(const Scene& scene);

/// The light's view volume fitted to the scene bounds.
geom::ViewVolume lightVolume(const Scene& scene, const Light& light);

class Renderer {
  public:
    /// Compiles the passes' shaders and uploads the scene (needs a current context).
    Renderer(const ShaderLibrary& shaders, const Scene& scene, const RenderSettings& settings);

    void setSettings(const RenderSettings& settings) { settings_ = settings; }
    [[nodiscard]] const RenderSettings& settings() const { return settings_; }
    /// Sets the output size in pixels (both > 0).
    void resize(int width, int height);
    /// Renders one frame into color()/visibility(); throws fl::gl::GlError on any GL error.
    void render(const CameraView& camera);
    /// Draws the last frame to the default framebuffer (windows).
    void present(int framebufferWidth, int framebufferHeight);

    [[nodiscard]] const gl::Texture& color() const { return *color_; }
    [[nodiscard]] const gl::Texture& visibility() const { return *visibility_; }
    /// R8 mask of the last frame: 1 where the visible surface faces the light (its visibility
    /// changes the image), 0 on back-facing surfaces and background.
    [[nodiscard]] const gl::Texture& receivers() const { return *receivers_; }
    /// The disk light the soft methods use.
    [[nodiscard]] const DiskLight& disk() const { return disk_; }
    /// JFA-L / flood-L: the last frame's silhouette seeds and penumbra map (nullptr otherwise).
    [[nodiscard]] const gl::Texture* seeds() const { return seeds_; }
    [[nodiscard]] const gl::Texture* penumbraMap() const { return penumbraMap_; }
    /// JFA-E / flood-E: the last frame's phase outputs (nullptr otherwise).
    [[nodiscard]] const EyeSoftShadowPass::Outputs* eyeSoft() const {
        return eyeSoft_ ? &*eyeSoft_ : nullptr;
    }
    /// Step 5's output (see ShadowDiagnosticsPass); nullptr unless settings().diagnostics.
    [[nodiscard]] const gl::Texture* diagnostics() const { return diagnostics_; }
    /// The last frame's shadow map and its matrices; nullptr before the first frame.
    [[nodiscard]] const ShadowMapPass::Outputs* shadow() const {
        return shadow_ ? &*shadow_ : nullptr;
    }
    /// Makes the next diagnostics frame compare with itself (e.g. after a camera cut).
    void resetDiagnostics() { diagnosticsPass_.reset(); }
    [[nodiscard]] const PassTimer& timer() const { return timer_; }
    [[nodiscard]] const Light& light() const { return light_; }
    /// Replaces the light (e.g. moved from the window): recomputes the disk light and the light's
    /// view volume from the scene bounds; the next render() uses it.
    void setLight(const Light& light);
    [[nodiscard]] int width() const { return width_; }
    [[nodiscard]] int height() const { return height_; }

  private:
    RenderSettings settings_;
    GpuScene scene_;
    Light light_;
    geom::Aabb sceneBounds_;
    DiskLight disk_;
    geom::ViewVolume lightVolume_;
    ShadowMapPass shadowPass_;
    PenumbraMapPass penumbraPass_;
    EyeSoftShadowPass eyeSoftPass_;
    FilteredShadowPass filteredPass_;
    ReferenceShadowPass referencePass_;
    ForwardPass forwardPass_;
    ShadowDiagnosticsPass diagnosticsPass_;
    PresentPass presentPass_;
    PassTimer timer_;
    const gl::Texture* color_ = nullptr;
    const gl::Texture* visibility_ = nullptr;
    const gl::Texture* receivers_ = nullptr;
    const gl::Texture* diagnostics_ = nullptr;
    const gl::Texture* seeds_ = nullptr;
    const gl::Texture* penumbraMap_ = nullptr;
    std::optional<ShadowMapPass::Outputs> shadow_;
    std::optional<EyeSoftShadowPass::Outputs> eyeSoft_;
    int width_ = 0, height_ = 0;
};

} // namespace fl
