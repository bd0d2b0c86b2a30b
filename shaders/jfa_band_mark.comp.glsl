#version 450 core
#include "bindings.glsl"
// Band-limited flooding, step B: one invocation per full-resolution tile. A tile holding seeds
// marks every tile its rect (the union of its seeds' rects, step A) touches, within the square
// the plan can reach from the tile. Same as fl::jfa::markTiles on the CPU.

layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = FL_SSBO_BAND_TILE_RECTS) readonly buffer TileRects { uint tileRects[]; };
layout(std430, binding = FL_SSBO_BAND_FLAGS) writeonly buffer Flags { uint flags[]; };
uniform ivec2 uTiles; // tiles per axis
uniform int uTile;
uniform int uPlanReach;

void main() {
    ivec2 t = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(t, uTiles))) return;
    uint base = uint(t.y * uTiles.x + t.x) * 4u;
    uvec4 r = uvec4(tileRects[base], tileRects[base + 1u], tileRects[base + 2u],
                    tileRects[base + 3u]);
    if (r.x > r.z || r.y > r.w) return; // no seed accepted anywhere
    // The plan's square around the tile's texels (r < 2^30, grids < 2^14: no overflow).
    ivec2 lo = max(ivec2(r.xy), t * uTile - uPlanReach) / uTile;
    ivec2 hi = min(ivec2(r.zw), t * uTile + uTile - 1 + uPlanReach) / uTile;
    for (int y = lo.y; y <= hi.y; ++y)
        for (int x = lo.x; x <= hi.x; ++x) flags[y * uTiles.x + x] = 1u;
}
