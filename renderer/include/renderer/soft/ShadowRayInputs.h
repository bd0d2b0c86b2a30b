#pragma once
// What the ray-traced ground truth (raytrace/ShadowRays.h) takes from a frame: the scene's
// triangles in world space, and one receiver per pixel of the frame's surfaces (step 2). Shared by
// the `raytrace` method and the benchmarks that measure it.

#include <raytrace/ShadowRays.h>
#include <renderer/metrics/BiasArtifacts.h>
#include <renderer/passes/SurfacesPass.h>
#include <scene/Pose.h>
#include <scene/Scene.h>

#include <vector>

namespace fl {

/// Every instance's triangles in world space, as the vertex stage places them. Throws
/// std::invalid_argument naming the node and mesh when a node's transform takes a vertex beyond
/// rt::kMaxCoordinate (the loader has already refused non-finite input). With the vertex normals
/// (for the terminator offset), turned as the vertex stage turns them. The triangles of MASK
/// and BLEND materials are cut out as the GL passes cut them (scene/AlphaCoverage.h);
/// that test reads `scene`, which must outlive the result and any RayScene built from it.
rt::Triangles worldTriangles(const Scene& scene);
/// The same triangles' vertices in `pose` (scene/Pose.h): what RayScene::refit takes
/// for an animated frame; their normals into `normals` when given.
std::vector<glm::vec3> worldVertices(const Scene& scene, const Pose& pose,
                                     std::vector<glm::vec3>* normals = nullptr);

/// One receiver per pixel of `surfaces`, in GL's row order (row 0 at the bottom): the world
/// position, the triangle's plane turned to the side the eye sees (by the shading normal), and
/// valid where a surface was drawn. Reads the targets back (the context must be current).
std::vector<rt::Receiver> surfaceReceivers(const SurfacesPass::Outputs& surfaces);

/// The same surfaces as the acne and peter-panning figures read them (metrics/BiasArtifacts.h):
/// positions, the receivers' planes and the receiver mask, row 0 at the top, and `camera`'s eye
/// and pixel size. Reads the targets back (the context must be current).
SurfaceGeometry surfaceGeometry(const SurfacesPass::Outputs& surfaces, const CameraView& camera);

} // namespace fl
