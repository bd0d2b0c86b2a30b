#pragma once
// The CPU flood kernel: runs a Plan with a Criterion on a Grid, rows split among std::threads.
// It is the reference the GL kernels (jfa_gl/GlKernel.h) replicate texel for texel, so its
// semantics are spelled out exactly here.
//
// Semantics of flood(plan, fullResSeeds, criterion):
//  * Grids. Stage s of a plan with S stages has scale 2^(S-1-s) (1 = full resolution; the
//    half-resolution stage of the thesis' "halve resolution" variant has scale 2). Texel (x, y)
//    of a stage grid stands for the full-resolution grid point gridPoint(x, y, scale) =
//    (x * scale, y * scale); every better() call is made at that point.
//  * Seeding. `fullResSeeds` must be plan.width() x plan.height(). If the first stage has scale
//    1 it is copied as is. Otherwise it is downsampled: texel (x, y) of the first stage takes the
//    best non-empty cell among the full-resolution cells (x*scale + i, y*scale + j),
//    0 <= i, j < scale, that exist (a grid with odd W or H has partial blocks), judged at grid
//    point (x*scale, y*scale); kEmptyCell if all of them are empty. For the usual two-stage
//    half-resolution plan that is the 2x2 block (2x..2x+1, 2y..2y+1) at grid point (2x, 2y).
//  * A pass with step k writes texel (x, y) of its stage grid from the grid of the previous pass
//    (ping-pong; never in place). Candidates are the cells at (x + i*k, y + j*k), i, j in
//    {-1, 0, 1}, that lie inside the stage grid (outside ones are skipped, no clamping or
//    wrapping). The result is the best non-empty candidate under
//    criterion.better(p.x, p.y, a, b), p = gridPoint(x, y, scale); kEmptyCell if all candidates
//    are empty. Candidates are read j = -1, 0, 1 (outer) and i = -1, 0, 1 (inner) and a later
//    one replaces the best so far only if strictly better, so with a strict total order (as the
//    Criterion concept demands) the reading order does not matter.
//  * Expansion (Pass::expandBefore, the first pass of every stage after the first): texel (x, y)
//    first takes the previous stage's cell r = (x / 2, y / 2) (integer division), then the pass
//    runs on the expanded grid. Thesis §4.3.2: each of the new texels "derives its nearest site
//    from those sites represented by the representative site", so for a criterion with
//    seedPixel() (NearestSite) the texel takes the best, at its own grid point, of the
//    full-resolution seeds in the block of the previous stage's scale that holds r's seed pixel
//    (r is one of them, so it is never worse than the copy); other criteria copy r verbatim. The
//    full- resolution seeds are not read again: a seed that was not its block's pick is gone (so a
//    half-resolution distance transform is not 0 on every feature pixel).
//  * Changed texels. A pass changes texel (x, y) if the cell it writes differs (Cell::operator==,
//    float comparison of all four components) from the cell that texel held before the pass (for
//    an expanding pass: the expanded cell). Counted for every pass.
//  * Until unchanged (Stage::untilUnchanged): after the first pass of such a stage that changes no
//    texel, the stage's remaining passes are skipped (its step count is the cap). Skipped passes
//    are not run and not reported; later stages still run.
//  * Result: the full-resolution grid after the last pass run (the seeded grid if the plan has
//    no passes at all; a stage after the first always has at least one pass).
//  * Region (FloodOptions::region, jfa/Band.h). With FloodRegion::Band a pass computes only the
//    texels of the band's tiles (at a reduced-resolution stage: texels whose grid point lies in
//    one) and writes kEmptyCell elsewhere; the result is identical to the full grid's.
//  * Threads. Each pass splits the stage's rows into min(threads, rows) contiguous bands, one per
//    thread; every texel depends only on the previous grid, so results are identical for every
//    thread count.

#include <base/Parallel.h>
#include <jfa/Band.h>
#include <jfa/Grid.h>
#include <jfa/Plan.h>

#include <algorithm>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace fl::jfa {

/// The cell a texel holds when no candidate is non-empty (the GL kernels' kJfaEmptyCell).
inline constexpr Cell kEmptyCell{0.0f, 0.0f, -1.0f, 0.0f};

/// How flood() runs.
struct FloodOptions {
    /// Worker threads per pass; 0 = std::thread::hardware_concurrency() (at least 1).
    int threads = 0;
    /// Called on the calling thread after every pass that runs, with the pass' index in
    /// plan.passes(), the pass and the grid it wrote (valid only during the call).
    std::function<void(int passIndex, const Pass& pass, const Grid& after)> onPass;
    /// Band: compute only the texels the seeds can reach (jfa/Band.h); Full: every texel.
    FloodRegion region = FloodRegion::Full;
    int bandTile = kDefaultBandTile;
    /// With FloodRegion::View: one flag per band tile (row-major; nonzero where the caller reads
    /// the result). The run is then exact at those tiles' texels only (jfa/Band.h, limitToView).
    /// Without it, View floods the band.
    const std::vector<std::uint8_t>* viewTiles = nullptr;
    /// With a band, on one-stage plans: each pass computes only the band tiles within the
    /// flood's front (jfa/Band.h; the same result). Off only for comparisons.
    bool front = true;
};

/// What one executed pass did.
struct PassStats {
    int passIndex = 0; // index in plan.passes()
    Pass pass;
    std::int64_t changed = 0; // texels whose cell differs from the one they held before the pass
};

/// A flood's full-resolution result plus one entry per executed pass, in execution order.
struct FloodResult {
    Grid grid;
    std::vector<PassStats> passes;
    /// Number of passes actually run (less than plan.passCount() if an until-unchanged stage
    /// stopped early).
    [[nodiscard]] int passesRun() const { return static_cast<int>(passes.size()); }
    /// Share of the full-resolution grid in the band (1 for FloodRegion::Full).
    double activeShare = 1.0;
    /// Share of the grid an average pass computed: the band's, or less within the front.
    double computedShare = 1.0;
};

// The thread fan-out is base/Parallel.h, shared with every CPU path.
using ::fl::bandCount;
using ::fl::parallelRows;
using ::fl::resolveThreads;

/// Scale (1, 2, 4, ...) of a plan's stage: 2^(stage count - 1 - stageIndex).
int stageScale(const Plan& plan, std::size_t stageIndex);

/// Criteria that reject a candidate at some grid points (`accepts(px, py, c)` false): such a
/// candidate is treated as empty there, so the texel neither takes nor passes it on. JFA-L uses
/// this for occluders whose ray misses the light (thesis §5.2). Criteria without `accepts`
/// accept every non-empty cell.
template <class C>
concept Accepting = Criterion<C> && requires(const C& c, int px, int py, const Cell& a) {
    { c.accepts(px, py, a) } -> std::convertible_to<bool>;
};

/// Whether non-empty cell `c` may be taken at grid point (px, py).
template <Criterion C>
bool acceptsAt(const C& criterion, int px, int py, const Cell& c) {
    if constexpr (Accepting<C>)
        return criterion.accepts(px, py, c);
    else
        return true;
}

/// Downsamples full-resolution seeds to the grid of a stage at `scale` (see the header comment).
template <Criterion C>
Grid downsample(const Grid& full, int scale, const C& criterion) {
    if (scale == 1) return full;
    const int w = (full.width + scale - 1) / scale, h = (full.height + scale - 1) / scale;
    Grid out(w, h, kEmptyCell);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const int px = x * scale, py = y * scale;
            const Cell* best = nullptr;
            for (int j = 0; j < scale && py + j < full.height; ++j) {
                for (int i = 0; i < scale && px + i < full.width; ++i) {
                    const Cell& c = full.at(px + i, py + j);
                    if (criterion.empty(c) || !acceptsAt(criterion, px, py, c)) continue;
                    if (best == nullptr || criterion.better(px, py, c, *best)) best = &c;
                }
            }
            if (best != nullptr) out.at(x, y) = *best;
        }
    }
    return out;
}

/// Expands a grid 2x into width x height: texel (x, y) takes cell (x / 2, y / 2) verbatim.
/// Requires grid.width == ceil(width / 2) and grid.height == ceil(height / 2).
Grid expand(const Grid& grid, int width, int height);

/// Criteria that can name the full-resolution pixel a cell was seeded at.
template <class C>
concept SeedLocating = Criterion<C> && requires(const Cell& c) {
    { C::seedPixel(c) } -> std::same_as<GridPoint>;
};

/// Expands the previous stage's grid `prev` (at scale `prevScale`) 2x into width x height (at
/// scale prevScale / 2), refining each texel among the seeds its representative stands for (see
/// the header comment).
template <Criterion C>
Grid expandStage(const Grid& prev, int width, int height, int prevScale, const Grid& fullResSeeds,
                 const C& criterion) {
    Grid out = expand(prev, width, height);
    if constexpr (SeedLocating<C>) {
        const int scale = prevScale / 2;
        for (int y = 0; y < height; ++y) {
            for (int x = 0; x < width; ++x) {
                Cell& best = out.at(x, y);
                if (criterion.empty(best)) continue;
                const GridPoint seed = C::seedPixel(best);
                if (seed.x < 0 || seed.y < 0) continue; // not a grid pixel: keep the copy
                const int bx = seed.x / prevScale * prevScale, by = seed.y / prevScale * prevScale;
                const GridPoint p = gridPoint(x, y, scale);
                for (int j = 0; j < prevScale && by + j < fullResSeeds.height; ++j) {
                    for (int i = 0; i < prevScale && bx + i < fullResSeeds.width; ++i) {
                        const Cell& c = fullResSeeds.at(bx + i, by + j);
                        if (!criterion.empty(c) && acceptsAt(criterion, p.x, p.y, c) &&
                            criterion.better(p.x, p.y, c, best))
                            best = c;
                    }
                }
            }
        }
    }
    return out;
}

/// Runs one pass of step `step` from `src` into `dst` (resized to src's size; must not be src)
/// for a stage at `scale`; returns the number of changed texels (compared with src).
/// With `band` (not full), only texels whose grid point lies in the band are computed; the others
/// get kEmptyCell (jfa/Band.h says why that is exact).
template <Criterion C>
std::int64_t runPass(const Grid& src, Grid& dst, int step, int scale, const C& criterion,
                     int threads, const Band* band = nullptr) {
    const int w = src.width, h = src.height;
    dst.width = w;
    dst.height = h;
    dst.cells.resize(src.cells.size());
    std::vector<std::int64_t> changedPerBand(static_cast<std::size_t>(bandCount(h, threads)), 0);
    parallelRows(h, threads, [&](int rowBegin, int rowEnd, int part) {
        std::int64_t changed = 0;
        for (int y = rowBegin; y < rowEnd; ++y) {
            const int py = y * scale;
            // Rows y - step, y, y + step that exist, in reading order (j = -1, 0, 1).
            const Cell* own = &src.cells[std::size_t(y) * std::size_t(w)];
            const Cell* rows[3];
            int rowCount = 0;
            if (y >= step) rows[rowCount++] = own - std::size_t(step) * std::size_t(w);
            rows[rowCount++] = own;
            if (step < h - y) rows[rowCount++] = own + std::size_t(step) * std::size_t(w);
            for (int x = 0; x < w; ++x) {
                const int px = x * scale;
                if (band != nullptr && !band->covers(px, py)) {
                    if (!criterion.empty(own[x])) ++changed; // cannot happen: see jfa/Band.h
                    dst.cells[std::size_t(y) * std::size_t(w) + std::size_t(x)] = kEmptyCell;
                    continue;
                }
                const bool left = x >= step, right = step < w - x;
                const Cell* best = nullptr;
                auto offer = [&](const Cell& c) {
                    if (!criterion.empty(c) && acceptsAt(criterion, px, py, c) &&
                        (best == nullptr || criterion.better(px, py, c, *best)))
                        best = &c;
                };
                for (int r = 0; r < rowCount; ++r) { // i = -1, 0, 1 within each row
                    const Cell* row = rows[r];
                    if (left) offer(row[x - step]);
                    offer(row[x]);
                    if (right) offer(row[x + step]);
                }
                const Cell result = best != nullptr ? *best : kEmptyCell;
                if (!(result == own[x])) ++changed;
                dst.cells[std::size_t(y) * std::size_t(w) + std::size_t(x)] = result;
            }
        }
        changedPerBand[static_cast<std::size_t>(part)] = changed;
    });
    std::int64_t total = 0;
    for (std::int64_t c : changedPerBand) total += c;
    return total;
}

/// Runs `plan` on full-resolution seeds with `criterion`; returns the result and per-pass stats.
/// Throws std::invalid_argument if the seeds are not plan.width() x plan.height().
template <Criterion C>
FloodResult floodWithStats(const Plan& plan, const Grid& fullResSeeds, const C& criterion,
                           const FloodOptions& options = {}) {
    if (fullResSeeds.width != plan.width() || fullResSeeds.height != plan.height() ||
        fullResSeeds.cells.size() !=
            std::size_t(fullResSeeds.width) * std::size_t(fullResSeeds.height)) {
        throw std::invalid_argument("flood: seeds are " + std::to_string(fullResSeeds.width) + "x" +
                                    std::to_string(fullResSeeds.height) + " but plan \"" +
                                    plan.name() + "\" runs on " + std::to_string(plan.width()) +
                                    "x" + std::to_string(plan.height()));
    }
    resolveThreads(options.threads); // validates
    FloodResult result;
    std::optional<Band> band;
    if (banded(options.region)) {
        if (const std::string bad = checkBandTile(options.bandTile); !bad.empty())
            throw std::invalid_argument("flood: " + bad);
        band = floodBand(plan, fullResSeeds, criterion, options.bandTile);
        if (options.region == FloodRegion::View && options.viewTiles != nullptr)
            if (const int reach = viewTileReach(plan, options.bandTile); reach >= 0)
                limitToView(*band, *options.viewTiles, reach);
        result.activeShare = band->activeShare();
        if (band->full) band.reset();
    }
    Grid current = downsample(fullResSeeds, stageScale(plan, 0), criterion);
    Grid next;
    // The flood's front (jfa/Band.h), on one-stage plans: the tiles that have held a cell.
    std::vector<std::uint8_t> front;
    if (band && plan.stages().size() == 1 && options.front) {
        front.assign(band->active.size(), 0);
        markFront(front, fullResSeeds, band->tile, criterion);
    }
    long long computed = 0; // texels the passes computed
    int passIndex = 0;
    const std::vector<Stage>& stages = plan.stages();
    for (std::size_t s = 0; s < stages.size(); ++s) {
        const Stage& stage = stages[s];
        const int scale = stageScale(plan, s);
        if (s > 0)
            current = expandStage(current, stage.width, stage.height, stageScale(plan, s - 1),
                                  fullResSeeds, criterion);
        bool skipRest = false;
        for (std::size_t k = 0; k < stage.steps.size(); ++k, ++passIndex) {
            if (skipRest) continue;
            const Pass pass{stage.steps[k], stage.width, stage.height, s > 0 && k == 0,
                            stage.untilUnchanged};
            std::optional<Band> live;
            if (!front.empty()) live = frontTiles(*band, front, pass.step);
            const Band* run = live ? &*live : (band ? &*band : nullptr);
            const std::int64_t changed =
                runPass(current, next, pass.step, scale, criterion, options.threads, run);
            computed +=
                run ? run->activeTexels() : static_cast<long long>(next.width) * next.height;
            std::swap(current, next);
            if (!front.empty()) markFront(front, current, band->tile, criterion);
            result.passes.push_back(PassStats{passIndex, pass, changed});
            if (options.onPass) options.onPass(passIndex, pass, current);
            if (stage.untilUnchanged && changed == 0) skipRest = true;
        }
    }
    if (!result.passes.empty())
        result.computedShare = double(computed) / double(result.passes.size()) /
                               (double(plan.width()) * double(plan.height()));
    result.grid = std::move(current);
    return result;
}

/// Runs `plan` on full-resolution seeds with `criterion`; returns the full-resolution grid.
template <Criterion C>
Grid flood(const Plan& plan, const Grid& fullResSeeds, const C& criterion,
           const FloodOptions& options = {}) {
    return floodWithStats(plan, fullResSeeds, criterion, options).grid;
}

} // namespace fl::jfa
