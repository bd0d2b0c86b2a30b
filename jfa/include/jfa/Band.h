#pragma once
// Band-limited flooding: any plan run over only the part of the grid its seeds can reach.
//
// Why it is exact. A pass writes a texel only a cell that some candidate held and that the
// criterion accepts there (jfaAccept / Criterion::accepts), and a cell moves at most one step per
// pass. So after any pass, a texel holds a cell from seed s only if
//   (a) it lies within the plan's reach of s (the sum of the steps, bandReach()), and
//   (b) the criterion accepts s's cell there; a criterion with reach() bounds that distance
//       (for the penumbra criteria: the widest penumbra the occluder can cast).
// A texel farther than min(a, b) from every seed therefore holds "empty" after every pass of the
// full-grid flood. The band is the set of tiles within that distance of a seed tile; texels
// outside it are left empty (cleared once) and never computed, and every texel inside is computed
// exactly as the full flood computes it, from neighbours that are either computed or truly empty.
// By induction the result equals the full flood texel for texel, for every plan and criterion.
// Computing more than the band is harmless, so stage grids at half resolution use the tiles that
// cover any band texel's grid point.
//
// The view limit (FloodRegion::View). A caller that reads the result at some texels only (JFA-L's
// lookup reads one penumbra-map texel per eye pixel) needs it exact there only. After a plan, a
// texel's cell depends only on what the texels within the plan's reach of it (planBandReach) held
// before: information moves at most that far. So a run that computes, at every pass, the band
// less the tiles farther than that reach from every view tile leaves each view texel as the full
// flood leaves it, by the same induction run backwards from the view: each texel it computes that
// a view texel depends on reads only texels that are computed too, or truly empty. Texels beyond
// the view's reach may hold anything a partial flood leaves there. Plans that stop "until
// unchanged" are not limited: their stopping reads the whole grid.
//
// The flood's front. Within the band, a pass of jump length k changes a texel only if one of
// the 9 texels at (i, j) * k around it holds a non-empty cell. Keep one flag per tile that has
// held a non-empty cell at any time so far (the seeds' tiles, then every tile a pass wrote a
// non-empty cell in). A texel none of whose 9 candidates lies in a flagged tile takes the empty
// cell, and it already holds it in both ping-pong grids: had it ever held another, its own tile
// (offset 0, 0) would be flagged. So each pass computes only the band tiles with a flagged tile
// among their candidates' tiles (frontTiles) and leaves the rest as they are, with the same
// result for any criterion, monotone or not. One-stage plans only: a half-resolution stage's
// tiles are not the seeds'. On JFA-E's eye grid this leaves out most of the band in the long
// early passes, which reach from the few boundary seeds into a band of mostly empty texels.

#include <jfa/Grid.h>
#include <jfa/Plan.h>

#include <algorithm>
#include <concepts>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fl::jfa {

/// Where a flood runs: only over the band its seeds can reach, over the whole grid, or over the
/// band less what a view cannot read (exact at the view's texels only; see above).
enum class FloodRegion { Band, Full, View };
/// "band", "full" or "view".
std::string_view floodRegionName(FloodRegion region);
/// Parses "band", "full" or "view"; nullopt otherwise.
std::optional<FloodRegion> parseFloodRegion(std::string_view text);
/// Whether the region floods a band (Band, or View, which is a band further limited).
constexpr bool banded(FloodRegion region) {
    return region != FloodRegion::Full;
}

/// Tile side in texels: 8 measured fastest on llvmpipe for JFA-L (frame 99 ms against 109 at 16
/// and ~145 at 32; docs/history/soft-shadows.md "Band-limited flooding"). Tiles must be a
/// multiple of 8 (the compute kernels' 8x8 groups).
inline constexpr int kDefaultBandTile = 8;
inline constexpr int kMinBandTile = 8;
inline constexpr int kMaxBandTile = 256;
/// "" when `tile` is a valid tile side, else the problem in words.
std::string checkBandTile(int tile);

/// A reach that bounds nothing (the plan's reach then decides); the shaders' 2^30 - 1.
inline constexpr long long kUnboundedReach = (1LL << 30) - 1;

/// Where a seed's cell may be accepted: texels x0..x1, y0..y1 (inclusive, full resolution; may
/// extend past the grid). x0 > x1 or y0 > y1: nowhere.
struct ReachRect {
    long long x0 = -kUnboundedReach, y0 = -kUnboundedReach;
    long long x1 = kUnboundedReach, y1 = kUnboundedReach;
    [[nodiscard]] bool empty() const { return x0 > x1 || y0 > y1; }
};

/// Criteria that bound, per seed, where its cell may be accepted (Criterion::accepts): nowhere
/// outside reach(px, py, c) (px, py: the seed pixel), so the flood never holds it there.
template <class C>
concept Reaching = Criterion<C> && requires(const C& c, int px, int py, const Cell& a) {
    { c.reach(px, py, a) } -> std::convertible_to<ReachRect>;
};

/// How far (full-resolution texels per axis) a plan can move a seed: its maxReach() plus one
/// texel per change of resolution for the downsampling and the 2x2 expansion offsets.
long long planBandReach(const Plan& plan);

/// The criterion's rect for the seed cell at (px, py), or an unbounded one.
template <Criterion C>
ReachRect criterionRect(const C& criterion, int px, int py, const Cell& c) {
    if constexpr (Reaching<C>)
        return criterion.reach(px, py, c);
    else
        return {};
}

/// `r` clipped to a width x height grid and to the square of half-side `reach` around (px, py).
ReachRect clipRect(ReachRect r, int px, int py, long long reach, int width, int height);
/// The farthest (per axis) texel of non-empty `r` from (px, py); -1 when r is empty.
long long rectReach(const ReachRect& r, int px, int py);

/// The tiles of a flood's band over a width x height (full-resolution) grid.
struct Band {
    int width = 0, height = 0;
    int tile = kDefaultBandTile;
    int tilesX = 0, tilesY = 0;
    /// Every tile active: no seed is far enough from any texel to save work (the caller runs the
    /// full grid).
    bool full = false;
    std::vector<std::uint8_t> active; // tilesX * tilesY, row-major; 1 = in the band

    /// Whether full-resolution texel (x, y) lies in an active tile.
    [[nodiscard]] bool covers(int x, int y) const {
        return active[std::size_t(y / tile) * std::size_t(tilesX) + std::size_t(x / tile)] != 0;
    }
    /// Texels in active tiles (clipped to the grid).
    [[nodiscard]] long long activeTexels() const;
    /// activeTexels() / (width * height); 1 for an empty grid.
    [[nodiscard]] double activeShare() const;
};

/// Builds the band from per-tile rects (the union of the grid-clipped rects of the tile's seeds;
/// empty for a tile without seeds): every tile a rect touches within `planReach` of the tile.
/// The GPU does the same (shaders/jfa_band_mark.comp.glsl), so both bands are equal.
Band markTiles(int width, int height, int tile, const std::vector<ReachRect>& tileRects,
               long long planReach = kUnboundedReach);

/// Calls f(x, y, rect) for every seed of `seeds` (cells the criterion does not call empty) with
/// the rect where the criterion may accept its cell, clipped to the grid.
template <Criterion C, typename F>
void forEachSeedRect(const Grid& seeds, const C& criterion, F&& f) {
    for (int y = 0; y < seeds.height; ++y)
        for (int x = 0; x < seeds.width; ++x) {
            const Cell& c = seeds.at(x, y);
            if (criterion.empty(c)) continue;
            f(x, y,
              clipRect(criterionRect(criterion, x, y, c), x, y, kUnboundedReach, seeds.width,
                       seeds.height));
        }
}

/// The band of `plan` over full-resolution `seeds` with `criterion`: the union of each tile's
/// seeds' criterion rects, within the square the plan can reach from the tile (planBandReach).
/// Band::full when that is every tile.
template <Criterion C>
Band floodBand(const Plan& plan, const Grid& seeds, const C& criterion,
               int tile = kDefaultBandTile) {
    const long long planReach = planBandReach(plan);
    const int tilesX = (seeds.width + tile - 1) / tile, tilesY = (seeds.height + tile - 1) / tile;
    std::vector<ReachRect> rects(std::size_t(tilesX) * std::size_t(tilesY), ReachRect{1, 1, 0, 0});
    forEachSeedRect(seeds, criterion, [&](int x, int y, const ReachRect& r) {
        if (r.empty()) return;
        ReachRect& u = rects[std::size_t(y / tile) * std::size_t(tilesX) + std::size_t(x / tile)];
        u = u.empty() ? r
                      : ReachRect{std::min(u.x0, r.x0), std::min(u.y0, r.y0), std::max(u.x1, r.x1),
                                  std::max(u.y1, r.y1)};
    });
    return markTiles(seeds.width, seeds.height, tile, rects, planReach);
}

/// The largest distance (per axis) from a seed to where the criterion may accept its cell, on
/// the grid: what a pass count must cover so that no accepted cell is cut off. -1 without seeds
/// (or none accepted anywhere); criteria that are not Reaching reach the grid's far side.
template <Criterion C>
long long maxSeedReach(const Grid& seeds, const C& criterion) {
    long long best = -1;
    forEachSeedRect(seeds, criterion, [&](int x, int y, const ReachRect& r) {
        best = std::max(best, rectReach(r, x, y));
    });
    return best;
}

/// The widest view limit, in tiles: a plan that reaches farther (full JFA, long standard
/// floods) is left to its band, since its cone around the view is most of any band it has.
inline constexpr int kMaxViewTileReach = 16;
/// How many tiles (per axis) from a view tile a band tile may lie and still be computed under
/// the view limit, for `plan` on tiles of side `tile`: the plan's reach plus one texel (the GPU
/// finds the view's texels in a pass of its own, whose rounding may differ from the reader's by a
/// texel). -1 when the plan cannot be limited: an until-unchanged stage, or more than
/// kMaxViewTileReach tiles.
int viewTileReach(const Plan& plan, int tile);
/// The tiles of a width x height grid within `tileReach` tiles (per axis) of a view tile (`view`:
/// one flag per tile of side `tile`, row-major): where a view-limited run computes at most.
/// Throws std::invalid_argument when `view` has another size.
Band viewRegion(int width, int height, int tile, const std::vector<std::uint8_t>& view,
                int tileReach);
/// Removes from `band` the tiles farther than `tileReach` tiles (per axis) from every view tile.
/// `view` holds one flag per tile of the band's grid, row-major (nonzero: the reader reads a
/// texel there). Throws std::invalid_argument when its size is not the band's tile count.
void limitToView(Band& band, const std::vector<std::uint8_t>& view, int tileReach);

/// The flood's front: of `band`'s tiles, those a pass of jump length `step` may change. Its
/// texels read the cells at (i, j) * step around them; where every tile those lie in is off
/// `front` (one flag per band tile: the tiles that have held a non-empty cell so far, seeds
/// included), the texel stays empty. The GPU does the same (shaders/jfa_band_front.comp.glsl).
/// Throws std::invalid_argument when `front` has another size.
Band frontTiles(const Band& band, const std::vector<std::uint8_t>& front, int step);

/// Flags in `front` (one per tile of side `tile` over `grid`) every tile where `grid` holds a
/// non-empty cell under `criterion`.
template <class C>
void markFront(std::vector<std::uint8_t>& front, const Grid& grid, int tile, const C& criterion) {
    const int tilesX = (grid.width + tile - 1) / tile;
    for (int y = 0; y < grid.height; ++y)
        for (int x = 0; x < grid.width; ++x)
            if (!criterion.empty(grid.at(x, y)))
                front[std::size_t(y / tile) * std::size_t(tilesX) + std::size_t(x / tile)] = 1;
}

/// The fewest halving JFA passes (steps 2^(k-1) .. 1, reach 2^k - 1) that cover `reach` texels,
/// clamped to [1, maxPasses]; maxPasses for an unbounded reach, 1 without seeds (reach < 0).
int passesForReach(long long reach, int maxPasses);

} // namespace fl::jfa
