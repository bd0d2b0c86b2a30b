// The Delaunay result buffer's header and G3's loop state, in uint words: the one definition the
// step kernels (delaunay_common.glsl) and the host (geometry/src/GlDiscreteDelaunayDetail.h,
// which includes this file with `uint` as std::uint32_t) both read. Only `const uint` lines, so
// the file is valid GLSL and C++.
#ifndef FL_DELAUNAY_RESULT_GLSL
#define FL_DELAUNAY_RESULT_GLSL

// What G3, G4 and G6 counted, read back with the triangles in run()'s one read-back.
const uint kHeadVertices = 0u;     // G6: Voronoi vertices (all rows)
const uint kHeadTriangles = 1u;    // G6: triangles
const uint kHeadStats = 2u;        // G6: TriangleStats, 4 words in declaration order
const uint kHeadPasses = 6u;       // G3: IslandStats::passes
const uint kHeadReassignedLo = 7u; // G3: IslandStats::reassigned, low and high word
const uint kHeadReassignedHi = 8u;
const uint kHeadConverged = 9u;   // G3: IslandStats::converged
const uint kHeadUnfinished = 10u; // G3: 1 if the queued passes ended before the loop did
const uint kHeadCorners = 11u;    // G4: corners per CornerCase, kCornerCaseCount (9) words
const uint kHeaderWords = 32u;    // the header's size; the result's parts follow it

// G3's loop state between passes (delaunay_islands_control.comp.glsl).
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

#endif
