// Steps G4 (Voronoi vertices on pixel corners) and G5 (chaining them along rows) of the thesis
// (§6.3.2).
#include <geometry/DiscreteTriangles.h>

#include <jfa/CpuKernel.h>
#include <jfa/Plan.h>

#include <algorithm>
#include <utility>

namespace fl::geom {

CornerCase classifyCorner(std::uint32_t c1, std::uint32_t c2, std::uint32_t c3, std::uint32_t c4) {
    // Fig. 6.10 first: with two colours it is case 1 either way, but it is the one two-colour
    // pattern that §6.4 relies on never seeing, so it gets its own value for the statistics.
    if (c1 == c3 && c2 == c4) return c1 == c2 ? CornerCase::None : CornerCase::Alternating;
    const int colours =
        1 + (c2 != c1) + (c3 != c1 && c3 != c2) + (c4 != c1 && c4 != c2 && c4 != c3);
    if (colours <= 2) return CornerCase::None;
    if (colours == 4) return CornerCase::Four;
    // Three colours: exactly one pair of pixels shares a colour. An edge-adjacent pair is one of
    // the four valid subcases; a diagonal pair means the shared colour is a slim region that cuts
    // the other two apart (Fig. 6.6), so the corner is not a Voronoi vertex.
    if (c1 == c2) return CornerCase::ThreeA;
    if (c2 == c3) return CornerCase::ThreeB;
    if (c3 == c4) return CornerCase::ThreeC;
    if (c4 == c1) return CornerCase::ThreeD;
    if (c2 == c4) return CornerCase::ExcludedA;
    return CornerCase::ExcludedB; // c1 == c3
}

CornerTexture classifyCorners(const IdTexture& ids, int threads) {
    CornerTexture out;
    out.width = ids.width;
    out.height = ids.height;
    out.cases.assign(ids.ids.size(), CornerCase::None);
    const int w = ids.width, h = ids.height;
    // Corners of pixel rows 0..h-2; the top row's corners lie on the border.
    const int rows = std::max(0, h - 1);
    using Counts = std::array<std::int64_t, kCornerCaseCount>;
    std::vector<Counts> perBand(
        static_cast<std::size_t>(jfa::bandCount(std::max(rows, 1), threads)), Counts{});
    if (rows > 0) {
        jfa::parallelRows(rows, threads, [&](int rowBegin, int rowEnd, int band) {
            Counts& counts = perBand[static_cast<std::size_t>(band)];
            for (int y = rowBegin; y < rowEnd; ++y) {
                const std::uint32_t* lower = &ids.ids[std::size_t(y) * std::size_t(w)];
                const std::uint32_t* upper = lower + w;
                CornerCase* row = &out.cases[std::size_t(y) * std::size_t(w)];
                for (int x = 0; x + 1 < w; ++x) {
                    const CornerCase c =
                        classifyCorner(lower[x], lower[x + 1], upper[x + 1], upper[x]);
                    row[x] = c;
                    ++counts[static_cast<std::size_t>(c)];
                }
            }
        });
    }
    for (const Counts& c : perBand) {
        for (std::size_t k = 0; k < kCornerCaseCount; ++k) out.counts[k] += c[k];
    }
    // Border corners (last column, last row) are case 1.
    const std::int64_t classified = std::int64_t(rows) * std::max(0, w - 1);
    out.counts[static_cast<std::size_t>(CornerCase::None)] +=
        std::int64_t(out.cases.size()) - classified;
    return out;
}

namespace {

VertexChain emptyChain(const CornerTexture& corners) {
    VertexChain chain;
    chain.width = corners.width;
    chain.height = corners.height;
    chain.next.assign(corners.cases.size(), kNoVertex);
    return chain;
}

} // namespace

VertexChain chainRowsJfa(const CornerTexture& corners, int threads) {
    VertexChain chain = emptyChain(corners);
    const int w = corners.width, h = corners.height;
    if (w == 0 || h == 0) return chain;
    const std::vector<int> steps = jfa::jfaSteps(w);
    jfa::parallelRows(h, threads, [&](int rowBegin, int rowEnd, int) {
        std::vector<std::int32_t> a(static_cast<std::size_t>(w)), b(static_cast<std::size_t>(w));
        for (int y = rowBegin; y < rowEnd; ++y) {
            // Seeds: every vertex is its own nearest vertex to the right.
            for (int x = 0; x < w; ++x)
                a[std::size_t(x)] = isVoronoiVertex(corners.at(x, y)) ? x : kNoVertex;
            for (int step : steps) {
                // One-sided pass: a texel reads itself and the texel `step` to its right only, so
                // information flows leftwards (the thesis' one query per pass instead of two).
                for (int x = 0; x < w; ++x) {
                    std::int32_t best = a[std::size_t(x)];
                    if (x + step < w) {
                        const std::int32_t r = a[std::size_t(x + step)];
                        if (r != kNoVertex && (best == kNoVertex || r < best)) best = r;
                    }
                    b[std::size_t(x)] = best;
                }
                std::swap(a, b);
            }
            std::copy(a.begin(), a.end(), chain.next.begin() + std::ptrdiff_t(y) * w);
        }
    });
    return chain;
}

VertexChain chainRows(const CornerTexture& corners, int threads) {
    VertexChain chain = emptyChain(corners);
    const int w = corners.width, h = corners.height;
    if (w == 0 || h == 0) return chain;
    jfa::parallelRows(h, threads, [&](int rowBegin, int rowEnd, int) {
        for (int y = rowBegin; y < rowEnd; ++y) {
            std::int32_t* row = &chain.next[std::size_t(y) * std::size_t(w)];
            std::int32_t nearest = kNoVertex;
            for (int x = w - 1; x >= 0; --x) {
                if (isVoronoiVertex(corners.at(x, y))) nearest = x;
                row[x] = nearest;
            }
        }
    });
    return chain;
}

} // namespace fl::geom
