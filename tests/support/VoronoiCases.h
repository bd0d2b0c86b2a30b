#pragma once
// Seed grids that are hard for jump flooding and for a repair built on Delaunay graphs (issue 31
// item 3): uniform, clustered, collinear and co-circular integer sites, and masks. Shared by the
// CPU and GL tests of the exact Voronoi repair.

#include <jfa/Grid.h>

#include <string>
#include <vector>

namespace fl::test {

struct VoronoiCase {
    std::string name;
    jfa::Grid seeds; // integer sites at their own pixels (seedPoints / seedMask)
};

/// Every kind of case on grids of at most `maxSide` per side (>= 64), deterministic.
std::vector<VoronoiCase> voronoiCases(int maxSide);

} // namespace fl::test
