#pragma once
// Sites into seed grids (thesis §4.1, §4.3.1, §4.5.3; step G1 of ch. 6): point sites at integer
// or sub-pixel positions, generalized sites from a mask image, and deterministic random point
// sets for tests and benchmarks.
//
// Conventions. Positions are in full-resolution grid coordinates: grid point (x, y) is the centre
// of pixel (x, y), so pixel (px, py) covers [px - 0.5, px + 0.5) x [py - 0.5, py + 0.5). A site
// is written into the pixel round(x), round(y), where round(v) = floor(v + 0.5) (halves round
// up), as the cell {x, y, id, 0} (the rounded x, y for integer sites). Ids must be < 2^24 so that
// a float holds them exactly (kMaxSiteId).

#include <jfa/Grid.h>

#include <cstdint>
#include <vector>

namespace fl::jfa {

/// Largest site id a cell can hold exactly (ids are stored in a float).
inline constexpr std::int32_t kMaxSiteId = (1 << 24) - 1;

/// A point site in full-resolution grid coordinates.
struct Site {
    float x = 0.0f;
    float y = 0.0f;
    friend bool operator==(const Site&, const Site&) = default;
};

/// Seeds written by seedPoints(), plus the sites that lost their pixel to another site.
struct SeedResult {
    Grid grid;
    /// Indices (= ids) of sites that share their pixel with a better site and are therefore not
    /// in the grid, ascending. For integer sites they duplicate a kept site's position; for
    /// sub-pixel sites they are distinct points whose Voronoi regions the flood cannot see (the
    /// Delaunay pipeline, thesis §6.3.3 step C3, inserts them afterwards).
    std::vector<int> missing;
};

/// The pixel a coordinate falls in: floor(v + 0.5), computed in double (correct for any float).
long long pixelOf(float v);

/// Writes site i as id i at pixel (round(x), round(y)). integer: the cell holds the rounded
/// position (for NearestSite{true}); otherwise the exact float position (NearestSite{false}).
/// When several sites fall into one pixel, the kept one is the best for that pixel's grid point
/// under NearestSite{integer} (nearest; then smaller id); the others are listed in `missing`.
/// Throws std::invalid_argument for a site that is not finite or whose pixel is outside the
/// W x H grid (the message names its index), for more than kMaxSiteId + 1 sites, or a bad size.
SeedResult seedPoints(const std::vector<Site>& sites, int width, int height, bool integer);

/// Generalized sites from an image (thesis §4.5.3): every non-zero mask pixel (x, y) becomes a
/// seed {x, y, id, 0} at its own integer position, id = labels[y * W + x] if labels are given,
/// else 0 (one class). mask (and labels) hold W * H values, row-major, row 0 at y = 0. Throws
/// std::invalid_argument on a size mismatch or a label of a mask pixel outside 0..kMaxSiteId.
Grid seedMask(const std::vector<std::uint8_t>& mask, int width, int height,
              const std::vector<std::int32_t>* labels = nullptr);

/// splitmix64 (Steele, Lea, Flood 2014): the deterministic generator behind the random sets.
class SplitMix64 {
  public:
    explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
    /// Next 64 random bits.
    std::uint64_t next();
    /// Uniform integer in [0, bound) (bound >= 1), unbiased (rejection sampling).
    std::uint64_t below(std::uint64_t bound);
    /// Uniform double in [0, 1) with 53 random bits.
    double unit();

  private:
    std::uint64_t state_;
};

/// `count` uniformly random sites at integer positions of a W x H grid, all distinct if
/// `distinct` (then count <= W * H), deterministic for a given seed. Site i is the i-th drawn.
std::vector<Site> randomIntegerSites(int count, int width, int height, std::uint64_t seed,
                                     bool distinct = true);

/// `count` uniformly random sub-pixel sites in [0, W - 1] x [0, H - 1] (floats), deterministic for
/// a given seed; distinct points may still share a pixel (seedPoints reports those).
std::vector<Site> randomFloatSites(int count, int width, int height, std::uint64_t seed);

} // namespace fl::jfa
