// The seed list of band-limited flooding (step A0, jfa/Band.h): the seed texels packed
// x | y << 16, in any order (what reads it, step A, is order-independent), and step A's indirect
// dispatch. A pass that writes the seeds texture over the whole grid appends its seeds here
// itself (jfaListSeed; GlFloodKernelBase::beginSeedList), so that step A0 need not sweep the grid
// again; otherwise jfa_band_seeds.comp.glsl fills it.
#include "bindings.glsl"

layout(std430, binding = FL_SSBO_SEED_LIST) buffer SeedList {
    uint seedCount;
    uint dispatch[3];
    uint seeds[];
};

void jfaListSeed(ivec2 p) { seeds[atomicAdd(seedCount, 1u)] = uint(p.x) | (uint(p.y) << 16); }
