#pragma once
// An occluder's silhouette near a shadow-map texel as straight edges at sub-texel precision, and
// the share of the disk light a receiver sees past them, with other occluders fused in: the CPU
// twin of shaders/occluder_lines.glsl (operation for operation; the GLSL file says why). JFA-L's
// lookup and JFA-E's composite recompute a penumbra pixel's visibility with these.

#include <renderer/passes/ShadowMapPass.h>
#include <scene/DiskLight.h>

#include <glm/glm.hpp>

#include <vector>

namespace fl {

/// The shadow map as the edges read it: the receiver target (the light's unbiased NDC depth per
/// texel, shadowmap::kNoReceiver where it sees nothing) and the map's own (biased) depths for the
/// fused test, both size x size with row 0 at the bottom (GL order), and the matrices.
struct LineMap {
    int size = 0;
    std::vector<float> receiverDepth;
    std::vector<float> depth;
    glm::mat3 unwarp{1.0f};               // shadowmap::unwarp(warp)
    glm::mat4 inverseLightViewProj{1.0f}; // shadowmap::inverseLightViewProj(lightViewProj)
    glm::mat4 lightViewProj{1.0f}, warp{1.0f};
    DiskLight light;
};

/// A frame's shadow map read back (its receiver target and depths) as the edges read it.
LineMap readLineMap(const ShadowMapPass::Outputs& shadow, const DiskLight& light);

/// Up to two straight edges of an occluder, in world space (occluder_lines.glsl's struct).
struct OccluderLines {
    int count = 0;     // 0: none found, else 1 or 2
    bool slit = false; // two edges whose uncovered sides face each other (else a strip)
    glm::vec3 point[2]{};
    glm::vec3 tangent{0.0f};
    glm::vec3 open[2]{}; // towards each edge's uncovered side, a texel long at its depth
};

/// The occluder's edges in the 5 x 5 window around texel t as the receiver at p with surface
/// normal n sees them (covered: the light's centre sees something nearer than p's plane).
OccluderLines occluderLines(const LineMap& map, glm::ivec2 t, glm::vec3 p, glm::vec3 n);

/// The share of the disk p sees past the edges, other occluders fused in (what the map shows
/// nearer than p's plane where the rays cross the edge's depth, and `own`, the light depth of
/// the occluder over p, 0 for none), or -1 when no edge lies between p and the light.
float occluderLinesVisibilityFused(const LineMap& map, glm::vec3 p, glm::vec3 n,
                                   const OccluderLines& lines, float own);

/// The thesis' occluder point o fused the same way (its chord at right angles to cq), or -1 for
/// a miss.
float occluderPointVisibilityFused(const LineMap& map, glm::vec3 p, glm::vec3 n, glm::vec3 o,
                                   bool inside, float own);

/// A penumbra point's share from its occluder's edges `lines` (count 0: none found) or else the
/// occluder point o, fused, with the occluder over p's texel `own` crossed inside the hard shadow;
/// a borrowed occluder only through its edges and only where they keep p on its side of the hard
/// edge; -1 where neither shades p (occluderShareFused() in occluder_lines.glsl).
float occluderShareFused(const LineMap& map, glm::ivec2 own, glm::vec3 p, glm::vec3 n,
                         const OccluderLines& lines, glm::vec3 o, bool inside, bool borrowed);

/// What texel t of the receiver target sees: xyz its world position, w 1; vec4(0) for nothing
/// (mapReceiver() in shadow_map_decode.glsl).
glm::vec4 lineMapReceiver(const LineMap& map, glm::ivec2 t);

/// The light depth (along the disk's normal) of what texel t of the receiver target sees, 0
/// where it sees nothing.
float lineMapDepth(const LineMap& map, glm::ivec2 t);

/// The hard test of the map at world point p (hardShadow() in shadow_lookup.glsl): 1 lit (or
/// off the map), 0 shadowed.
float lineMapHardShadow(const LineMap& map, glm::vec3 p);

} // namespace fl
