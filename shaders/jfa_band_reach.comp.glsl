#version 450 core
#include "bindings.glsl"
// Band-limited flooding, step A (jfa/Band.h): one invocation per seed of step A0's list. The
// criterion bounds where the seed's cell can be accepted (jfaSeedRect); clipped to the grid, the
// rect joins its tile's union (4 words per tile: min x, min y, max x, max y; an empty tile keeps
// min > max), and uMaxReach keeps the largest distance + 1 from a seed to its rect (for choosing
// a pass count). Same as fl::jfa::floodBand / maxSeedReach on the CPU before the plan's square.

layout(local_size_x = 64) in;

bool jfaEmpty(vec4 c);
vec4 jfaLoad(sampler2D grid, ivec2 q);
// Texels x0..x1 (.x, .z), y0..y1 (.y, .w) where seed cell c seeded at p may be accepted.
ivec4 jfaSeedRect(ivec2 p, vec4 c);

layout(binding = FL_TEX_FLOOD_SEEDS) uniform sampler2D uSeeds;
layout(std430, binding = FL_SSBO_BAND_TILE_RECTS) buffer TileRects { uint tileRects[]; };
layout(std430, binding = FL_SSBO_BAND_MAX_REACH) buffer MaxReach { uint maxReach; };
// The flood's front (jfa_band_front.comp.glsl): every seed's tile starts it.
layout(std430, binding = FL_SSBO_FLOOD_FRONT) buffer Front { uint front[]; };
layout(std430, binding = FL_SSBO_SEED_LIST) readonly buffer SeedList {
    uint seedCount;
    uint dispatch[3];
    uint seeds[];
};
uniform ivec2 uSize;
uniform int uTile;
uniform int uTilesX;

void main() {
    if (gl_GlobalInvocationID.x >= seedCount) return;
    uint entry = seeds[gl_GlobalInvocationID.x];
    ivec2 p = ivec2(int(entry & 0xffffu), int(entry >> 16));
    vec4 c = jfaLoad(uSeeds, p);
    front[(p.y / uTile) * uTilesX + p.x / uTile] = 1u;
    ivec4 r = jfaSeedRect(p, c);
    r.xy = max(r.xy, ivec2(0));
    r.zw = min(r.zw, uSize - 1);
    if (r.x > r.z || r.y > r.w) return; // accepted nowhere on the grid
    ivec2 t = p / uTile;
    uint base = uint(t.y * uTilesX + t.x) * 4u;
    atomicMin(tileRects[base + 0u], uint(r.x));
    atomicMin(tileRects[base + 1u], uint(r.y));
    atomicMax(tileRects[base + 2u], uint(r.z));
    atomicMax(tileRects[base + 3u], uint(r.w));
    ivec2 far = max(p - r.xy, r.zw - p);
    atomicMax(maxReach, uint(max(max(far.x, far.y), 0)) + 1u);
}
