#pragma once
// The frame, as numbered steps (the same numbers wherever a step is written):
//   1. shadow map from the light (uniform or TSM provider);
//   2. surfaces: one geometry pass from the eye (SurfacesPass);
//   3. the shadow method: visibility per pixel (renderer/methods/ShadowMethod.h); a method's
//      own phases (its timed names; JFA-L's and JFA-E's "phase 2..5" are the thesis' numbers)
//      are parts of this step, not frame steps;
//   4. shading with that visibility (ShadingPass) and the blended surfaces over it; then,
//      optionally, the shadow-map diagnostics;
//   5. overlays and HUD (renderer/overlays, HudPass: drawn by the caller over the frame);
//   6. present (window only): present() puts the colour in the window's framebuffer
//      (PresentPass) before the caller draws step 5 over it, and the caller's buffer swap shows it.
// render() runs steps 1-4.
// Owns the passes, one instance of every method of the table, and the uploaded scene.

#include <gpu/PassTimer.h>
#include <gpu/ShaderLibrary.h>
#include <renderer/methods/ShadowMethod.h>
#include <renderer/passes/ShadingPass.h>
#include <renderer/passes/ShadowDiagnosticsPass.h>
#include <renderer/passes/ShadowMapPass.h>
#include <renderer/passes/SurfacesPass.h>
#include <renderer/scene/GpuScene.h>
#include <scene/Camera.h>
#include <scene/DiskLight.h>
#include <scene/Pose.h>
#include <scene/Scene.h>

#include <base/Framing.h>

#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace fl {

struct RenderSettings {
    ShadowMapSettings shadow;
    std::string method = "hard"; // a name of the method table (methodTable())
    MethodOptions options;       // the methods' options by flag; unset ones take their defaults
    gl::TimingMode timing = gl::TimingMode::Auto;
    bool diagnostics = false; // measure the shadow map after shading (ShadowDiagnosticsPass)
    /// Something reads the flood at every texel, not only where the eye's pixels look (the
    /// overlays that show the map: overlayReadsWholeFlood): an unset --flood-region floods the
    /// band instead of its default, view.
    bool wholeFlood = false;
    /// Set by a command that shows progress: slow methods (the ray tracer) call it during a
    /// frame with the share done, in [0, 1], on the rendering thread.
    std::function<void(double)> progress;
};

/// The timed passes of a frame with method `m`, in frame order, as PassTimer names them:
/// "shadow map", "surfaces", the method's phases (its table row), "shading".
std::vector<std::string_view> framePhases(const MethodDescriptor& m);

class Renderer {
  public:
    /// Compiles the passes' and the chosen method's shaders and uploads the scene (needs a
    /// current context); other methods are built when first chosen. Throws
    /// std::invalid_argument for a method name the table does not have.
    Renderer(const gl::ShaderLibrary& shaders, const Scene& scene, const RenderSettings& settings);

    /// Replaces the settings (building the method if it is new); throws std::invalid_argument for
    /// an unknown method name.
    void setSettings(const RenderSettings& settings);
    [[nodiscard]] const RenderSettings& settings() const { return settings_; }
    /// Sets the output size in pixels (both > 0).
    void resize(int width, int height);
    /// Renders one frame into color()/visibility(); throws fl::gl::GlError on any GL error.
    /// `previous` is the camera of the frame before (the same camera for a first frame): the
    /// frame also writes the motion target (motion()), which scoring flicker on the same surface
    /// point needs. The one-argument form writes none, and costs a sixth less of step 2.
    void render(const CameraView& camera, const CameraView& previous) {
        renderFrame(camera, &previous);
    }
    void render(const CameraView& camera) { renderFrame(camera, nullptr); }
    /// Draws the last frame to the default framebuffer (windows).
    void present(int framebufferWidth, int framebufferHeight);

    [[nodiscard]] const gl::Texture& color() const { return *color_; }
    /// The method's visibility of the last frame, R32F in [0, 1], 1 on background.
    [[nodiscard]] const gl::Texture& visibility() const { return *visibility_; }
    /// R8 mask of the last frame: 1 where the visible surface faces the light (its visibility
    /// changes the image), 0 on back-facing surfaces and background.
    [[nodiscard]] const gl::Texture& receivers() const { return surfacesPass_.outputs().receivers; }
    /// The last frame's motion target (SurfacesPass::Outputs::motion); nullptr when the frame
    /// was rendered without a previous camera.
    [[nodiscard]] const gl::Texture* motion() const { return surfacesPass_.outputs().motion; }
    /// Step 2's targets of the last frame.
    [[nodiscard]] SurfacesPass::Outputs surfaces() const { return surfacesPass_.outputs(); }
    /// The disk light the soft methods use.
    [[nodiscard]] const DiskLight& disk() const { return disk_; }
    /// The current method's table row.
    [[nodiscard]] const MethodDescriptor& method() const { return *method_; }
    /// The last frame's flood when the current method floods (JFA-L/E, flood-L/E), else nullptr.
    [[nodiscard]] const FloodFrame* flood() const;
    /// The diagnostics of the last frame (see ShadowDiagnosticsPass); nullptr unless
    /// settings().diagnostics.
    [[nodiscard]] const gl::Texture* diagnostics() const { return diagnostics_; }
    /// The last frame's shadow map and its matrices; nullptr before the first frame.
    [[nodiscard]] const ShadowMapPass::Outputs* shadow() const {
        return shadow_ ? &*shadow_ : nullptr;
    }
    /// The last frame's shadow-map receiver positions decoded into RGBA32F (ShadowMapPass::
    /// decodedReceivers; for overlays and tests). Throws std::logic_error when the last frame's
    /// method wrote no receiver target.
    [[nodiscard]] const gl::Texture& decodedShadowReceivers() const {
        return shadowPass_.decodedReceivers();
    }
    /// Eye-space geometry draws of the last frame (1: the surfaces pass; methods read it).
    [[nodiscard]] int eyeGeometryDraws() const { return eyeDraws_; }
    /// Makes the next diagnostics frame compare with itself (e.g. after a camera cut).
    void resetDiagnostics() { diagnosticsPass_.reset(); }
    [[nodiscard]] const gl::PassTimer& timer() const { return timer_; }
    [[nodiscard]] const Light& light() const { return light_; }
    /// Replaces the light (e.g. moved from the window): recomputes the disk light and the light's
    /// view volume from the scene bounds; the next render() uses it.
    void setLight(const Light& light);
    /// Plays `animations` (indices into the scene's: chooseAnimations, scene/Pose.h)
    /// from now on, posed at time 0. The light's frustum fits every pose they take
    /// (animatedBounds), so that the map's texel grid stays put while they move. A new renderer
    /// plays all of the scene's.
    void setAnimations(std::vector<int> animations);
    /// Poses the scene at `time` seconds for the next frames; `previousTime` is the frame
    /// before's, for the motion target (equal: no motion). Throws std::invalid_argument for a
    /// negative or non-finite time.
    void setTime(double time, double previousTime);
    void setTime(double time) { setTime(time, time); }
    [[nodiscard]] double time() const { return time_; }
    [[nodiscard]] const std::vector<int>& animations() const { return animations_; }
    [[nodiscard]] int width() const { return width_; }
    [[nodiscard]] int height() const { return height_; }

  private:
    /// Steps 1-4 of a frame; `previous` null: no motion target.
    void renderFrame(const CameraView& camera, const CameraView* previous);
    /// The current method's instance, built on first use.
    ShadowMethod& currentMethod();
    /// The instance slot of the current method (methods_ follows the table's order).
    [[nodiscard]] std::size_t slot() const {
        return static_cast<std::size_t>(method_ - methodTable().data());
    }

    gl::ShaderLibrary shaders_;
    RenderSettings settings_;
    const MethodDescriptor* method_ = nullptr;
    std::optional<std::any> parsedOptions_; // settings_.options as method_'s struct, once parsed
    GpuScene scene_;
    Light light_;
    geom::Aabb sceneBounds_;  // the scene's, or every pose its animations take
    geom::Aabb modelBounds_;  // the same without an added ground
    geom::Aabb casterBounds_; // what casts shadows under light_ (shadowCasterBounds)
    std::vector<int> animations_;
    double time_ = 0.0;
    std::optional<std::pair<double, double>> posedAt_; // (time, previous) the scene is posed at
    DiskLight disk_;
    geom::ViewVolume lightVolume_;
    ShadowMapPass shadowPass_;
    SurfacesPass surfacesPass_;
    std::vector<std::unique_ptr<ShadowMethod>> methods_; // per table row (null until used)
    ShadingPass shadingPass_;
    ShadowDiagnosticsPass diagnosticsPass_;
    PresentPass presentPass_;
    gl::PassTimer timer_;
    const gl::Texture* color_ = nullptr;
    const gl::Texture* visibility_ = nullptr;
    const gl::Texture* diagnostics_ = nullptr;
    std::optional<ShadowMapPass::Outputs> shadow_;
    int eyeDraws_ = 0;
    int width_ = 0, height_ = 0;
};

} // namespace fl
