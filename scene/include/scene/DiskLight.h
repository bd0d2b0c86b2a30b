#pragma once
// The disk area light of the soft-shadow methods (thesis §5.2) and the occluder intensity:
// a point p that receives occluder point o shoots the ray p -> o; if it meets the light's disk
// at q, the chord through q perpendicular to cq (c the disk's centre) splits the disk, and the
// part on p's side of the occluder is what p sees. Outside the hard shadow (p sees c) that is
// the part holding c; inside (JFA-E's inner penumbrae) it is the other part. The shaders
// (shaders/disk_light.glsl) compute the same in float with the same operations.

#include <scene/Scene.h>

#include <base/Aabb.h>

#include <optional>

namespace fl {

/// A disk light: centre, unit normal (the direction the light faces) and radius.
struct DiskLight {
    glm::vec3 center{0.0f};
    glm::vec3 normal{0.0f, -1.0f, 0.0f};
    float radius = 0.0f;
};

/// The scene light as a disk of the light's radius: spot lights face along their direction,
/// point lights face the scene's centre, and a directional light becomes a disk two scene radii
/// back from the scene's centre (where its shadow map's volume starts), facing along the light.
DiskLight makeDiskLight(const Light& light, const geom::Aabb& bounds);

/// Area of the part of a unit-area disk beyond a chord at distance t * radius from the centre
/// (t in [0, 1]): (acos t - t sqrt(1 - t^2)) / pi. 0.5 at t = 0, 0 at t = 1.
float segmentFraction(float t);

/// Where the ray from p through o meets the light's plane, relative to the disk: the squared
/// distance |cq|^2, or nullopt when the ray does not reach the plane beyond o (o is not between
/// p and the light) or misses the disk (|cq| >= radius).
std::optional<float> occluderHit(const DiskLight& light, glm::vec3 p, glm::vec3 o);

/// occluderHit() as a plain float: |cq|^2, or -1 for a miss. Bit-identical to penumbraHit() in
/// shaders/disk_light.glsl.
float occluderHitDistance2(const DiskLight& light, glm::vec3 p, glm::vec3 o);

/// JFA-L's umbra side (--penumbra both): the key of occluder o at a shadow-map texel whose surface
/// r lies no deeper from the light's plane than o (r may hide a receiver in o's umbra): |cq|^2 +
/// radius^2 for the stand-in receiver on the ray from the disk's centre through r at depth
/// `umbraDepth` (the deepest a receiver can lie), or -1 for a miss (or a surface deeper than o,
/// or umbraDepth 0: off). The + radius^2 ranks every such key after every key of r itself
/// (occluderHitDistance2 < radius^2). Bit-identical to umbraSideKey() in disk_light.glsl.
float umbraSideKey(const DiskLight& light, glm::vec3 r, glm::vec3 o, float umbraDepth);

/// Visible fraction of the light at p with occluder o (nullopt when the ray misses, see
/// occluderHit): 1 - segmentFraction(|cq| / r) outside the hard shadow, segmentFraction inside.
std::optional<float> occluderIntensity(const DiskLight& light, glm::vec3 p, glm::vec3 o,
                                       bool insideHardShadow);

} // namespace fl
