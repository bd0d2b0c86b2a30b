#pragma once
// Silhouette edges of the shadow map's receiver grid (shaders/occluder_edge.glsl, which this
// matches operation for operation): the test JFA-L's silhouette pass uses, and the occluder
// point moved from the texel's centre to the edge. See the GLSL file for why.

#include <renderer/soft/PenumbraCriterion.h>
#include <scene/DiskLight.h>

#include <glm/glm.hpp>

#include <cstdint>

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

/// Which axis neighbours of texel (x, y) lie across a silhouette edge on one side only: two bits
/// per axis (x bits 0-1, y bits 2-3), 1 edge on the high side, 2 on the low side, 0 neither.
std::uint32_t occluderEdgeCode(const ReceiverGrid& receivers, const DiskLight& light, int x, int y,
                               float threshold);
/// Texel (x, y)'s receiver moved half a texel along its surface as `code` (occluderEdgeCode)
/// says: the point a packed occluder decodes to without the neighbourhood test.
glm::vec3 occluderEdgeApply(const ReceiverGrid& receivers, int x, int y, std::uint32_t code);

/// Texel (x, y)'s receiver moved half a texel along its surface toward each axis neighbour
/// across a silhouette edge (its position unchanged where it has none, or one on both sides).
glm::vec3 occluderEdgePoint(const ReceiverGrid& receivers, const DiskLight& light, int x, int y,
                            float threshold);

} // namespace fl
