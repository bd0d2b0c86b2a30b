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

// The result buffer's header (uint words; GlDiscreteDelaunayDetail.h's ResultHeader mirrors it):
// what G3, G4 and G6 counted, read back with the triangles in run()'s one read-back.
const uint kHeadVertices = 0u;      // G6: Voronoi vertices (all rows)
const uint kHeadTriangles = 1u;     // G6: triangles
const uint kHeadStats = 2u;         // G6: TriangleStats, 4 words
const uint kHeadPasses = 6u;        // G3: IslandStats::passes
const uint kHeadReassignedLo = 7u;  // G3: IslandStats::reassigned, low and high word
const uint kHeadReassignedHi = 8u;
const uint kHeadConverged = 9u;     // G3: IslandStats::converged
const uint kHeadUnfinished = 10u;   // G3: 1 if the queued passes ended before the loop did
const uint kHeadCorners = 11u;      // G4: corners per CornerCase, 9 words

// G3's loop state between passes (delaunay_islands_control.comp.glsl), uint words.
const uint kCtlGroupsX = 0u; // the next pass' indirect dispatch (x = 0 once the loop ended)
const uint kCtlGroupsY = 1u;
const uint kCtlGroupsZ = 2u;
const uint kCtlActive = 3u;       // 1 while passes run
const uint kCtlPasses = 4u;       // passes run
const uint kCtlChanging = 5u;     // passes that recoloured something
const uint kCtlReassignedLo = 6u; // recoloured pixels, low and high word
const uint kCtlReassignedHi = 7u;
const uint kCtlConverged = 8u; // 0 if the cap stopped the loop
const uint kCtlChanged = 9u;   // the running pass' atomic counter

bool isVoronoiVertex(uint c) { return c >= kCaseThreeA && c <= kCaseFour; }

// The index of a 1D item in a dispatch that may be 2D: 2^24 sites need more work groups than
// the x dimension allows (65535), so the host spreads them over y as well. `groupSize` is the
// kernel's local_size_x (gl_WorkGroupSize is not declared yet where this file is included).
uint dispatchIndex(uint groupSize) {
    return gl_GlobalInvocationID.y * (gl_NumWorkGroups.x * groupSize) + gl_GlobalInvocationID.x;
}
