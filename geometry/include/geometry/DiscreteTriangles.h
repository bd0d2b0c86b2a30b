#pragma once
// Steps G4-G6 of the thesis' Delaunay pipeline (ch. 6, §6.3.2), CPU backend: Voronoi vertices on
// pixel corners (G4), chaining them along rows by a one-sided 1D JFA (G5), and one or two
// triangles per vertex (G6), the mesh T'(S') that the CPU steps C1-C4 complete.
//
// Corners. The corner (x + 0.5, y + 0.5) is shared by four pixels, numbered as in Fig. 6.6
// counterclockwise from the lower left (the figure's drawing is not in our copy; its text fixes
// only that 1-2, 2-3, 3-4, 4-1 share an edge and 1-3, 2-4 a corner, and we read it CCW):
//
//     4 = (x, y+1)    3 = (x+1, y+1)
//     1 = (x, y)      2 = (x+1, y)
//
// Its case is stored at pixel 1, the lower-left one (as the thesis does). The last column and
// row hold corners on the texture border, which have at most two colours and are never vertices.

#include <geometry/DiscreteVoronoi.h>

#include <glm/glm.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace fl::geom {

/// G4's classification of a corner by the colours of its pixels 1-4 (thesis §6.3.2, step G4).
enum class CornerCase : std::uint8_t {
    None = 0,        // case 1: one or two colours, not a Voronoi vertex
    ThreeA = 1,      // case 2 (a): pixels 1, 2 share a colour, 3 and 4 have the other two
    ThreeB = 2,      // case 2 (b): pixels 2, 3 share a colour, 4 and 1 have the other two
    ThreeC = 3,      // case 2 (c): pixels 3, 4 share a colour, 1 and 2 have the other two
    ThreeD = 4,      // case 2 (d): pixels 4, 1 share a colour, 2 and 3 have the other two
    Four = 5,        // case 3: four colours, a vertex with two triangles
    ExcludedA = 6,   // Fig. 6.6(a): pixels 2, 4 (diagonal) share a colour; not a vertex
    ExcludedB = 7,   // Fig. 6.6(b): pixels 1, 3 (diagonal) share a colour; not a vertex
    Alternating = 8, // Fig. 6.10: two colours alternate (1 = 3, 2 = 4); case 1, kept apart
                     // because §6.4 argues it cannot occur
};
/// Number of CornerCase values (for per-case counts).
inline constexpr std::size_t kCornerCaseCount = 9;

/// Whether a corner of this case is a Voronoi vertex (case 2 (a)-(d) and case 3).
[[nodiscard]] constexpr bool isVoronoiVertex(CornerCase c) {
    return c >= CornerCase::ThreeA && c <= CornerCase::Four;
}
/// Triangles G6 makes from a corner of this case: 1 for case 2 (a)-(d), 2 for case 3, else 0.
[[nodiscard]] constexpr int trianglesOf(CornerCase c) {
    return c == CornerCase::Four ? 2 : (isVoronoiVertex(c) ? 1 : 0);
}

/// G4's classification of the corner whose pixels 1-4 (numbered as above) have colours c1..c4.
[[nodiscard]] CornerCase classifyCorner(std::uint32_t c1, std::uint32_t c2, std::uint32_t c3,
                                        std::uint32_t c4);

/// One CornerCase per pixel: entry (x, y) is the corner (x + 0.5, y + 0.5); plus per-case counts.
struct CornerTexture {
    int width = 0;
    int height = 0;
    std::vector<CornerCase> cases;
    std::array<std::int64_t, kCornerCaseCount> counts{}; // corners per CornerCase value

    [[nodiscard]] CornerCase at(int x, int y) const {
        return cases[std::size_t(y) * std::size_t(width) + std::size_t(x)];
    }
    /// Corners of case `c`.
    [[nodiscard]] std::int64_t count(CornerCase c) const {
        return counts[static_cast<std::size_t>(c)];
    }
    friend bool operator==(const CornerTexture&, const CornerTexture&) = default;
};

/// G4: classifies every corner of `ids` (after G3). Results do not depend on `threads`.
CornerTexture classifyCorners(const IdTexture& ids, int threads = 0);

/// "No vertex to the right" in a VertexChain.
inline constexpr std::int32_t kNoVertex = -1;

/// G5's per-pixel record: next(x, y) = the smallest x' >= x whose corner (x', y) is a Voronoi
/// vertex, or kNoVertex. Walking a row: v = next(0, y), then v = next(v + 1, y), ... (Fig. 6.7).
struct VertexChain {
    int width = 0;
    int height = 0;
    std::vector<std::int32_t> next;

    [[nodiscard]] std::int32_t at(int x, int y) const {
        return next[std::size_t(y) * std::size_t(width) + std::size_t(x)];
    }
    friend bool operator==(const VertexChain&, const VertexChain&) = default;
};

/// G5 as the GPU runs it: a 1D JFA per row with steps jfa::jfaSteps(width) whose information
/// travels only leftwards (each pass reads its own texel and the one `step` to its right, keeps
/// the nearer vertex at or right of itself), ping-pong between passes. It is exact: the steps
/// sum to >= width - 1 and reach every offset (Property 3.1).
VertexChain chainRowsJfa(const CornerTexture& corners, int threads = 0);

/// G5 by one right-to-left scan per row: the same data as chainRowsJfa in O(N^2) instead of
/// O(N^2 log N) work; what the CPU pipeline uses.
VertexChain chainRows(const CornerTexture& corners, int threads = 0);

/// A Voronoi vertex found by G4 and visited by G6.
struct VoronoiVertex {
    glm::ivec2 pixel{0}; // pixel 1 of the corner: the vertex is at pixel + (0.5, 0.5)
    CornerCase kind = CornerCase::None;
    std::array<std::uint32_t, 4> colours{}; // site ids of pixels 1-4
    friend bool operator==(const VoronoiVertex&, const VoronoiVertex&) = default;
};

/// What G6 saw in the triangles it made (orientations on the sites' pixel positions).
struct TriangleStats {
    std::int64_t threeColour = 0; // vertices of case 2
    std::int64_t fourColour = 0;  // vertices of case 3
    std::int64_t degenerate = 0;  // triangles of zero area (§6.4 allows them at four-colour
                                  // corners; step C4 flips them away)
    std::int64_t clockwise = 0;   // triangles of negative orientation (Property 6.2 rules them
                                  // out when D(S') has no wrong topology; kept, and counted)
    friend bool operator==(const TriangleStats&, const TriangleStats&) = default;
};

/// G6's mesh T'(S') (before C1-C4).
struct DiscreteTriangles {
    /// The Voronoi vertices in chain order (rows bottom to top, left to right in a row).
    std::vector<VoronoiVertex> vertices;
    /// Three site indices per triangle, counterclockwise in the x-right, y-up sense of texture
    /// and world coordinates (the mapping's scale is positive): the colours' counterclockwise
    /// order around the corner (Property 6.2).
    std::vector<std::uint32_t> triangles;
    /// Per triangle the index in `vertices` of the corner it came from.
    std::vector<std::uint32_t> triangleVertex;
    TriangleStats stats;

    /// Number of triangles.
    [[nodiscard]] std::size_t triangleCount() const { return triangles.size() / 3; }
    friend bool operator==(const DiscreteTriangles&, const DiscreteTriangles&) = default;
};

/// Twice the signed area of the pixel triangle (a, b, c): > 0 counterclockwise. Exact in 64 bits.
[[nodiscard]] std::int64_t pixelOrient(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c);
/// > 0 if d is strictly inside the circle through counterclockwise a, b, c; exact in 64 bits for
/// coordinates in [0, 2^13) (textures up to kMaxDiscreteSize).
[[nodiscard]] std::int64_t pixelInCircle(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, glm::ivec2 d);

/// G6: follows `chain` along every row and makes the triangles of each vertex from the colours
/// of `ids` (the G3 texture G4 classified): for case 2 the three colours in counterclockwise order
/// around the corner; for case 3, with colours a, b, c, d of pixels 1-4, either (a, b, c) +
/// (a, c, d) or (a, b, d) + (b, c, d). The thesis makes that choice "arbitrarily" (C4 fixes it);
/// we take the diagonal whose two triangles are both counterclockwise on the pixel positions, and
/// if both are, the one passing the empty-circle test there (a-c on ties), so T' holds fewer
/// triangles for C4 to flip. `pixels` are the sites' pixels. Results do not depend on `threads`.
DiscreteTriangles buildTriangles(const IdTexture& ids, const CornerTexture& corners,
                                 const VertexChain& chain, const std::vector<glm::ivec2>& pixels,
                                 int threads = 0);

} // namespace fl::geom
