#include <renderer/Renderer.h>

#include <glm/gtc/matrix_transform.hpp>

#include <stdexcept>

namespace fl {

CameraView makeCameraView(const Scene& scene, const CameraSpec& spec, float aspect) {
    CameraSpec::Kind kind = spec.kind;
    if (kind == CameraSpec::Kind::Default)
        kind = scene.cameras.empty() ? CameraSpec::Kind::Auto : CameraSpec::Kind::Gltf;
    CameraView out;
    const float r = std::max(scene.bounds.radius(), 1e-3f);
    switch (kind) {
    case CameraSpec::Kind::Gltf: {
        if (spec.gltfIndex < 0 || spec.gltfIndex >= static_cast<int>(scene.cameras.size()))
            throw std::invalid_argument("--camera " + std::to_string(spec.gltfIndex) +
                                        ": the scene has " + std::to_string(scene.cameras.size()) +
                                        " camera(s)");
        const Camera& c = scene.cameras[static_cast<size_t>(spec.gltfIndex)];
        const float fov = spec.yfovDegrees ? glm::radians(*spec.yfovDegrees) : c.yfov;
        out.view = c.view;
        out.proj = glm::perspective(fov, aspect, c.znear, c.zfar);
        out.eye = glm::vec3(glm::inverse(c.view)[3]);
        return out;
    }
    case CameraSpec::Kind::LookAt: {
        const float fov = glm::radians(spec.yfovDegrees.value_or(50.0f));
        const glm::vec3 dir = spec.target - spec.eye;
        if (glm::length(dir) < 1e-6f)
            throw std::invalid_argument("--eye and --target are the same point");
        out.view = glm::lookAt(spec.eye, spec.target, geom::stableUp(dir));
        // Near/far from the distance to the bounds so depth precision follows the scene.
        const float d = glm::length(scene.bounds.center() - spec.eye);
        const float znear = std::max(1e-3f * r, (d - r) * 0.5f);
        out.proj = glm::perspective(fov, aspect, znear, (d + r) * 1.5f);
        out.eye = spec.eye;
        return out;
    }
    default: {
        const float fov = glm::radians(spec.yfovDegrees.value_or(50.0f));
        const geom::ViewVolume v =
            geom::frameBounds(scene.bounds, glm::vec3(0.55f, 0.5f, 0.75f), fov, aspect);
        out.view = v.view;
        out.proj = v.proj;
        out.eye = glm::vec3(glm::inverse(v.view)[3]);
        return out;
    }
    }
}

std::string_view methodName(ShadowMethod m) {
    switch (m) {
    case ShadowMethod::JfaL:
        return "jfa-l";
    case ShadowMethod::FloodL:
        return "flood-l";
    case ShadowMethod::JfaE:
        return "jfa-e";
    case ShadowMethod::FloodE:
        return "flood-e";
    case ShadowMethod::Pcf:
        return "pcf";
    case ShadowMethod::Pcss:
        return "pcss";
    case ShadowMethod::Reference:
        return "reference";
    default:
        return "hard";
    }
}

std::span<const ShadowMethod> allShadowMethods() {
    static constexpr ShadowMethod kAll[] = {
        ShadowMethod::Hard,   ShadowMethod::JfaL, ShadowMethod::FloodL, ShadowMethod::JfaE,
        ShadowMethod::FloodE, ShadowMethod::Pcf,  ShadowMethod::Pcss,   ShadowMethod::Reference};
    return kAll;
}

std::optional<ShadowMethod> parseMethod(std::string_view name) {
    for (ShadowMethod m : allShadowMethods())
        if (name == methodName(m)) return m;
    return std::nullopt;
}

Light sceneLight(const Scene& scene) {
    if (scene.light) return *scene.light;
    Light l;
    l.name = "default";
    l.type = Light::Type::Point;
    const float r = std::max(scene.bounds.radius(), 1e-3f);
    l.position = scene.bounds.center() + glm::normalize(glm::vec3(-0.5f, 1.0f, 0.35f)) * (2.5f * r);
    l.direction = glm::normalize(scene.bounds.center() - l.position);
    l.radius = 0.02f * r;
    return l;
}

geom::ViewVolume lightVolume(const Scene& scene, const Light& light) {
    if (light.type == Light::Type::Directional)
        return geom::fitDirectionalLight(scene.bounds, light.direction);
    return geom::fitPerspectiveLight(scene.bounds, light.position);
}

Renderer::Renderer(const ShaderLibrary& shaders, const Scene& scene, const RenderSettings& settings)
    : settings_(settings), scene_(scene), light_(sceneLight(scene)), sceneBounds_(scene.bounds),
      disk_(makeDiskLight(light_, scene.bounds)), lightVolume_(lightVolume(scene, light_)),
      shadowPass_(shaders), penumbraPass_(shaders), eyeSoftPass_(shaders), filteredPass_(shaders),
      referencePass_(shaders), forwardPass_(shaders), diagnosticsPass_(shaders),
      presentPass_(shaders), timer_(settings.timing) {
    gl::throwIfErrors("renderer set-up");
}

void Renderer::setLight(const Light& light) {
    light_ = light;
    disk_ = makeDiskLight(light_, sceneBounds_);
    lightVolume_ = light_.type == Light::Type::Directional
                       ? geom::fitDirectionalLight(sceneBounds_, light_.direction)
                       : geom::fitPerspectiveLight(sceneBounds_, light_.position);
    diagnosticsPass_.reset(); // a moved light changes the map: nothing to compare with
}

void Renderer::resize(int width, int height) {
    if (width <= 0 || height <= 0)
        throw std::invalid_argument("render size must be positive, got " + std::to_string(width) +
                                    "x" + std::to_string(height));
    forwardPass_.resize(width, height);
    diagnosticsPass_.resize(width, height);
    width_ = width;
    height_ = height;
}

void Renderer::render(const CameraView& camera) {
    if (width_ == 0) throw std::logic_error("Renderer::render before resize");
    timer_.beginFrame();
    const bool penumbra =
        settings_.method == ShadowMethod::JfaL || settings_.method == ShadowMethod::FloodL;
    const bool eyeSoft =
        settings_.method == ShadowMethod::JfaE || settings_.method == ShadowMethod::FloodE;
    // 1. Shadow map: depth from the light, fitted to the scene bounds; TSM also fits the warp
    //    to the camera's frustum. The soft methods also keep each texel's world position.
    timer_.begin("shadow map");
    shadow_.reset();
    const ShadowMapPass::Outputs& shadow =
        shadow_.emplace(shadowPass_.execute({scene_, lightVolume_, settings_.shadow, camera.view,
                                             camera.proj, sceneBounds_, penumbra || eyeSoft}));
    timer_.end();
    // 2-3. JFA-L / flood-L: silhouette seeds, flooded into the penumbra map.
    seeds_ = penumbraMap_ = nullptr;
    if (penumbra) {
        PenumbraSettings ps = settings_.penumbra;
        ps.standardFlooding = settings_.method == ShadowMethod::FloodL;
        const float threshold = ps.silhouetteThreshold > 0.0f
                                    ? ps.silhouetteThreshold
                                    : 0.001f * std::max(sceneBounds_.radius(), 1e-3f);
        const PenumbraMapPass::Outputs pm =
            penumbraPass_.execute({*shadow.receivers, disk_, ps, threshold}, &timer_);
        seeds_ = &pm.seeds;
        penumbraMap_ = &pm.penumbraMap;
    }
    // 2-3'. JFA-E / flood-E: eye hard shadows, boundary seeds, eye-space flood, visibility.
    eyeSoft_.reset();
    if (eyeSoft)
        eyeSoft_.emplace(eyeSoftPass_.execute(
            {scene_, camera, shadow, settings_.shadow, disk_, settings_.eyeSoft,
             settings_.penumbra.passes, settings_.method == ShadowMethod::FloodE, width_, height_},
            &timer_));
    // 2-3''. Baselines: PCF / PCSS filter the map per eye pixel; the ground truth renders its
    //        own N maps over the disk. Either way a visibility texture for step 4.
    const gl::Texture* baseline = nullptr;
    if (settings_.method == ShadowMethod::Pcf || settings_.method == ShadowMethod::Pcss)
        baseline = &filteredPass_
                        .execute({scene_, camera, shadow, lightVolume_, disk_, settings_.filtered,
                                  settings_.method == ShadowMethod::Pcss, width_, height_},
                                 &timer_)
                        .visibility;
    if (settings_.method == ShadowMethod::Reference)
        baseline = &referencePass_
                        .execute({scene_, camera, sceneBounds_, disk_, settings_.shadow,
                                  settings_.reference, width_, height_},
                                 &timer_)
                        .visibility;
    // 4. Forward shading with the method's visibility.
    timer_.begin("forward");
    const ForwardPass::Outputs fwd =
        forwardPass_.execute({scene_, camera, light_, shadow, penumbraMap_, &disk_,
                              eyeSoft_ ? &eyeSoft_->visibility : baseline});
    timer_.end();
    // 5. Diagnostics: texel footprint and the previous frame's visibility (measurement only).
    diagnostics_ = nullptr;
    if (settings_.diagnostics) {
        timer_.begin("diagnostics");
        diagnostics_ = &diagnosticsPass_.execute({scene_, camera, light_, shadow}).diagnostics;
        timer_.end();
    }
    timer_.endFrame();
    color_ = &fwd.color;
    visibility_ = &fwd.visibility;
    receivers_ = &fwd.receivers;
    gl::throwIfErrors("frame");
}

void Renderer::present(int framebufferWidth, int framebufferHeight) {
    if (!color_ || framebufferWidth <= 0 || framebufferHeight <= 0) return;
    presentPass_.execute(*color_, framebufferWidth, framebufferHeight);
    gl::throwIfErrors("present");
}

} // namespace fl
