#version 450 core
#include "bindings.glsl"
// Between G6's two walks (thesis §6.3.2): an exclusive prefix sum over the corner rows of their
// vertex and triangle counts, so the second walk writes every row's records where the CPU's
// row-major order puts them and the host copies nothing into place. One work group: at most
// 8191 rows (kMaxDiscreteSize - 1), each invocation sums a run of consecutive rows.
#include "delaunay_common.glsl"

layout(local_size_x = 1024) in;

layout(std430, binding = FL_SSBO_DELAUNAY_HEADER) buffer Header { uint header[]; };
// Per corner row: vertices, triangles (first walk); first vertex, first triangle (written here).
layout(std430, binding = FL_SSBO_DELAUNAY_ROWS) buffer Rows { uvec4 rows[]; };
uniform int uRows;

shared uvec2 sums[1024];

void main() {
    uint i = gl_LocalInvocationID.x;
    uint count = uint(uRows);
    uint per = (count + 1023u) / 1024u;
    uint begin = min(i * per, count);
    uint end = min(begin + per, count);
    uvec2 own = uvec2(0u);
    for (uint y = begin; y < end; ++y) own += rows[y].xy;
    sums[i] = own;
    barrier();
    // Hillis-Steele inclusive scan over the 1024 run sums.
    for (uint d = 1u; d < 1024u; d <<= 1u) {
        uvec2 add = i >= d ? sums[i - d] : uvec2(0u);
        barrier();
        sums[i] += add;
        barrier();
    }
    uvec2 start = sums[i] - own;
    for (uint y = begin; y < end; ++y) {
        uvec2 here = rows[y].xy;
        rows[y].zw = start;
        start += here;
    }
    if (i == 1023u) {
        header[kHeadVertices] = sums[1023].x;
        header[kHeadTriangles] = sums[1023].y;
    }
}
