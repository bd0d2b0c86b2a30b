#pragma once
// The GPU half of the thesis' Delaunay pipeline (ch. 6, steps G1-G6), CPU backend, with every
// intermediate result kept for the step pictures (`floodlight delaunay --steps DIR`) and the
// window's Delaunay visualiser. Its output T'(S') (triangles on S', the sites that kept a pixel)
// plus the missing sites is what the CPU steps C1-C4 complete into the Delaunay triangulation.

#include <geometry/DiscreteTriangles.h>
#include <geometry/DiscreteVoronoi.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace fl::geom {

/// How discreteDelaunay() runs.
struct DiscreteDelaunayOptions {
    int size = 1024;            // texture side N (the thesis used up to 4096)
    std::string plan = "1+JFA"; // G2's flood plan (jfa::parsePlan spec); the thesis' is 1+JFA
    int threads = 0;            // worker threads per step; 0 = all hardware threads
    bool countIslands = false;  // also count G2's island components (a full labelling pass,
                                // outside the step timings)
};

/// Wall-clock milliseconds per step.
struct DiscreteTimings {
    double g1 = 0.0; // sites into the texture
    double g2 = 0.0; // 1+JFA
    double g3 = 0.0; // island removal
    double g4 = 0.0; // corner classification
    double g5 = 0.0; // row chains
    double g6 = 0.0; // triangles
    /// Sum of the six steps.
    [[nodiscard]] double total() const { return g1 + g2 + g3 + g4 + g5 + g6; }
};

/// Every stage of G1-G6.
struct DiscreteDelaunay {
    SnappedSites snapped;            // G1: mapping, each site's pixel, S', missing sites
    IdTexture voronoi;               // G2: D(S'), site id per pixel
    IdTexture cleaned;               // G3: D(S') without islands
    IslandStats islands;             // G3: passes and recoloured pixels
    std::int64_t islandsBefore = -1; // island components in `voronoi` (-1: not counted)
    CornerTexture corners;           // G4: case per corner
    VertexChain chain;               // G5: next vertex to the right per pixel
    DiscreteTriangles mesh;          // G6: T'(S') and its Voronoi vertices
    DiscreteTimings timings;

    /// T'(S') as a flat list of site indices, three per counterclockwise triangle.
    [[nodiscard]] const std::vector<std::uint32_t>& triangles() const { return mesh.triangles; }
    /// The sites that lost their pixel (with the site that kept it), for step C3.
    [[nodiscard]] const std::vector<MissingSite>& missing() const { return snapped.missing; }
};

/// Runs G1-G6 on `sites` (any finite points; indices are the ids everywhere). Throws
/// std::invalid_argument for a bad size, plan or site (the message says which).
DiscreteDelaunay discreteDelaunay(const std::vector<glm::dvec2>& sites,
                                  const DiscreteDelaunayOptions& options = {});

} // namespace fl::geom
