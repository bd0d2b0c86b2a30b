#version 450 core
#include "bindings.glsl"
// One pass of step G5 (thesis §6.3.2, Fig. 6.7), chainRowsJfa in geometry/DiscreteTriangles.h:
// a one-sided 1D jump flood per row. A texel reads itself and the texel `step` to its right (if
// inside the row) and keeps the nearer (smaller x) Voronoi vertex, so after the halving steps
// every texel holds the first vertex at or right of it. The first pass seeds from the corner
// cases directly (a vertex is its own nearest vertex), which saves a seeding pass.
#include "delaunay_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = FL_TEX_DELAUNAY_CHAIN_IN) uniform isampler2D uSrc;     // the previous pass' chain
layout(binding = FL_TEX_DELAUNAY_CORNERS) uniform usampler2D uCorners; // G4's cases (first pass)
layout(binding = FL_IMG_DELAUNAY_OUT, r32i) uniform writeonly iimage2D uDst;
uniform ivec2 uSize;
uniform int uStep;
uniform int uFromCorners;

int nearestAt(ivec2 q) {
    if (uFromCorners != 0) return isVoronoiVertex(texelFetch(uCorners, q, 0).r) ? q.x : kNoVertex;
    return texelFetch(uSrc, q, 0).r;
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, uSize))) return;
    int best = nearestAt(p);
    if (p.x + uStep < uSize.x) {
        int right = nearestAt(p + ivec2(uStep, 0));
        if (right != kNoVertex && (best == kNoVertex || right < best)) best = right;
    }
    imageStore(uDst, p, ivec4(best));
}
