#version 450 core
#include "bindings.glsl"
// Band-limited flooding, the flood's front (jfa/Band.h): before each pass of a one-stage plan,
// the band tiles that may change, as a tile list and indirect commands like step C's. A texel
// can take a cell only from the 9 texels at (i, j) * step around it; when every tile those
// lie in has held nothing but the empty cell so far (uFront: one flag per tile, set by the
// seeds and by every pass that wrote a non-empty cell there), the texel stays empty, and so
// does what the ping-pong texture already holds there. One invocation per tile of the grid.

layout(local_size_x = 8, local_size_y = 8) in;

// the band (step B)
layout(std430, binding = FL_SSBO_BAND_FLAGS) readonly buffer Flags { uint flags[]; };
#include "jfa_band_list.glsl" // [3] sums the texels over the run's passes
layout(std430, binding = FL_SSBO_FLOOD_FRONT) readonly buffer Front { uint front[]; };
uniform ivec2 uTiles;
uniform ivec2 uSize;
uniform int uTile;
uniform int uStep;

void main() {
    ivec2 t = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(t, uTiles)) || flags[t.y * uTiles.x + t.x] == 0u) return;
    ivec2 first = t * uTile;
    ivec2 last = min(first + uTile - 1, uSize - 1);
    bool live = false;
    for (int j = -1; j <= 1; ++j) {
        for (int i = -1; i <= 1; ++i) {
            // The candidates' texels for this offset, clipped to the grid (the passes ignore
            // candidates outside it), and the tiles they lie in.
            ivec2 lo = max(first + ivec2(i, j) * uStep, ivec2(0));
            ivec2 hi = min(last + ivec2(i, j) * uStep, uSize - 1);
            if (any(greaterThan(lo, hi))) continue;
            ivec2 a = lo / uTile, b = hi / uTile;
            for (int y = a.y; y <= b.y; ++y)
                for (int x = a.x; x <= b.x; ++x) live = live || front[y * uTiles.x + x] != 0u;
        }
    }
    if (live) jfaAppendTile(t, last + 1 - first);
}
