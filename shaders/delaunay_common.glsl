// Shared by the Delaunay step kernels (geometry/GlDiscreteDelaunay.h, thesis §6.3.2 G1-G6):
// the constants of geometry/DiscreteVoronoi.h and DiscreteTriangles.h, which these must match.

const uint kNoSite = 0xffffffffu; // fl::geom::kNoSite
const int kNoVertex = -1;         // fl::geom::kNoVertex

// fl::geom::CornerCase values.
const uint kCaseNone = 0u;
const uint kCaseThreeA = 1u;
const uint kCaseThreeB = 2u;
const uint kCaseThreeC = 3u;
const uint kCaseThreeD = 4u;
const uint kCaseFour = 5u;
const uint kCaseExcludedA = 6u;
const uint kCaseExcludedB = 7u;
const uint kCaseAlternating = 8u;

#include "delaunay_result.glsl"

bool isVoronoiVertex(uint c) { return c >= kCaseThreeA && c <= kCaseFour; }

// The index of a 1D item in a dispatch that may be 2D: 2^24 sites need more work groups than
// the x dimension allows (65535), so the host spreads them over y as well. `groupSize` is the
// kernel's local_size_x (gl_WorkGroupSize is not declared yet where this file is included).
uint dispatchIndex(uint groupSize) {
    return gl_GlobalInvocationID.y * (gl_NumWorkGroups.x * groupSize) + gl_GlobalInvocationID.x;
}
