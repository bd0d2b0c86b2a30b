// Step G6 of the thesis (§6.3.2): one or two triangles per Voronoi vertex, T'(S').
#include <geometry/DiscreteTriangles.h>

#include <jfa/CpuKernel.h>

#include <stdexcept>

namespace fl::geom {

std::int64_t pixelOrient(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c) {
    return (std::int64_t(b.x) - a.x) * (std::int64_t(c.y) - a.y) -
           (std::int64_t(b.y) - a.y) * (std::int64_t(c.x) - a.x);
}

std::int64_t pixelInCircle(glm::ivec2 a, glm::ivec2 b, glm::ivec2 c, glm::ivec2 d) {
    // The lifted 3x3 determinant relative to d. Pixel coordinates lie in [0, 2^13): differences
    // < 2^13, lifts and 2x2 minors < 2^27, products < 2^54, so no partial sum comes near 2^63.
    const std::int64_t adx = std::int64_t(a.x) - d.x, ady = std::int64_t(a.y) - d.y;
    const std::int64_t bdx = std::int64_t(b.x) - d.x, bdy = std::int64_t(b.y) - d.y;
    const std::int64_t cdx = std::int64_t(c.x) - d.x, cdy = std::int64_t(c.y) - d.y;
    const std::int64_t alift = adx * adx + ady * ady;
    const std::int64_t blift = bdx * bdx + bdy * bdy;
    const std::int64_t clift = cdx * cdx + cdy * cdy;
    return alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) +
           clift * (adx * bdy - bdx * ady);
}

namespace {

// One band's output; bands are concatenated in row order, so the result is the same for every
// thread count.
struct BandMesh {
    std::vector<VoronoiVertex> vertices;
    std::vector<std::uint32_t> triangles;
    std::vector<std::uint32_t> triangleVertex; // band-local vertex indices
    TriangleStats stats;
};

class MeshBuilder {
  public:
    MeshBuilder(const std::vector<glm::ivec2>& pixels, BandMesh& out)
        : pixels_(pixels), out_(out) {}

    void vertex(const VoronoiVertex& v) {
        const auto index = static_cast<std::uint32_t>(out_.vertices.size());
        out_.vertices.push_back(v);
        const auto& [c1, c2, c3, c4] = v.colours;
        // Case 2: the three colours in the counterclockwise order of pixels 1-4, skipping the
        // repeated one (Property 6.2: regions counterclockwise around a corner give a
        // counterclockwise triangle). The shared pair: 1-2 (a), 2-3 (b), 3-4 (c), 4-1 (d).
        // clang-format off
        switch (v.kind) {
        case CornerCase::ThreeA: three(index, c1, c3, c4); break;
        case CornerCase::ThreeB: three(index, c1, c2, c4); break;
        case CornerCase::ThreeC:
        case CornerCase::ThreeD: three(index, c1, c2, c3); break;
        case CornerCase::Four: four(index, c1, c2, c3, c4); break;
        default: throw std::logic_error("buildTriangles: the chain names a non-vertex corner");
        }
        // clang-format on
    }

  private:
    glm::ivec2 at(std::uint32_t id) const { return pixels_[id]; }

    void three(std::uint32_t index, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        ++out_.stats.threeColour;
        emit(index, a, b, c);
    }

    // Case 3 (two triangles): the thesis picks the diagonal "arbitrarily" and relies on C4; a
    // diagonal with a clockwise or flat triangle would give C4 an overlap or a sliver to undo, and
    // one that fails the empty-circle test on the pixels is a certain flip, so avoid both when the
    // other diagonal allows it.
    void four(std::uint32_t index, std::uint32_t a, std::uint32_t b, std::uint32_t c,
              std::uint32_t d) {
        const glm::ivec2 pa = at(a), pb = at(b), pc = at(c), pd = at(d);
        ++out_.stats.fourColour;
        const bool acValid = pixelOrient(pa, pb, pc) > 0 && pixelOrient(pa, pc, pd) > 0;
        const bool bdValid = pixelOrient(pa, pb, pd) > 0 && pixelOrient(pb, pc, pd) > 0;
        bool useBd = bdValid && !acValid;
        if (acValid && bdValid) useBd = pixelInCircle(pa, pb, pc, pd) > 0; // d inside abc's circle
        if (useBd) {
            emit(index, a, b, d);
            emit(index, b, c, d);
        } else {
            emit(index, a, b, c);
            emit(index, a, c, d);
        }
    }

    void emit(std::uint32_t index, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        const std::int64_t o = pixelOrient(at(a), at(b), at(c));
        if (o == 0) ++out_.stats.degenerate;
        if (o < 0) ++out_.stats.clockwise;
        out_.triangles.insert(out_.triangles.end(), {a, b, c});
        out_.triangleVertex.push_back(index);
    }

    const std::vector<glm::ivec2>& pixels_;
    BandMesh& out_;
};

} // namespace

DiscreteTriangles buildTriangles(const IdTexture& ids, const CornerTexture& corners,
                                 const VertexChain& chain, const std::vector<glm::ivec2>& pixels,
                                 int threads) {
    const int w = ids.width, h = ids.height;
    if (corners.width != w || corners.height != h || chain.width != w || chain.height != h) {
        throw std::invalid_argument("buildTriangles: texture, corners and chain differ in size");
    }
    DiscreteTriangles out;
    const int rows = h - 1; // corner rows; the top row's corners lie on the border
    if (rows <= 0 || w < 2) return out;
    std::vector<BandMesh> bands(static_cast<std::size_t>(jfa::bandCount(rows, threads)));
    // The GPU version runs one CUDA thread per row and pre-allocates from per-row counts; on the
    // CPU a band of rows appends to its own arrays instead.
    jfa::parallelRows(rows, threads, [&](int rowBegin, int rowEnd, int band) {
        BandMesh& mesh = bands[static_cast<std::size_t>(band)];
        MeshBuilder builder(pixels, mesh);
        for (int y = rowBegin; y < rowEnd; ++y) {
            const std::uint32_t* lower = &ids.ids[std::size_t(y) * std::size_t(w)];
            const std::uint32_t* upper = lower + w;
            // Jump from vertex to vertex (Fig. 6.7): the first is next(0), then next(v + 1).
            for (std::int32_t x = chain.at(0, y); x != kNoVertex;
                 x = x + 1 < w ? chain.at(x + 1, y) : kNoVertex) {
                builder.vertex(VoronoiVertex{
                    {x, y}, corners.at(x, y), {lower[x], lower[x + 1], upper[x + 1], upper[x]}});
            }
        }
    });
    for (const BandMesh& b : bands) {
        const auto base = static_cast<std::uint32_t>(out.vertices.size());
        out.vertices.insert(out.vertices.end(), b.vertices.begin(), b.vertices.end());
        out.triangles.insert(out.triangles.end(), b.triangles.begin(), b.triangles.end());
        for (std::uint32_t v : b.triangleVertex) out.triangleVertex.push_back(base + v);
        out.stats.threeColour += b.stats.threeColour;
        out.stats.fourColour += b.stats.fourColour;
        out.stats.degenerate += b.stats.degenerate;
        out.stats.clockwise += b.stats.clockwise;
    }
    return out;
}

} // namespace fl::geom
