#pragma once
// Silhouette edges of the shadow map's receiver grid (shaders/occluder_edge.glsl, which this
// matches operation for operation): the test JFA-L's silhouette pass uses, and the occluder
// point moved from the texel's centre to the edge. See the GLSL file for why.

#include <renderer/soft/DiskLight.h>
#include <renderer/soft/PenumbraCriterion.h>

#include <glm/glm.hpp>

namespace fl {

/// Where an occluder texel's point lies: at the silhouette's edge (default), or at the texel's
/// centre (the thesis' construction).
enum class OccluderPoints { Edge, TexelCentre };

/// Depth jumps up to kSilhouetteSlope times the lateral distance are one continuous surface.
inline constexpr float kSilhouetteSlope = 3.0f;

/// The silhouette threshold of a scene: depth jumps under 1/1000 of its radius are no edge.
inline float silhouetteThreshold(float sceneRadius) {
    return 0.001f * (sceneRadius > 1e-3f ? sceneRadius : 1e-3f);
}

/// Whether receiver texel n lies across a silhouette edge from texel self: it sees nothing, or it
/// lies deeper from the light by more than threshold + kSilhouetteSlope * lateral distance.
bool acrossSilhouette(const DiskLight& light, glm::vec4 self, glm::vec4 n, float threshold);

/// Texel (x, y)'s receiver moved half a texel along its surface toward each axis neighbour
/// across a silhouette edge (its position unchanged where it has none, or one on both sides).
glm::vec3 occluderEdgePoint(const ReceiverGrid& receivers, const DiskLight& light, int x, int y,
                            float threshold);

} // namespace fl
