#include <scene/Camera.h>
#include <scene/Ground.h>
#include <scene/Pose.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

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
        const float fov = glm::radians(spec.yfovDegrees.value_or(kAutoViewFovDegrees));
        const glm::vec3 from = kAutoViewFrom;
        // A model on the ground Floodlight added is framed with its shadow, as tightly as they
        // allow (a 5% border), not the whole ground it would be a speck on; a
        // scene of its own is framed whole, as before.
        // In spec.pose, the geometry where it is drawn then (a skinned model at --time).
        const std::vector<glm::vec3> focus =
            modelAndShadowPoints(scene, sceneLight(scene), spec.pose);
        geom::Aabb bounds = scene.bounds;
        if (spec.pose) bounds.extend(posedBounds(scene, *spec.pose));
        const geom::ViewVolume v =
            focus.empty() ? geom::frameBounds(bounds, from, fov, aspect)
                          : geom::framePointsTightly(focus, bounds, from, fov, aspect, 0.9f);
        out.view = v.view;
        out.proj = v.proj;
        out.eye = glm::vec3(glm::inverse(v.view)[3]);
        return out;
    }
    }
}

Light sceneLight(const Scene& scene) {
    if (scene.light) return *scene.light;
    Light l;
    l.name = "default";
    l.type = Light::Type::Point;
    const float r = std::max(scene.bounds.radius(), 1e-3f);
    l.position = scene.bounds.center() + glm::normalize(glm::vec3(-0.5f, 1.0f, 0.35f)) * (2.5f * r);
    l.direction = glm::normalize(scene.bounds.center() - l.position);
    // A scene whose bounds were set by hand has no modelBounds: its whole box is the model.
    const geom::Aabb& model = scene.modelBounds.valid() ? scene.modelBounds : scene.bounds;
    l.radius = kDefaultLightSize * std::max(model.radius(), 1e-3f);
    return l;
}

geom::Aabb shadowCasterBounds(const Scene& scene, const Light& light, const geom::Aabb& bounds,
                              const geom::Aabb& model) {
    // Everything lies above the added ground, so a ray from any point to a light above its plane
    // never crosses it. A directional light keeps the whole box: its orthographic map costs no
    // texels per distance, and its fit stays as it was.
    const bool groundBelowLight = scene.addedGround >= 0 && model.valid() &&
                                  light.type != Light::Type::Directional &&
                                  light.position.y > bounds.min.y;
    return groundBelowLight ? model : bounds;
}

geom::ViewVolume lightVolume(const Scene& scene, const Light& light) {
    return lightVolume(shadowCasterBounds(scene, light, scene.bounds, scene.modelBounds),
                       scene.bounds, light);
}

geom::ViewVolume lightVolume(const geom::Aabb& bounds, const Light& light) {
    return lightVolume(bounds, bounds, light);
}

geom::ViewVolume lightVolume(const geom::Aabb& casters, const geom::Aabb& bounds,
                             const Light& light) {
    if (light.type == Light::Type::Directional)
        return geom::fitDirectionalLight(bounds, light.direction);
    // A spot light's own axis is the fallback when aiming at the casters' centre would leave
    // some of them behind the light (geom::fitPerspectiveLight). The volume is widened for the
    // disk's penumbrae only where it leaves receivers out: fitted to everything, it holds them.
    const bool everything = casters.min == bounds.min && casters.max == bounds.max;
    return geom::fitPerspectiveLight(casters, bounds, light.position,
                                     light.type == Light::Type::Spot ? light.direction
                                                                     : glm::vec3(0.0f),
                                     everything ? 0.0f : light.radius);
}

} // namespace fl
