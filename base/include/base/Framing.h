#pragma once
// Fitting view volumes to scene bounds: the light's frustum for shadow maps and automatic camera
// framing when a scene has no camera.

#include <base/Aabb.h>

#include <glm/glm.hpp>

#include <span>

namespace fl::geom {

/// A view and projection pair with the depth range it was fitted to.
struct ViewVolume {
    glm::mat4 view{1.0f};
    glm::mat4 proj{1.0f};
    float znear = 0.1f;
    float zfar = 100.0f;
    [[nodiscard]] glm::mat4 viewProj() const { return proj * view; }
};

/// Orthographic light volume for a directional light travelling along `dir` that tightly
/// contains `bounds`.
ViewVolume fitDirectionalLight(const Aabb& bounds, glm::vec3 dir);

/// Perspective light volume from `position` aimed at the bounds' centre whose square frustum
/// contains every corner of `bounds` in front of the light. When a corner lies behind the light
/// (no finite frustum contains them all) and looking along `axis` (a spot light's direction; zero
/// for none) leaves none behind, the volume looks along `axis` instead: a scene that extends far
/// to one side of a spot light would otherwise get the capped fov and a near plane at 1/1000 of
/// the bounds' diagonal, which PCSS's blocker search looks through. Otherwise the field of view
/// is capped at `maxFov` radians and the near plane at 1/1000 of the bounds' diagonal.
ViewVolume fitPerspectiveLight(const Aabb& bounds, glm::vec3 position,
                               glm::vec3 axis = glm::vec3(0.0f),
                               float maxFov = glm::radians(150.0f));

/// The same aimed at the shadow casters only: the frustum holds every corner of `casters`,
/// widened by the angle a disk light of radius `lightRadius` around `position` subtends from
/// the nearest of them (the disk's penumbrae reach that far past the centre's cone), while its
/// depth range holds all of `scene` (the receivers behind the casters). A receiver outside the
/// frustum sees the whole light, so the map need not spend texels on it: on a model standing on
/// a wide ground, most of the map would otherwise hold ground that nothing shadows.
ViewVolume fitPerspectiveLight(const Aabb& casters, const Aabb& scene, glm::vec3 position,
                               glm::vec3 axis, float lightRadius,
                               float maxFov = glm::radians(150.0f));

/// A look-at view from direction `fromDir` (pointing from the target to the eye) that shows the
/// whole bounding sphere of `bounds` for the given vertical fov and aspect, plus near/far planes.
ViewVolume frameBounds(const Aabb& bounds, glm::vec3 fromDir, float yfov, float aspect);

/// The view from direction `fromDir` (target to eye) whose frustum holds every one of `points`
/// with the eye as close as it can be: they span `fill` (in (0, 1]) of the picture's width or
/// height, centred in it on that axis (the sphere frameBounds fits around a box leaves the box
/// much smaller than the picture). The near and far planes hold every point of `scene` in view
/// too: a model framed on a wide ground must not lose the rest of the ground. No points:
/// frameBounds(scene).
ViewVolume framePointsTightly(std::span<const glm::vec3> points, const Aabb& scene,
                              glm::vec3 fromDir, float yfov, float aspect, float fill = 1.0f);

/// The perspective projection `proj` (a glm::perspective / glm::frustum matrix) with its near and
/// far planes moved in to the depth range that `bounds` (in the space `view` maps from) occupies,
/// never beyond the original planes. TSM fits its trapezoid to this frustum: the part of the eye
/// frustum beyond the scene holds no receivers and would only waste shadow-map texels. Returns
/// `proj` unchanged for an orthographic projection or when the bounds lie outside the frustum's
/// depth range.
glm::mat4 clampDepthRange(const glm::mat4& proj, const glm::mat4& view, const Aabb& bounds);

/// An up vector that is not parallel to `dir` (world +Y unless dir is nearly vertical).
glm::vec3 stableUp(glm::vec3 dir);

} // namespace fl::geom
