// Steps G2 (1+JFA) and G3 (island removal) of the thesis (§6.3.2).
#include <geometry/DiscreteVoronoi.h>

#include <jfa/CpuKernel.h>
#include <jfa/NearestSite.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>

namespace fl::geom {

namespace {

std::int64_t squaredDistance(glm::ivec2 a, glm::ivec2 b) {
    const std::int64_t dx = std::int64_t(a.x) - b.x, dy = std::int64_t(a.y) - b.y;
    return dx * dx + dy * dy;
}

int sign(int v) {
    return (v > 0) - (v < 0);
}

// The neighbours the island test of pixel (x, y) looks at (towards its site at `site`): three in
// the site's quadrant, one if the site is on an axis through the pixel, none on the site itself.
int towardsSite(int x, int y, glm::ivec2 site, glm::ivec2 (&out)[3]) {
    const int dx = sign(site.x - x), dy = sign(site.y - y);
    if (dx != 0 && dy != 0) {
        out[0] = {x + dx, y};
        out[1] = {x + dx, y + dy};
        out[2] = {x, y + dy};
        return 3;
    }
    if (dx == 0 && dy == 0) return 0;
    out[0] = {x + dx, y + dy};
    return 1;
}

} // namespace

IdTexture floodVoronoi(const SnappedSites& snapped, const jfa::Plan& plan, int threads) {
    const int n = snapped.mapping.size;
    if (plan.width() != n || plan.height() != n) {
        throw std::invalid_argument("floodVoronoi: plan \"" + plan.name() + "\" runs on " +
                                    std::to_string(plan.width()) + "x" +
                                    std::to_string(plan.height()) + ", the texture is " +
                                    std::to_string(n) + "x" + std::to_string(n));
    }
    jfa::Grid seeds(n, n, jfa::kEmptyCell);
    for (std::uint32_t id : snapped.kept) {
        const glm::ivec2 p = snapped.pixels[id];
        seeds.at(p.x, p.y) = jfa::Cell{float(p.x), float(p.y), float(id), 0.0f};
    }
    // Integer sites: the thesis measures distances between the snapped sites themselves (§6.3.1),
    // which also makes them exact 64-bit integers here and in the GL kernel.
    const jfa::Grid grid = jfa::flood(plan, seeds, jfa::NearestSite{true}, {threads, {}});
    IdTexture ids(n, n);
    for (std::size_t i = 0; i < ids.ids.size(); ++i) {
        const float z = grid.cells[i].z;
        ids.ids[i] = z < 0.0f ? kNoSite : static_cast<std::uint32_t>(z);
    }
    return ids;
}

IdTexture floodVoronoi(const SnappedSites& snapped, std::string_view plan, int threads) {
    const int n = snapped.mapping.size;
    return floodVoronoi(snapped, jfa::parsePlan(plan, n, n), threads);
}

bool isIslandPixel(const IdTexture& ids, const std::vector<glm::ivec2>& pixels, int x, int y) {
    const std::uint32_t c = ids.at(x, y);
    if (c == kNoSite) return false;
    glm::ivec2 nb[3];
    const int count = towardsSite(x, y, pixels[c], nb);
    if (count == 0) return false;
    // The neighbours lie between the pixel and its site, so inside the texture.
    for (int k = 0; k < count; ++k) {
        if (ids.at(nb[k].x, nb[k].y) == c) return false;
    }
    return true;
}

IslandStats removeIslands(IdTexture& ids, const std::vector<glm::ivec2>& pixels, int threads) {
    IslandStats stats;
    const int w = ids.width, h = ids.height;
    IdTexture next(w, h);
    // The thesis needs "less than 5" passes in practice; 2 N is a generous cap that still ends
    // should recolouring ever cycle.
    const int cap = 2 * std::max(w, h);
    const int bands = jfa::bandCount(h, threads);
    std::vector<std::int64_t> changedPerBand(static_cast<std::size_t>(bands));
    while (true) {
        std::fill(changedPerBand.begin(), changedPerBand.end(), 0);
        // Each pass reads the previous pass' texture only (a GPU pass cannot read what it
        // writes), so the result does not depend on the order pixels are visited in.
        jfa::parallelRows(h, threads, [&](int rowBegin, int rowEnd, int band) {
            std::int64_t changed = 0;
            for (int y = rowBegin; y < rowEnd; ++y) {
                for (int x = 0; x < w; ++x) {
                    std::uint32_t c = ids.at(x, y);
                    if (c != kNoSite) {
                        glm::ivec2 nb[3];
                        const int count = towardsSite(x, y, pixels[c], nb);
                        bool island = count > 0;
                        for (int k = 0; k < count && island; ++k)
                            island = ids.at(nb[k].x, nb[k].y) != c;
                        if (island) {
                            // The nearest of the checked neighbours' sites, ties to the smaller
                            // id as in jfa::NearestSite, so passes are deterministic.
                            const glm::ivec2 p{x, y};
                            std::uint32_t best = ids.at(nb[0].x, nb[0].y);
                            std::int64_t bestD = squaredDistance(p, pixels[best]);
                            for (int k = 1; k < count; ++k) {
                                const std::uint32_t o = ids.at(nb[k].x, nb[k].y);
                                const std::int64_t d = squaredDistance(p, pixels[o]);
                                if (d < bestD || (d == bestD && o < best)) {
                                    best = o;
                                    bestD = d;
                                }
                            }
                            c = best;
                            ++changed;
                        }
                    }
                    next.at(x, y) = c;
                }
            }
            changedPerBand[static_cast<std::size_t>(band)] = changed;
        });
        ++stats.passes;
        std::int64_t changed = 0;
        for (std::int64_t c : changedPerBand) changed += c;
        if (changed == 0) break;
        stats.reassigned += changed;
        std::swap(ids.ids, next.ids);
        if (stats.passes >= cap) {
            stats.converged = false;
            break;
        }
    }
    return stats;
}

std::int64_t countIslandComponents(const IdTexture& ids, const std::vector<glm::ivec2>& pixels) {
    const int w = ids.width, h = ids.height;
    std::vector<std::uint8_t> seen(ids.ids.size(), 0);
    std::vector<std::pair<int, int>> stack;
    std::int64_t islands = 0;
    for (int y0 = 0; y0 < h; ++y0) {
        for (int x0 = 0; x0 < w; ++x0) {
            const std::size_t i0 = std::size_t(y0) * std::size_t(w) + std::size_t(x0);
            const std::uint32_t c = ids.ids[i0];
            if (seen[i0] || c == kNoSite) continue;
            // Flood-fill this 8-connected component and see whether its site's pixel is in it.
            bool holdsSite = false;
            seen[i0] = 1;
            stack.assign(1, {x0, y0});
            while (!stack.empty()) {
                const auto [x, y] = stack.back();
                stack.pop_back();
                if (pixels[c].x == x && pixels[c].y == y) holdsSite = true;
                for (int dy = -1; dy <= 1; ++dy) {
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int nx = x + dx, ny = y + dy;
                        if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                        const std::size_t j = std::size_t(ny) * std::size_t(w) + std::size_t(nx);
                        if (seen[j] || ids.ids[j] != c) continue;
                        seen[j] = 1;
                        stack.emplace_back(nx, ny);
                    }
                }
            }
            if (!holdsSite) ++islands;
        }
    }
    return islands;
}

} // namespace fl::geom
