#version 450 core
#include "bindings.glsl"
// One quad per row of tiles, over the span from the row's first to its last tile in a set
// (tile_dilate.comp.glsl writes the spans): draws a pass over (about) only that set. Instance
// i is tile row i; 6 vertices per instance (two triangles); a row without tiles is a degenerate
// quad.

// first, last per row
layout(std430, binding = FL_SSBO_ROW_SPANS) readonly buffer RowSpans { int rowSpans[]; };
uniform ivec2 uSize; // the target's texels
uniform int uTile;

void main() {
    int row = gl_InstanceID;
    int first = rowSpans[2 * row], last = rowSpans[2 * row + 1];
    const ivec2 corner[6] = ivec2[](ivec2(0, 0), ivec2(1, 0), ivec2(1, 1), ivec2(0, 0),
                                    ivec2(1, 1), ivec2(0, 1));
    ivec2 c = corner[gl_VertexID];
    vec2 texel = first > last ? vec2(0.0)
                              : vec2(c.x == 0 ? first * uTile : min((last + 1) * uTile, uSize.x),
                                     c.y == 0 ? row * uTile : min((row + 1) * uTile, uSize.y));
    gl_Position = vec4(texel / vec2(uSize) * 2.0 - 1.0, 0.0, 1.0);
}
