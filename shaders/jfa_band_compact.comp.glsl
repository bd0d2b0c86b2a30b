#version 450 core
#include "bindings.glsl"
// Band-limited flooding, step C: one invocation per tile of a stage grid (at scale uScale: its
// texel t stands for full-resolution grid point t * uScale). A stage tile is in the band when a
// full-resolution tile holding any of its grid points is; it is appended to the tile list and
// counted in the indirect dispatch (groups x).

layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = FL_SSBO_BAND_FLAGS) readonly buffer Flags { uint flags[]; };
#include "jfa_band_list.glsl"
uniform ivec2 uStageTiles; // tiles per axis of the stage grid
uniform ivec2 uStageSize;  // the stage grid
uniform ivec2 uTiles;      // full-resolution tiles per axis
uniform int uTile;
uniform int uScale;

void main() {
    ivec2 t = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(t, uStageTiles))) return;
    ivec2 first = t * uTile * uScale / uTile;
    ivec2 last = min((t * uTile + uTile - 1), uStageSize - 1) * uScale / uTile;
    last = min(last, uTiles - 1);
    bool inBand = false;
    for (int y = first.y; y <= last.y; ++y)
        for (int x = first.x; x <= last.x; ++x) inBand = inBand || flags[y * uTiles.x + x] != 0u;
    if (inBand) jfaAppendTile(t, min(t * uTile + uTile, uStageSize) - t * uTile);
}
