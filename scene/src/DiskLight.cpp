#include <scene/DiskLight.h>

#include <algorithm>
#include <cmath>

namespace fl {

DiskLight makeDiskLight(const Light& light, const geom::Aabb& bounds) {
    DiskLight d;
    d.radius = std::max(light.radius, 0.0f);
    const float r = std::max(bounds.radius(), 1e-3f);
    switch (light.type) {
    case Light::Type::Spot:
        d.center = light.position;
        d.normal = glm::normalize(light.direction);
        break;
    case Light::Type::Point: {
        d.center = light.position;
        const glm::vec3 toScene = bounds.center() - light.position;
        d.normal = glm::length(toScene) > 1e-6f * r ? glm::normalize(toScene)
                                                    : glm::vec3(0.0f, -1.0f, 0.0f);
        break;
    }
    case Light::Type::Directional:
        // A directional light has no position; the disk is placed where the shadow map's
        // light volume starts (two scene radii back from the centre, geom::fitDirectionalLight),
        // so its radius keeps the meaning "radius in scene units" at the scene's distance.
        d.normal = glm::normalize(light.direction);
        d.center = bounds.center() - d.normal * (2.0f * r);
        break;
    }
    return d;
}

float segmentFraction(float t) {
    t = std::clamp(t, 0.0f, 1.0f);
    return (std::acos(t) - t * std::sqrt(1.0f - t * t)) / 3.14159265358979f;
}

float occluderHitDistance2(const DiskLight& light, glm::vec3 p, glm::vec3 o) {
    // Written out operation by operation, in the order of penumbraHit() in
    // shaders/disk_light.glsl (built without fused multiply-add on both sides), so that CPU and
    // GL floods make identical choices.
    // q = p + s (o - p) on the plane dot(x - c, n) = 0: s = dot(c - p, n) / dot(o - p, n); the
    // occluder must lie strictly between p and the plane: s > 1.
    const glm::vec3 n = light.normal;
    const float dx = o.x - p.x, dy = o.y - p.y, dz = o.z - p.z;
    const float den = dx * n.x + dy * n.y + dz * n.z;
    const float num =
        (light.center.x - p.x) * n.x + (light.center.y - p.y) * n.y + (light.center.z - p.z) * n.z;
    if (!(den != 0.0f)) return -1.0f;
    const float s = num / den;
    if (!(s > 1.0f)) return -1.0f;
    const float qx = (p.x + dx * s) - light.center.x;
    const float qy = (p.y + dy * s) - light.center.y;
    const float qz = (p.z + dz * s) - light.center.z;
    const float d2 = qx * qx + qy * qy + qz * qz;
    if (!(d2 < light.radius * light.radius)) return -1.0f;
    return d2;
}

float umbraSideKey(const DiskLight& light, glm::vec3 r, glm::vec3 o, float umbraDepth) {
    // The order of umbraSideKey() in shaders/disk_light.glsl, operation by operation.
    const glm::vec3 n = light.normal;
    const glm::vec3 c = light.center;
    const float dr = std::abs((r.x - c.x) * n.x + (r.y - c.y) * n.y + (r.z - c.z) * n.z);
    const float dO = std::abs((o.x - c.x) * n.x + (o.y - c.y) * n.y + (o.z - c.z) * n.z);
    // Only a surface no deeper than o can hide a receiver under o's occluder; and the stand-in
    // must lie beyond the surface.
    if (!(dr <= dO * 1.001f) || !(dr > 0.0f) || !(umbraDepth > dr)) return -1.0f;
    const float k = umbraDepth / dr;
    const glm::vec3 p((r.x - c.x) * k + c.x, (r.y - c.y) * k + c.y, (r.z - c.z) * k + c.z);
    const float d2 = occluderHitDistance2(light, p, o);
    if (d2 < 0.0f) return -1.0f;
    return d2 + light.radius * light.radius;
}

std::optional<float> occluderHit(const DiskLight& light, glm::vec3 p, glm::vec3 o) {
    const float d2 = occluderHitDistance2(light, p, o);
    if (d2 < 0.0f) return std::nullopt;
    return d2;
}

std::optional<float> occluderIntensity(const DiskLight& light, glm::vec3 p, glm::vec3 o,
                                       bool insideHardShadow) {
    const std::optional<float> d2 = occluderHit(light, p, o);
    if (!d2) return std::nullopt;
    const float seg = segmentFraction(std::sqrt(*d2) / light.radius);
    return insideHardShadow ? seg : 1.0f - seg;
}

} // namespace fl
