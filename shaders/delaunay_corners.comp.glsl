#version 450 core
#include "bindings.glsl"
// Step G4 (thesis §6.3.2), classifyCorner in geometry/DiscreteTriangles.h: the corner
// (x + 0.5, y + 0.5) by the colours of its pixels 1 = (x, y), 2 = (x+1, y), 3 = (x+1, y+1),
// 4 = (x, y+1), stored at pixel 1; the last row and column (border corners) are case 1. Each
// non-None corner also bumps its case's count in the result header (None is the rest, which the
// host derives).
#include "delaunay_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = FL_TEX_DELAUNAY_IDS) uniform usampler2D uIds;
layout(binding = FL_IMG_DELAUNAY_OUT, r8ui) uniform writeonly uimage2D uCorners;
layout(std430, binding = FL_SSBO_DELAUNAY_HEADER) buffer Header { uint header[]; };
uniform ivec2 uSize;

uint classifyCorner(uint c1, uint c2, uint c3, uint c4) {
    // Fig. 6.10 first: two alternating colours get their own value (§6.4 says they never occur).
    if (c1 == c3 && c2 == c4) return c1 == c2 ? kCaseNone : kCaseAlternating;
    int colours = 1 + int(c2 != c1) + int(c3 != c1 && c3 != c2) +
                  int(c4 != c1 && c4 != c2 && c4 != c3);
    if (colours <= 2) return kCaseNone;
    if (colours == 4) return kCaseFour;
    // Three colours: an edge-adjacent equal pair is a vertex (subcases a-d); a diagonal pair is
    // a slim region cutting the other two apart (Fig. 6.6), not a vertex.
    if (c1 == c2) return kCaseThreeA;
    if (c2 == c3) return kCaseThreeB;
    if (c3 == c4) return kCaseThreeC;
    if (c4 == c1) return kCaseThreeD;
    if (c2 == c4) return kCaseExcludedA;
    return kCaseExcludedB;
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, uSize))) return;
    uint c = kCaseNone;
    if (p.x + 1 < uSize.x && p.y + 1 < uSize.y) {
        c = classifyCorner(texelFetch(uIds, p, 0).r, texelFetch(uIds, p + ivec2(1, 0), 0).r,
                           texelFetch(uIds, p + ivec2(1, 1), 0).r,
                           texelFetch(uIds, p + ivec2(0, 1), 0).r);
        if (c != kCaseNone) atomicAdd(header[kHeadCorners + c], 1u);
    }
    imageStore(uCorners, p, uvec4(c));
}
