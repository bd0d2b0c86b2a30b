#version 450 core
#include "bindings.glsl"
// One half of widening a set of tiles by uReach tiles per axis (a square), along axis uAxis
// (0: x, 1: y): a tile is set when a source tile within uReach along the axis is. Run along x,
// then along y (fl::jfa::GlTileDilation; fl::jfa::viewRegion on the CPU): the view limit's
// region around the tiles a reader reads.

layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = FL_SSBO_DILATE_IN) readonly buffer Source { uint source[]; };
layout(std430, binding = FL_SSBO_DILATE_OUT) writeonly buffer Widened { uint widened[]; };
// uSpans (0 to 2) span lists, two ints per row, each starting from (tiles, -1) or from spans of
// before, widened to each row's first and last set tile (JFA-L draws them: tile_rows.vert.glsl).
layout(std430, binding = FL_SSBO_ROW_SPANS) buffer RowSpans { int rowSpans[]; };
layout(std430, binding = FL_SSBO_OWN_SPANS) buffer OwnSpans { int ownSpans[]; };
uniform int uSpans;
uniform ivec2 uTiles;
uniform int uReach;
uniform int uAxis;

void main() {
    ivec2 t = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(t, uTiles))) return;
    ivec2 step = uAxis == 0 ? ivec2(1, 0) : ivec2(0, 1);
    int at = uAxis == 0 ? t.x : t.y;
    int last = (uAxis == 0 ? uTiles.x : uTiles.y) - 1;
    uint set = 0u;
    for (int k = max(at - uReach, 0); k <= min(at + uReach, last); ++k) {
        ivec2 q = t + step * (k - at);
        set |= source[q.y * uTiles.x + q.x];
    }
    widened[t.y * uTiles.x + t.x] = set != 0u ? 1u : 0u;
    if (set != 0u && uSpans > 0) {
        atomicMin(rowSpans[2 * t.y], t.x);
        atomicMax(rowSpans[2 * t.y + 1], t.x);
    }
    if (set != 0u && uSpans > 1) {
        atomicMin(ownSpans[2 * t.y], t.x);
        atomicMax(ownSpans[2 * t.y + 1], t.x);
    }
}
