#include <jfa/Band.h>

#include <base/Text.h>

#include <algorithm>
#include <stdexcept>

namespace fl::jfa {

namespace {

/// A band over a width x height grid with no tile active.
Band noTiles(int width, int height, int tile) {
    Band b;
    b.width = width;
    b.height = height;
    b.tile = tile;
    b.tilesX = (width + tile - 1) / tile;
    b.tilesY = (height + tile - 1) / tile;
    b.active.assign(std::size_t(b.tilesX) * std::size_t(b.tilesY), 0);
    return b;
}

/// Sets b.full from its tiles.
void noteFull(Band& b) {
    b.full = std::all_of(b.active.begin(), b.active.end(), [](std::uint8_t a) { return a != 0; });
}

} // namespace

std::string_view floodRegionName(FloodRegion region) {
    switch (region) {
    case FloodRegion::Band:
        return "band";
    case FloodRegion::View:
        return "view";
    case FloodRegion::Full:
        break;
    }
    return "full";
}

std::optional<FloodRegion> parseFloodRegion(std::string_view text) {
    for (FloodRegion r : {FloodRegion::Band, FloodRegion::Full, FloodRegion::View})
        if (text == floodRegionName(r)) return r;
    return std::nullopt;
}

int viewTileReach(const Plan& plan, int tile) {
    if (plan.untilUnchanged() || tile <= 0) return -1;
    const long long reach = planBandReach(plan) + 1;
    const long long tiles = (reach + tile - 1) / tile;
    return tiles > kMaxViewTileReach ? -1 : static_cast<int>(tiles);
}

Band viewRegion(int width, int height, int tile, const std::vector<std::uint8_t>& view,
                int tileReach) {
    Band b = noTiles(width, height, tile);
    if (view.size() != std::size_t(b.tilesX) * std::size_t(b.tilesY))
        throw std::invalid_argument(
            cat("jfa: the view has ", view.size(), " tiles, the grid ", b.tilesX * b.tilesY));
    // Separably, as the GPU does it: along x, then along y.
    std::vector<std::uint8_t> rows(view.size(), 0);
    const auto at = [&](int x, int y) {
        return std::size_t(y) * std::size_t(b.tilesX) + std::size_t(x);
    };
    for (int y = 0; y < b.tilesY; ++y)
        for (int x = 0; x < b.tilesX; ++x)
            for (int k = std::max(0, x - tileReach); k <= std::min(b.tilesX - 1, x + tileReach);
                 ++k)
                if (view[at(k, y)] != 0) rows[at(x, y)] = 1;
    for (int y = 0; y < b.tilesY; ++y)
        for (int x = 0; x < b.tilesX; ++x)
            for (int k = std::max(0, y - tileReach); k <= std::min(b.tilesY - 1, y + tileReach);
                 ++k)
                if (rows[at(x, k)] != 0) b.active[at(x, y)] = 1;
    noteFull(b);
    return b;
}

void limitToView(Band& band, const std::vector<std::uint8_t>& view, int tileReach) {
    const Band near = viewRegion(band.width, band.height, band.tile, view, tileReach);
    for (std::size_t i = 0; i < band.active.size(); ++i)
        band.active[i] = band.active[i] != 0 && near.active[i] != 0 ? 1 : 0;
    noteFull(band);
}

std::string checkBandTile(int tile) {
    if (tile < kMinBandTile || tile > kMaxBandTile || tile % 8 != 0)
        return cat("the band tile must be a multiple of 8 in [", kMinBandTile, ", ", kMaxBandTile,
                   "], got ", tile);
    return {};
}

long long planBandReach(const Plan& plan) {
    // Downsampling moves a seed to its block's grid point and expansion copies a block's cell to
    // its 2x2 texels: at most one texel per axis each, per change of resolution.
    return plan.maxReach() + 2 * (static_cast<long long>(plan.stages().size()) - 1);
}

long long Band::activeTexels() const {
    long long n = 0;
    for (int ty = 0; ty < tilesY; ++ty)
        for (int tx = 0; tx < tilesX; ++tx)
            if (active[std::size_t(ty) * std::size_t(tilesX) + std::size_t(tx)] != 0)
                n += static_cast<long long>(std::min(tile, width - tx * tile)) *
                     std::min(tile, height - ty * tile);
    return n;
}

double Band::activeShare() const {
    const double all = double(width) * double(height);
    return all > 0.0 ? double(activeTexels()) / all : 1.0;
}

ReachRect clipRect(ReachRect r, int px, int py, long long reach, int width, int height) {
    r.x0 = std::max({r.x0, px - reach, 0LL});
    r.y0 = std::max({r.y0, py - reach, 0LL});
    r.x1 = std::min({r.x1, px + reach, width - 1LL});
    r.y1 = std::min({r.y1, py + reach, height - 1LL});
    return r;
}

long long rectReach(const ReachRect& r, int px, int py) {
    if (r.empty()) return -1;
    return std::max({px - r.x0, r.x1 - px, py - r.y0, r.y1 - py, 0LL});
}

Band markTiles(int width, int height, int tile, const std::vector<ReachRect>& tileRects,
               long long planReach) {
    Band b = noTiles(width, height, tile);
    for (int ty = 0; ty < b.tilesY; ++ty)
        for (int tx = 0; tx < b.tilesX; ++tx) {
            const ReachRect& u =
                tileRects[std::size_t(ty) * std::size_t(b.tilesX) + std::size_t(tx)];
            if (u.empty()) continue;
            // The plan's square around the tile's texels.
            const long long t0x = tx * 1LL * tile, t0y = ty * 1LL * tile;
            const ReachRect r{std::max(u.x0, t0x - planReach), std::max(u.y0, t0y - planReach),
                              std::min(u.x1, t0x + tile - 1 + planReach),
                              std::min(u.y1, t0y + tile - 1 + planReach)};
            if (r.empty()) continue;
            for (long long y = r.y0 / tile; y <= r.y1 / tile; ++y)
                for (long long x = r.x0 / tile; x <= r.x1 / tile; ++x)
                    b.active[std::size_t(y) * std::size_t(b.tilesX) + std::size_t(x)] = 1;
        }
    noteFull(b);
    return b;
}

Band frontTiles(const Band& band, const std::vector<std::uint8_t>& front, int step) {
    if (front.size() != band.active.size())
        throw std::invalid_argument("jfa: the front has " + std::to_string(front.size()) +
                                    " tiles, the band " + std::to_string(band.active.size()));
    Band out = noTiles(band.width, band.height, band.tile);
    const int t = band.tile;
    for (int ty = 0; ty < band.tilesY; ++ty)
        for (int tx = 0; tx < band.tilesX; ++tx) {
            const std::size_t index = std::size_t(ty) * std::size_t(band.tilesX) + std::size_t(tx);
            if (band.active[index] == 0) continue;
            const long long x0 = tx * 1LL * t, y0 = ty * 1LL * t;
            const long long x1 = std::min(x0 + t, 1LL * band.width) - 1;
            const long long y1 = std::min(y0 + t, 1LL * band.height) - 1;
            bool live = false;
            for (int j = -1; j <= 1 && !live; ++j)
                for (int i = -1; i <= 1 && !live; ++i) {
                    // The candidates' texels at this offset, clipped to the grid, and their tiles.
                    const long long lx = std::max(x0 + i * 1LL * step, 0LL);
                    const long long ly = std::max(y0 + j * 1LL * step, 0LL);
                    const long long hx = std::min(x1 + i * 1LL * step, band.width - 1LL);
                    const long long hy = std::min(y1 + j * 1LL * step, band.height - 1LL);
                    for (long long y = ly / t; y <= hy / t && lx <= hx && ly <= hy && !live; ++y)
                        for (long long x = lx / t; x <= hx / t && !live; ++x)
                            live =
                                front[std::size_t(y) * std::size_t(band.tilesX) + std::size_t(x)] !=
                                0;
                }
            out.active[index] = live ? 1 : 0;
        }
    return out;
}

int passesForReach(long long reach, int maxPasses) {
    if (reach < 0) return 1;
    int k = 1;
    while (k < maxPasses && (1LL << k) - 1 < reach) ++k;
    return k;
}

} // namespace fl::jfa
