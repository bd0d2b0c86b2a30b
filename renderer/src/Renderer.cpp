#include <renderer/Renderer.h>
#include <renderer/passes/Phases.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include <stdexcept>
#include <vector>

namespace fl {

std::vector<std::string_view> framePhases(const MethodDescriptor& m) {
    std::vector<std::string_view> out{phase::kShadowMap, phase::kSurfaces};
    out.insert(out.end(), m.phases.begin(), m.phases.end());
    out.push_back(phase::kShading);
    return out;
}

Renderer::Renderer(const gl::ShaderLibrary& shaders, const Scene& scene,
                   const RenderSettings& settings)
    : shaders_(shaders), settings_(settings), method_(&methodOrThrow(settings.method)),
      scene_(scene), light_(sceneLight(scene)), sceneBounds_(scene.bounds),
      modelBounds_(scene.modelBounds.valid() ? scene.modelBounds : scene.bounds),
      casterBounds_(shadowCasterBounds(scene, light_, sceneBounds_, modelBounds_)),
      disk_(makeDiskLight(light_, scene.bounds)), lightVolume_(lightVolume(scene, light_)),
      shadowPass_(shaders), surfacesPass_(shaders), shadingPass_(shaders),
      diagnosticsPass_(shaders), presentPass_(shaders), timer_(settings.timing) {
    methods_.resize(methodTable().size());
    if (isAnimated(scene)) setAnimations(chooseAnimations(scene, "all"));
    (void)currentMethod(); // its shader errors now, not at the first frame
    gl::throwIfErrors("renderer set-up");
}

ShadowMethod& Renderer::currentMethod() {
    std::unique_ptr<ShadowMethod>& m = methods_[slot()];
    if (!m) {
        m = method_->make(shaders_);
        if (width_ > 0) m->resize(width_, height_);
    }
    return *m;
}

void Renderer::setSettings(const RenderSettings& settings) {
    method_ = &methodOrThrow(settings.method);
    settings_ = settings;
    parsedOptions_.reset();
    (void)currentMethod();
}

const FloodFrame* Renderer::flood() const {
    const std::unique_ptr<ShadowMethod>& m = methods_[slot()];
    return method_->floods && m ? m->flood() : nullptr;
}

void Renderer::setLight(const Light& light) {
    light_ = light;
    disk_ = makeDiskLight(light_, sceneBounds_);
    casterBounds_ = shadowCasterBounds(scene_.source(), light_, sceneBounds_, modelBounds_);
    lightVolume_ = lightVolume(casterBounds_, sceneBounds_, light_);
    diagnosticsPass_.reset(); // a moved light changes the map: nothing to compare with
}

void Renderer::setAnimations(std::vector<int> animations) {
    animations_ = std::move(animations);
    // The poses are skinned once: the model's box, then the added ground's (rigid, on no node,
    // never animated: its mesh box at its world, as posedBounds places it in every pose).
    const Scene& s = scene_.source();
    modelBounds_ = animatedBounds(s, animations_, 64, s.addedGround);
    sceneBounds_ = modelBounds_;
    if (s.addedGround >= 0) {
        const Instance& ground = s.instances.at(static_cast<std::size_t>(s.addedGround));
        geom::Aabb local;
        for (const glm::vec3& p : s.meshes.at(static_cast<std::size_t>(ground.mesh)).positions)
            local.extend(p);
        sceneBounds_.extend(local.transformed(ground.world));
    }
    posedAt_.reset(); // another clip: the same times pose differently
    setLight(light_); // refits the light to the new bounds
    setTime(0.0);
}

void Renderer::setTime(double time, double previousTime) {
    if (!std::isfinite(time) || time < 0.0 || !std::isfinite(previousTime) || previousTime < 0.0)
        throw std::invalid_argument("the time must be a finite number of seconds >= 0, got " +
                                    std::to_string(time));
    time_ = time;
    if (!isAnimated(scene_.source())) return;
    // A paused window, a still capture clip and every lane of a capture ask for the pose they
    // already have: evaluate and upload only what changed.
    if (posedAt_ == std::make_pair(time, previousTime)) return;
    posedAt_ = std::make_pair(time, previousTime);
    const Scene& s = scene_.source();
    scene_.setPose(evaluatePose(s, animations_, time), evaluatePose(s, animations_, previousTime));
}

void Renderer::resize(int width, int height) {
    if (width <= 0 || height <= 0)
        throw std::invalid_argument("render size must be positive, got " + std::to_string(width) +
                                    "x" + std::to_string(height));
    gl::checkTextureSize("frame", width, height);
    surfacesPass_.resize(width, height);
    for (const std::unique_ptr<ShadowMethod>& m : methods_)
        if (m) m->resize(width, height);
    shadingPass_.resize(width, height);
    diagnosticsPass_.resize(width, height);
    shadowPass_.resetHistory(); // another frame size: start from a single frame's fit
    width_ = width;
    height_ = height;
}

void Renderer::renderFrame(const CameraView& camera, const CameraView* previous) {
    if (width_ == 0) throw std::logic_error("Renderer::render before resize");
    const MethodDescriptor& method = *method_;
    ShadowMethod& impl = currentMethod();
    timer_.beginFrame();
    const std::size_t eyeDrawsBefore = scene_.eyeDrawCalls();
    // 1. Shadow map: depth from the light, fitted to the shadow casters; TSM also fits the warp
    //    to the camera's frustum. The flooding methods also keep each texel's world position.
    timer_.begin(phase::kShadowMap);
    shadow_.reset();
    const ShadowMapPass::Outputs& shadow = shadow_.emplace(
        shadowPass_.execute({scene_, lightVolume_, settings_.shadow, camera.view, camera.proj,
                             sceneBounds_, method.shadowMapPositions}));
    timer_.wrote(gl::textureBytes(shadow.depth) +
                 (shadow.receivers ? gl::textureBytes(*shadow.receivers->depth) : 0));
    timer_.end();
    // 2. Surfaces: the scene drawn once from the eye; every later step reads these targets.
    timer_.begin(phase::kSurfaces);
    const SurfacesPass::Outputs surfaces =
        surfacesPass_.execute({scene_, camera, light_, previous});
    timer_.wrote(surfaces.bytes());
    timer_.end();
    // 3. The shadow method: visibility per pixel (it times its own phases). A reader of the
    //    whole flood (an overlay that shows the map) gets the band where --flood-region is
    //    unset: the default, view, is exact only where the eye's pixels read the map.
    //    The options are parsed into the method's struct once per settings (an invalid value
    //    throws here, at the first frame, and again at the next).
    if (!parsedOptions_) {
        MethodOptions wholeFlood;
        const bool band = settings_.wholeFlood && !settings_.options.has(floodRegionOption().flag);
        if (band) {
            wholeFlood = settings_.options;
            wholeFlood.set(floodRegionOption().flag,
                           std::string(jfa::floodRegionName(jfa::FloodRegion::Band)));
        }
        parsedOptions_ = method.options.parse(band ? wholeFlood : settings_.options);
    }
    const FrameInputs in{scene_,       camera,
                         light_,       disk_,
                         sceneBounds_, casterBounds_,
                         lightVolume_, settings_.shadow,
                         shadow,       surfaces,
                         method,       *parsedOptions_,
                         &timer_,      settings_.progress ? &settings_.progress : nullptr};
    const gl::Texture& methodVisibility = impl.execute(in);
    // 4. Shading with the method's visibility, and the blended surfaces over it; then the
    //    optional shadow-map diagnostics (texel footprint, the previous frame's visibility:
    //    measurement only).
    timer_.begin(phase::kShading);
    const ShadingPass::Outputs shaded =
        shadingPass_.execute({surfaces, light_, methodVisibility, scene_, camera});
    timer_.wrote(gl::textureBytes(shaded.color));
    timer_.end();
    diagnostics_ = nullptr;
    if (settings_.diagnostics) {
        timer_.begin(phase::kDiagnostics);
        diagnostics_ = &diagnosticsPass_.execute({surfaces, camera, light_, shadow}).diagnostics;
        // The pass also keeps a copy of this frame's map for the next.
        timer_.wrote(gl::textureBytes(*diagnostics_) + gl::textureBytes(shadow.depth));
        timer_.end();
    }
    timer_.endFrame();
    eyeDraws_ = static_cast<int>(scene_.eyeDrawCalls() - eyeDrawsBefore);
    color_ = &shaded.color;
    visibility_ = &methodVisibility; // every method writes 1 on background
    gl::throwIfErrors("frame");
}

// 6. Present (window only): the colour to the default framebuffer, sRGB-encoded; the caller draws
//    step 5 (overlays, HUD) over it and swaps the buffers.
void Renderer::present(int framebufferWidth, int framebufferHeight) {
    if (!color_ || framebufferWidth <= 0 || framebufferHeight <= 0) return;
    presentPass_.execute(*color_, framebufferWidth, framebufferHeight);
    gl::throwIfErrors("present");
}

} // namespace fl
