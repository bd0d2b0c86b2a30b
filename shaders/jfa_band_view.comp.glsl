#version 450 core
// Band-limited flooding, the view limit (jfa/Band.h, FloodRegion::View), between steps B and C:
// one invocation per full-resolution tile. A band tile with no view tile within uTileReach tiles
// (per axis) leaves the band: no texel the reader reads depends on it. Same as
// fl::jfa::limitToView on the CPU.

layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = 3) buffer Flags { uint flags[]; };
layout(std430, binding = 7) readonly buffer ViewTiles { uint viewTiles[]; };
uniform ivec2 uTiles; // tiles per axis
uniform int uTileReach;

void main() {
    ivec2 t = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(t, uTiles))) return;
    int i = t.y * uTiles.x + t.x;
    if (flags[i] == 0u) return;
    ivec2 lo = max(t - uTileReach, ivec2(0));
    ivec2 hi = min(t + uTileReach, uTiles - 1);
    for (int y = lo.y; y <= hi.y; ++y)
        for (int x = lo.x; x <= hi.x; ++x)
            if (viewTiles[y * uTiles.x + x] != 0u) return;
    flags[i] = 0u;
}
