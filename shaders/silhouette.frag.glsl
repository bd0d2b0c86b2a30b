#version 450 core
#include "bindings.glsl"
// JFA-L phase 2 (thesis §5.3.1, "Locating Occluders"): a shadow-map texel is a silhouette
// pixel, and so a seed (stored as its texel's tag, mapSeedTag; its occluder is the surface the
// texel sees), if one of its 8 neighbours sees nothing, or
// lies across a silhouette edge (acrossSilhouette, occluder_edge.glsl). Same as
// fl::silhouetteSeeds on the CPU.
#include "disk_light.glsl"
#include "shadow_map_decode.glsl"
#include "occluder_edge.glsl"
#include "jfa_seed_list.glsl"

// the map's receiver target (MapPositions)
layout(binding = FL_TEX_SILHOUETTE_RECEIVERS) uniform sampler2D uReceivers;
uniform float uSilhouetteThreshold;
uniform int uListSeeds; // append each seed to the band's seed list (jfa_seed_list.glsl)
// With SILHOUETTE_REGION (--flood-region view): only the tiles of the seed region (one uint per
// tile) can hold seeds (PenumbraMapPass::Inputs::viewSeedReach). The pass then draws only its
// rows' spans (tile_rows.vert.glsl), since llvmpipe runs a fragment's whole shader whatever it
// branches on: the texels outside are cleared beforehand, those in a span but not the region are
// emptied here. A define, not a uniform, so that the whole-map pass reads no buffer.
#ifdef SILHOUETTE_REGION
uniform int uRegionTile;
uniform int uRegionTilesX;
layout(std430, binding = FL_SSBO_SEED_REGION) readonly buffer SeedRegion { uint seedRegion[]; };
#endif

layout(location = 0) out float oSeed; // packed: the seed's tag, 0 none (jfa_penumbra.glsl)

void main() {
    ivec2 t = ivec2(gl_FragCoord.xy);
#ifdef SILHOUETTE_REGION
    ivec2 r = t / uRegionTile;
    if (seedRegion[r.y * uRegionTilesX + r.x] == 0u) {
        oSeed = 0.0;
        return;
    }
#endif
    ivec2 size = textureSize(uReceivers, 0);
    vec4 self = mapReceiver(uReceivers, t);
    bool silhouette = false;
    for (int j = -1; j <= 1; ++j) {
        for (int i = -1; i <= 1; ++i) {
            ivec2 q = t + ivec2(i, j);
            bool inside = all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, size));
            vec4 n = mapReceiver(uReceivers, clamp(q, ivec2(0), size - 1));
            bool edge = acrossSilhouette(self, n, uSilhouetteThreshold);
            silhouette = silhouette || (inside && (i != 0 || j != 0) && edge);
        }
    }
    bool seed = self.w != 0.0 && silhouette;
    oSeed = seed ? mapSeedTag(t, size.x) : 0.0;
    if (seed && uListSeeds != 0) jfaListSeed(t);
}
