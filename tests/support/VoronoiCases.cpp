#include "VoronoiCases.h"

#include <jfa/Sites.h>

#include <cmath>
#include <cstdint>
#include <set>
#include <utility>

namespace fl::test {

namespace {

// Distinct integer points inside w x h (later repeats and outside points dropped) as seeds.
jfa::Grid seedsOf(const std::vector<std::pair<int, int>>& points, int w, int h) {
    std::set<std::pair<int, int>> seen;
    std::vector<jfa::Site> sites;
    for (const auto& [x, y] : points)
        if (x >= 0 && y >= 0 && x < w && y < h && seen.insert({x, y}).second)
            sites.push_back({float(x), float(y)});
    return jfa::seedPoints(sites, w, h, true).grid;
}

// `count` points around each of `centres`, normally spread with deviation `sigma` (Box-Muller).
std::vector<std::pair<int, int>> clusters(const std::vector<std::pair<int, int>>& centres,
                                          int count, double sigma, std::uint64_t seed) {
    jfa::SplitMix64 rng(seed);
    std::vector<std::pair<int, int>> out;
    for (const auto& [cx, cy] : centres)
        for (int i = 0; i < count; ++i) {
            const double r = sigma * std::sqrt(-2.0 * std::log(1.0 - rng.unit()));
            const double a = 6.283185307179586 * rng.unit();
            out.emplace_back(cx + int(std::lround(r * std::cos(a))),
                             cy + int(std::lround(r * std::sin(a))));
        }
    return out;
}

// Lattice points at squared distance r2 from (cx, cy): co-circular sites.
std::vector<std::pair<int, int>> circle(int cx, int cy, int r2) {
    std::vector<std::pair<int, int>> out;
    const int r = int(std::sqrt(double(r2))) + 1;
    for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx)
            if (dx * dx + dy * dy == r2) out.emplace_back(cx + dx, cy + dy);
    return out;
}

jfa::Grid maskSeeds(int w, int h, bool (*inside)(int, int, int, int)) {
    std::vector<std::uint8_t> mask(std::size_t(w) * std::size_t(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            mask[std::size_t(y) * std::size_t(w) + std::size_t(x)] = inside(x, y, w, h) ? 1 : 0;
    return jfa::seedMask(mask, w, h);
}

} // namespace

std::vector<VoronoiCase> voronoiCases(int maxSide) {
    const int s = maxSide, m = s / 2;
    std::vector<VoronoiCase> out;
    auto uniform = [&](int n, int w, int h, std::uint64_t seed) {
        out.push_back(
            {"uniform " + std::to_string(n) + " on " + std::to_string(w) + "x" + std::to_string(h),
             jfa::seedPoints(jfa::randomIntegerSites(n, w, h, seed), w, h, true).grid});
    };
    uniform(1, s, s, 1);
    uniform(2, s, s / 2 + 3, 2);
    uniform(3, 37, s, 3);
    uniform(40, s, s, 4);
    uniform(400, s, s - 7, 5);
    uniform(2000, s, s, 6);
    out.push_back({"one tight cluster", seedsOf(clusters({{s / 5, s / 4}}, 300, 3.0, 7), s, s)});
    out.push_back({"three clusters",
                   seedsOf(clusters({{8, 8}, {s - 20, m}, {m, s - 4}}, 150, 6.0, 8), s, s)});
    out.push_back({"cluster and outliers",
                   seedsOf(
                       [&] {
                           auto p = clusters({{m, m}}, 400, 2.0, 9);
                           p.insert(p.end(), {{0, 0}, {s - 1, 0}, {0, s - 1}, {s - 1, s - 1}});
                           return p;
                       }(),
                       s, s)});
    std::vector<std::pair<int, int>> row, column, diagonal, slope, two;
    for (int i = 0; i < s; i += 3) row.emplace_back(i, m);
    for (int i = 1; i < s; i += 5) column.emplace_back(7, i);
    for (int i = 0; i < s; i += 4) diagonal.emplace_back(i, i);
    for (int i = 0; 3 * i < s && 2 * i + 5 < s; ++i) slope.emplace_back(3 * i, 2 * i + 5);
    two = {{3, 4}, {s - 9, s - 2}};
    out.push_back({"collinear row", seedsOf(row, s, s)});
    out.push_back({"collinear column", seedsOf(column, s, s - 5)});
    out.push_back({"collinear diagonal", seedsOf(diagonal, s, s)});
    out.push_back({"collinear slope 2/3", seedsOf(slope, s, s)});
    out.push_back({"two sites", seedsOf(two, s, s)});
    // Co-circular: 12 lattice points on x^2 + y^2 = 25, 16 on 65, 24 on 325, 32 on 1105, all
    // centred on grid points (whose nearest sites then tie), and a lattice of sites (every unit
    // square of it co-circular), plus concentric circles.
    for (int r2 : {25, 65, 325, 1105}) {
        if (2 * int(std::sqrt(double(r2))) + 2 >= s) continue;
        out.push_back({"co-circular r^2 = " + std::to_string(r2), seedsOf(circle(m, m, r2), s, s)});
    }
    std::vector<std::pair<int, int>> lattice, rings;
    for (int y = 2; y < s; y += 6)
        for (int x = 1; x < s; x += 6) lattice.emplace_back(x, y);
    for (int r2 : {25, 100, 325, 625, 1105})
        for (const auto& p : circle(m, m - 3, r2)) rings.push_back(p);
    out.push_back({"lattice", seedsOf(lattice, s, s)});
    out.push_back({"concentric circles", seedsOf(rings, s, s)});
    out.push_back({"mask disk", maskSeeds(s, s, [](int x, int y, int w, int h) {
                       const int dx = x - w / 2, dy = y - h / 3;
                       return dx * dx + dy * dy < w * w / 16;
                   })});
    out.push_back({"mask ring and bar", maskSeeds(s, s - 3, [](int x, int y, int w, int h) {
                       const int dx = x - w / 2, dy = y - h / 2, d = dx * dx + dy * dy;
                       return (d < w * w / 9 && d > w * w / 16) || (x > w - 6 && y > 3);
                   })});
    out.push_back({"mask checkerboard", maskSeeds(s, s, [](int x, int y, int, int) {
                       return ((x / 3) + (y / 5)) % 2 == 0;
                   })});
    out.push_back({"mask every pixel", maskSeeds(40, 24, [](int, int, int, int) { return true; })});
    return out;
}

} // namespace fl::test
