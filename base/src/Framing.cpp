#include <base/Framing.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace fl::geom {

glm::vec3 stableUp(glm::vec3 dir) {
    dir = glm::normalize(dir);
    return std::abs(dir.y) > 0.99f ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
}

ViewVolume fitDirectionalLight(const Aabb& bounds, glm::vec3 dir) {
    dir = glm::normalize(dir);
    const glm::vec3 c = bounds.center();
    const float r = std::max(bounds.radius(), 1e-4f);
    ViewVolume v;
    // Eye one radius plus a margin behind the centre so every point has positive depth.
    v.view = glm::lookAt(c - dir * (2.0f * r), c, stableUp(dir));
    const Aabb ls = bounds.transformed(v.view);
    // View space looks down -Z: depth of a point is -z.
    const float pad = 1e-3f * r;
    v.znear = std::max(-ls.max.z - pad, 1e-4f * r);
    v.zfar = -ls.min.z + pad;
    v.proj =
        glm::ortho(ls.min.x - pad, ls.max.x + pad, ls.min.y - pad, ls.max.y + pad, v.znear, v.zfar);
    return v;
}

namespace {

// The perspective volume from `position` along unit `dir` whose square frustum holds every
// corner of `casters` in front of it, widened by the angle a disk of radius `lightRadius` around
// `position` subtends from the nearest of them (its penumbrae reach past the cone from the
// centre by at most that angle), and whose depth range holds `scene` too (receivers behind the
// casters must lie inside the map to be looked up); `behind` says whether a caster corner lay
// behind the light.
ViewVolume fitAlong(const Aabb& casters, const Aabb& scene, glm::vec3 position, glm::vec3 dir,
                    float maxFov, float lightRadius, bool& behind) {
    const float r = std::max(scene.radius(), 1e-4f);
    ViewVolume v;
    v.view = glm::lookAt(position, position + dir, stableUp(dir));
    // Largest tangent over the corners in front of the light; corners behind it cannot be
    // covered by any frustum, so they force the capped fov.
    float maxTan = 0.0f;
    float zmin = std::numeric_limits<float>::max();
    float zmax = 0.0f;
    behind = false;
    const auto corner = [](const Aabb& b, int i) {
        return glm::vec3{(i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y,
                         (i & 4) ? b.max.z : b.min.z};
    };
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 p = glm::vec3(v.view * glm::vec4(corner(casters, i), 1.0f));
        const float depth = -p.z;
        zmax = std::max(zmax, depth);
        if (depth <= 1e-6f * r) {
            behind = true;
            continue;
        }
        zmin = std::min(zmin, depth);
        maxTan = std::max({maxTan, std::abs(p.x) / depth, std::abs(p.y) / depth});
    }
    for (int i = 0; i < 8; ++i)
        zmax = std::max(zmax, -(v.view * glm::vec4(corner(scene, i), 1.0f)).z);
    if (!behind && lightRadius > 0.0f)
        maxTan = std::tan(std::atan(maxTan) + std::atan(lightRadius / zmin));
    const float capTan = std::tan(0.5f * maxFov);
    const float tanHalf = behind ? capTan : std::min(maxTan * 1.01f, capTan);
    v.znear = behind ? 1e-3f * 2.0f * r : std::max(zmin * 0.99f, 1e-3f * 2.0f * r);
    v.zfar = std::max(zmax * 1.01f, v.znear * 2.0f);
    v.proj = glm::perspective(2.0f * std::atan(tanHalf), 1.0f, v.znear, v.zfar);
    return v;
}

} // namespace

ViewVolume fitPerspectiveLight(const Aabb& bounds, glm::vec3 position, glm::vec3 axis,
                               float maxFov) {
    return fitPerspectiveLight(bounds, bounds, position, axis, 0.0f, maxFov);
}

ViewVolume fitPerspectiveLight(const Aabb& casters, const Aabb& scene, glm::vec3 position,
                               glm::vec3 axis, float lightRadius, float maxFov) {
    const float r = std::max(scene.radius(), 1e-4f);
    glm::vec3 dir = casters.center() - position;
    if (glm::length(dir) < 1e-6f * r) dir = glm::vec3(0.0f, -1.0f, 0.0f);
    bool behind = false;
    const ViewVolume toCentre =
        fitAlong(casters, scene, position, glm::normalize(dir), maxFov, lightRadius, behind);
    if (!behind || !(glm::length(axis) > 0.0f)) return toCentre;
    bool axisBehind = false;
    const ViewVolume along =
        fitAlong(casters, scene, position, glm::normalize(axis), maxFov, lightRadius, axisBehind);
    return axisBehind ? toCentre : along;
}

ViewVolume frameBounds(const Aabb& bounds, glm::vec3 fromDir, float yfov, float aspect) {
    fromDir = glm::normalize(fromDir);
    const glm::vec3 c = bounds.center();
    const float r = std::max(bounds.radius(), 1e-4f);
    // The sphere fits when its distance satisfies r / d = sin(half of the narrower fov).
    const float halfY = 0.5f * yfov;
    const float halfX = std::atan(std::tan(halfY) * std::max(aspect, 1e-3f));
    const float d = r / std::sin(std::min(halfX, halfY));
    ViewVolume v;
    v.view = glm::lookAt(c + fromDir * d, c, stableUp(fromDir));
    v.znear = std::max(d - r, 1e-3f * r) * 0.9f;
    v.zfar = (d + r) * 1.1f;
    v.proj = glm::perspective(yfov, aspect, v.znear, v.zfar);
    return v;
}

ViewVolume framePointsTightly(std::span<const glm::vec3> points, const Aabb& scene,
                              glm::vec3 fromDir, float yfov, float aspect, float fill) {
    fromDir = glm::normalize(fromDir);
    const glm::vec3 up = stableUp(fromDir);
    // The camera's axes as glm::lookAt builds them: side, up, and towards the eye.
    const glm::vec3 side = glm::normalize(glm::cross(-fromDir, up));
    const glm::vec3 camUp = glm::cross(side, -fromDir);
    const float halfY = std::tan(0.5f * yfov), halfX = halfY * std::max(aspect, 1e-3f);
    const glm::vec2 t = glm::vec2(halfX, halfY) * fill;
    // A point at (x, y) across and z towards the eye is in view from an eye at (ex, ey, D) when
    // |x - ex| <= tx (D - z), and likewise in y: D >= (ax - bx) / (2 tx) with ax = max(x + tx z),
    // bx = min(x - tx z), the least D at ex = (ax + bx) / 2.
    glm::vec2 a(std::numeric_limits<float>::lowest()), b(std::numeric_limits<float>::max());
    float zmax = std::numeric_limits<float>::lowest();
    Aabb all = scene;
    for (const glm::vec3& p : points) {
        const glm::vec2 xy(glm::dot(p, side), glm::dot(p, camUp));
        const float z = glm::dot(p, fromDir);
        a = glm::max(a, xy + t * z);
        b = glm::min(b, xy - t * z);
        zmax = std::max(zmax, z);
        all.extend(p);
    }
    const float r = std::max(all.radius(), 1e-4f);
    if (points.empty()) return frameBounds(all, fromDir, yfov, aspect);
    // Every point in front of the eye, if only just (points in a plane seen edge-on).
    const float d =
        std::max({(a.x - b.x) / (2.0f * t.x), (a.y - b.y) / (2.0f * t.y), zmax + 1e-3f * r});
    const glm::vec2 e = 0.5f * (a + b);
    const glm::vec3 eye = e.x * side + e.y * camUp + d * fromDir;
    ViewVolume v;
    v.view = glm::lookAt(eye, eye - fromDir, up);
    // No point of the scene's box is nearer than its nearest point, nor farther than its farthest
    // corner; a point in view at distance s has a depth of at least s times the cosine of the
    // frustum's half-diagonal.
    const float nearest = glm::length(glm::max(glm::max(all.min - eye, eye - all.max), 0.0f));
    const float farthest = glm::length(glm::max(glm::abs(all.min - eye), glm::abs(all.max - eye)));
    const float cosDiagonal = 1.0f / std::sqrt(1.0f + halfX * halfX + halfY * halfY);
    v.znear = std::max(0.9f * cosDiagonal * nearest, 1e-4f * r);
    v.zfar = std::max(1.1f * farthest, 2.0f * v.znear);
    v.proj = glm::perspective(yfov, aspect, v.znear, v.zfar);
    return v;
}

glm::mat4 clampDepthRange(const glm::mat4& proj, const glm::mat4& view, const Aabb& bounds) {
    // A perspective matrix has w_clip = -z_view: column 2, row 3 is -1 and column 3, row 3 is 0.
    if (proj[2][3] != -1.0f || proj[3][3] != 0.0f || !bounds.valid()) return proj;
    const float a = proj[2][2], b = proj[3][2];
    // z_ndc = (a z + b) / -z with z = -d: near plane d = b / (a - 1), far plane d = b / (a + 1).
    const float znear = b / (a - 1.0f), zfar = b / (a + 1.0f);
    if (!(znear > 0.0f) || !(zfar > znear) || !std::isfinite(zfar)) return proj;
    const Aabb v = bounds.transformed(view);
    const float dmin = std::max(znear, -v.max.z), dmax = std::min(zfar, -v.min.z);
    if (!(dmax > dmin * (1.0f + 1e-4f))) return proj;
    glm::mat4 out = proj;
    out[2][2] = -(dmax + dmin) / (dmax - dmin);
    out[3][2] = -2.0f * dmax * dmin / (dmax - dmin);
    return out;
}

} // namespace fl::geom
