#pragma once
// Steps G1-G3 of the thesis' Delaunay pipeline (ch. 6, §6.3.2), CPU backend: continuous sites into
// an N x N texture (G1), the discrete Voronoi diagram by 1+JFA (G2), island removal (G3). Steps
// G4-G6 are in geometry/DiscreteTriangles.h, the whole pipeline in geometry/DiscreteDelaunay.h.
//
// Texture space. We use jfa/'s grid convention (jfa/Sites.h): grid point (x, y) is pixel (x, y),
// which covers [x - 0.5, x + 0.5) x [y - 0.5, y + 0.5), row 0 at y = 0, y up. The thesis (§6.3.1)
// puts the snapped sites S' on the pixels' lower-left corners and colours a pixel by the region
// holding its centre; what matters is that sites and pixels are both measured at integer points
// ("D(S') and T'(S') are both treated as in digital geometry"), which is what grid points are. The
// Voronoi vertices of G4 then lie on the pixel corners (x + 0.5, y + 0.5).

#include <jfa/Plan.h>

#include <glm/glm.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

namespace fl::geom {

/// Id of "no site" in an IdTexture (only a texture without any site holds it).
inline constexpr std::uint32_t kNoSite = 0xffffffffu;
/// Largest texture side: the JFA kernel stores positions and ids in floats (exact below 2^24)
/// and the G6 empty-circle test on pixel positions must fit in 64-bit integers (it does to 2^13).
inline constexpr int kMaxDiscreteSize = 8192;
/// Most sites a texture can hold (jfa::Cell stores the id in a float).
inline constexpr std::size_t kMaxDiscreteSites = std::size_t(1) << 24;

/// G1's map from the sites' plane ("world") to texture space: a uniform scale (aspect kept) that
/// fits the sites' bounding box into [0, N-1]^2, the shorter side centred.
///   texture = (world - origin) * 2^exponent * scale + offset,
///   world = (texture - offset) / scale * 2^-exponent + origin.
/// The factor 2^exponent (exact) brings the longer side of the box to [1, 2) first, so that scale
/// stays finite and precise for any finite extent: (N-1) / 1e-309 alone overflows to infinity.
/// For ordinary extents the result is bit for bit (world - origin) * (N-1) / extent.
/// A site's pixel is floor(texture + 0.5) per axis, as jfa::pixelOf rounds.
struct TextureMapping {
    glm::dvec2 origin{0.0}; // bounding-box minimum of the sites
    double scale = 1.0;     // texels per 2^-exponent world units (1 for a box of extent 0)
    int exponent = 0;       // -ilogb(longer bounding-box side); 0 for a box of extent 0
    glm::dvec2 offset{0.0}; // texture point of `origin` (centres the shorter side)
    int size = 0;           // N

    /// World point to texture point (continuous).
    [[nodiscard]] glm::dvec2 toTexture(glm::dvec2 world) const {
        const glm::dvec2 d = world - origin;
        return glm::dvec2(std::ldexp(d.x, exponent), std::ldexp(d.y, exponent)) * scale + offset;
    }
    /// Texture point (continuous) back to world; the inverse of toTexture.
    [[nodiscard]] glm::dvec2 toWorld(glm::dvec2 texture) const {
        const glm::dvec2 d = (texture - offset) / scale;
        return glm::dvec2(std::ldexp(d.x, -exponent), std::ldexp(d.y, -exponent)) + origin;
    }
    /// World units per texel (rounds to 0 only for boxes within a few ulps of the smallest
    /// subnormal).
    [[nodiscard]] double texelSize() const { return std::ldexp(1.0 / scale, -exponent); }
    /// The pixel a world point snaps to, clamped into [0, N-1]^2 (only rounding can leave it; a
    /// point far outside the box, or not finite, goes to the nearest border, never past it).
    [[nodiscard]] glm::ivec2 pixelOf(glm::dvec2 world) const;
};

/// The mapping for `sites` (all finite) into an N x N texture; throws std::invalid_argument for
/// N outside [2, kMaxDiscreteSize] or a non-finite site (the message names its index).
TextureMapping fitTextureMapping(const std::vector<glm::dvec2>& sites, int size);

/// A site that lost its pixel to another one in G1 (step C3 inserts it next to `keeper`).
struct MissingSite {
    std::uint32_t site = 0;   // index of the missing site
    std::uint32_t keeper = 0; // index of the site that holds the pixel (the lowest index there)
    friend bool operator==(const MissingSite&, const MissingSite&) = default;
};

/// G1's result: every site's pixel, the surviving sites S' and the missing ones.
struct SnappedSites {
    TextureMapping mapping;
    std::vector<glm::ivec2> pixels;  // per input site (missing ones included)
    std::vector<std::uint32_t> kept; // S': indices of the sites written into the texture, ascending
    std::vector<MissingSite> missing; // ascending by site
};

/// G1: maps the sites with fitTextureMapping and snaps each to its pixel. When several sites
/// share a pixel the lowest index keeps it (independent of the order any GPU would render them
/// in), the others are missing. Throws std::invalid_argument as fitTextureMapping, or for more
/// than kMaxDiscreteSites sites.
SnappedSites snapSites(const std::vector<glm::dvec2>& sites, int size);

/// One site index per pixel, row-major (pixel (x, y) at y * width + x), row 0 at y = 0.
struct IdTexture {
    int width = 0;
    int height = 0;
    std::vector<std::uint32_t> ids;

    IdTexture() = default;
    /// A width x height texture filled with `fill`.
    IdTexture(int w, int h, std::uint32_t fill = kNoSite)
        : width(w), height(h), ids(std::size_t(w) * std::size_t(h), fill) {}
    [[nodiscard]] std::uint32_t& at(int x, int y) {
        return ids[std::size_t(y) * std::size_t(width) + std::size_t(x)];
    }
    [[nodiscard]] std::uint32_t at(int x, int y) const {
        return ids[std::size_t(y) * std::size_t(width) + std::size_t(x)];
    }
    friend bool operator==(const IdTexture&, const IdTexture&) = default;
};

/// G2: the discrete Voronoi diagram D(S') by the jfa/ CPU kernel running `plan` (thesis: 1+JFA)
/// with jfa::NearestSite on integer sites: distances are squared integer distances between pixel
/// positions, not between the continuous sites (§6.3.1: continuous distances gave inconsistently
/// oriented and crossing triangles), ties to the smaller id. threads: 0 = all hardware threads.
IdTexture floodVoronoi(const SnappedSites& snapped, const jfa::Plan& plan, int threads = 0);
/// G2 with a plan spec for jfa::parsePlan (default the thesis' "1+JFA") on N x N.
IdTexture floodVoronoi(const SnappedSites& snapped, std::string_view plan = "1+JFA",
                       int threads = 0);

/// What G3 did.
struct IslandStats {
    int passes = 0;              // passes run, the last one (which changed nothing) included
    std::int64_t reassigned = 0; // island pixels recoloured, summed over all passes
    bool converged = true;       // false if the pass cap (2 N) stopped it first
};

/// The thesis' local island test for pixel (x, y) (§6.3.2, step G3): look from the pixel towards
/// its own site; in the site's quadrant the three neighbours (±1, 0), (±1, ±1), (0, ±1) towards
/// it, on an axis the one neighbour towards it. The pixel is in an island if all of them have
/// another colour. A site's own pixel never is. `pixels` are the sites' pixels (SnappedSites).
[[nodiscard]] bool isIslandPixel(const IdTexture& ids, const std::vector<glm::ivec2>& pixels, int x,
                                 int y);

/// G3: recolours every island pixel with the nearest (squared integer distance; then smaller id)
/// of the sites of the neighbours it checked, in passes that read the previous pass' texture (as
/// a GPU pass would), until a pass changes nothing. Results do not depend on `threads`.
IslandStats removeIslands(IdTexture& ids, const std::vector<glm::ivec2>& pixels, int threads = 0);

/// Number of islands: 8-connected components of equal colour (thesis §6.4 counts pixels touching
/// at a corner as connected) that do not hold their site's pixel. For tests and statistics.
std::int64_t countIslandComponents(const IdTexture& ids, const std::vector<glm::ivec2>& pixels);

} // namespace fl::geom
