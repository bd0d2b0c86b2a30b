// The Delaunay visualiser: random points (or given ones) through the pipeline of thesis §6.3
// (geom::delaunay with keepStages), one stage at a time: sites, discrete Voronoi, islands,
// Voronoi vertices, T', hull fixed, shifted, missing inserted, flipped. Everything is drawn in
// the texture's coordinates (N x N) over the viewport's square.

#include "OverlayState.h"

#include <jfa/CpuKernel.h>
#include <jfa/Sites.h>

#include <algorithm>
#include <unordered_set>

namespace fl::overlay {

namespace {

// Small enough that islands and snapping are visible; the CPU backend keeps it GPU-free.
constexpr int kTextureSide = 256;
constexpr int kMaxPoints = 20000;
constexpr glm::vec4 kSite{0.0f, 0.0f, 0.0f, 1.0f};
constexpr glm::vec4 kEdge{0.85f, 0.85f, 0.85f, 1.0f};
constexpr glm::vec4 kNew{1.0f, 0.55f, 0.0f, 1.0f};
constexpr glm::vec4 kFlip{0.1f, 0.8f, 0.3f, 1.0f};
constexpr glm::vec4 kMiss{1.0f, 0.1f, 0.1f, 1.0f};
constexpr glm::vec4 kVertex{0.1f, 0.35f, 1.0f, 1.0f};

void refresh(DelaunayCache& cache, OverlayControls& c) {
    if (c.regenerate) {
        ++c.seed;
        c.regenerate = false;
        cache.valid = false;
    }
    const int points = std::clamp(c.delaunayPoints, 3, kMaxPoints);
    const std::vector<glm::dvec2>* given = c.delaunayInput.empty() ? nullptr : &c.delaunayInput;
    if (cache.valid && cache.seed == c.seed && cache.points == points &&
        (given ? *given == cache.input : true))
        return;
    cache = DelaunayCache{};
    cache.valid = true;
    cache.seed = c.seed;
    cache.points = points;
    if (given) {
        cache.input = *given;
    } else {
        jfa::SplitMix64 rng(c.seed);
        for (int i = 0; i < points; ++i) cache.input.push_back({rng.unit(), rng.unit()});
    }
    geom::DelaunayOptions o;
    o.discrete.size = kTextureSide;
    o.discrete.threads = 1;
    o.keepStages = true;
    try {
        cache.result = geom::delaunay(cache.input, o);
    } catch (const std::invalid_argument& e) {
        cache.error = e.what();
    }
}

std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
    if (a > b) std::swap(a, b);
    return std::uint64_t(a) << 32 | b;
}

// The edges of `now` as lines; those `before` lacks (if given) in `fresh`.
void addEdges(std::vector<Vertex>& out, const std::vector<std::uint32_t>& now,
              const std::vector<std::uint32_t>* before, const std::vector<glm::vec2>& at,
              glm::vec4 fresh) {
    std::unordered_set<std::uint64_t> old, drawn;
    if (before)
        for (std::size_t t = 0; t + 2 < before->size(); t += 3)
            for (std::size_t k = 0; k < 3; ++k)
                old.insert(edgeKey((*before)[t + k], (*before)[t + (k + 1) % 3]));
    std::vector<Vertex> added;
    for (std::size_t t = 0; t + 2 < now.size(); t += 3)
        for (std::size_t k = 0; k < 3; ++k) {
            const std::uint32_t a = now[t + k], b = now[t + (k + 1) % 3];
            if (!drawn.insert(edgeKey(a, b)).second) continue;
            const bool isNew = before && !old.count(edgeKey(a, b));
            auto& list = isNew ? added : out;
            list.push_back({at[a], isNew ? fresh : kEdge});
            list.push_back({at[b], isNew ? fresh : kEdge});
        }
    out.insert(out.end(), added.begin(), added.end()); // new edges on top
}

// An id texture as NearestSite-style cells (z = id, -1 where no site).
jfa::Grid idGrid(const geom::IdTexture& ids, const std::vector<glm::ivec2>& pixels) {
    jfa::Grid g(ids.width, ids.height, jfa::kEmptyCell);
    for (int y = 0; y < ids.height; ++y)
        for (int x = 0; x < ids.width; ++x) {
            const std::uint32_t id = ids.at(x, y);
            if (id == geom::kNoSite) continue;
            const glm::ivec2 p = pixels[id];
            g.at(x, y) = {float(p.x), float(p.y), float(id), 0.0f};
        }
    return g;
}

} // namespace

Lines drawDelaunay(State& s, const Frame& f) {
    refresh(s.delaunay, f.controls);
    const DelaunayCache& cache = s.delaunay;
    if (!cache.error.empty()) return {"delaunay: " + cache.error};
    const geom::DelaunayResult& r = cache.result;
    const geom::DiscreteDelaunay& d = r.discrete;
    const int stageCount = int(OverlayRenderer::delaunayStageNames().size());
    int& step = f.controls.delaunayStep;
    step = std::clamp(step, 0, stageCount - 1);
    const int n = d.snapped.mapping.size;
    std::vector<glm::vec2> points, pixels;
    for (const glm::dvec2 p : cache.input)
        points.push_back(texelToNdc(d.snapped.mapping.toTexture(p), n));
    for (const glm::ivec2 p : d.snapped.pixels) pixels.push_back(texelToNdc(glm::dvec2(p), n));
    const bool onPixels = step >= 1 && step <= 5; // G2-C1 work on the pixel positions
    const std::vector<glm::vec2>& at = onPixels ? pixels : points;

    // Background: a label grid for the discrete stages, else an empty one (uniform grey).
    jfa::Grid grid(1, 1, jfa::kEmptyCell);
    std::vector<std::uint8_t> mask(1, 0);
    if (step == 1) grid = idGrid(d.voronoi, d.snapped.pixels);
    if (step == 2 || step == 3) grid = idGrid(d.cleaned, d.snapped.pixels);
    if (step == 2) {
        mask.assign(grid.cells.size(), 0);
        for (std::size_t i = 0; i < mask.size(); ++i)
            mask[i] = d.voronoi.ids[i] != d.cleaned.ids[i] ? 1 : 0;
    } else {
        mask.assign(grid.cells.size(), 0);
    }
    const glm::ivec4 vp = squareViewport(f.width, f.height);
    const gl::Texture gridTex = jfa::uploadGrid(grid);
    const gl::Texture maskTex = uploadMask(mask, grid.width, grid.height);
    f.bindTarget();
    s.canvas.drawGrid({GridMode::Voronoi, &gridTex, nullptr, &maskTex}, vp);

    std::vector<Vertex> lines, marks;
    if (step >= 4 && r.stages.size() >= 5) {
        const std::size_t k = std::size_t(step - 4);
        addEdges(lines, r.stages[k], k > 0 ? &r.stages[k - 1] : nullptr, at,
                 step == 8 ? kFlip : kNew);
    }
    if (step == 6) // C2's shift vectors: from each kept site's pixel to its position
        for (const std::uint32_t i : d.snapped.kept) {
            lines.push_back({pixels[i], kVertex});
            lines.push_back({points[i], kVertex});
        }
    s.canvas.drawVertices(lines, GL_LINES, vp);
    for (std::size_t i = 0; i < at.size(); ++i)
        if (r.duplicateOf.empty() || r.duplicateOf[i] == i) marks.push_back({at[i], kSite});
    if (step == 0 || step == 7)
        for (const geom::MissingSite& m : d.missing()) marks.push_back({points[m.site], kMiss});
    s.canvas.drawVertices(marks, GL_POINTS, vp, 3.0f);
    if (step == 3) {
        std::vector<Vertex> vertices;
        for (const geom::VoronoiVertex& v : d.mesh.vertices)
            vertices.push_back({texelToNdc(glm::dvec2(v.pixel) + 0.5, n),
                                v.kind == geom::CornerCase::Four ? kMiss : kVertex});
        s.canvas.drawVertices(vertices, GL_POINTS, vp, 3.0f);
    }
    s.result.grid = std::move(grid);
    s.result.mask = std::move(mask);
    s.result.viewport = vp;
    s.result.drawn = true;
    static constexpr const char* kWhat[] = {
        "input points; red: lose their pixel in G1",
        "G2 discrete Voronoi diagram, sites on their pixels",
        "G3: red pixels were islands and got recoloured",
        "G4 Voronoi vertices (blue: three colours, red: four)",
        "G6 mesh T' on the pixel positions",
        "C1 convex hull completed (orange: new edges)",
        "C2 sites shifted to their positions (blue: shift vectors)",
        "C3 missing sites (red) inserted (orange: new edges)",
        "C4 edges flipped (green) into the Delaunay triangulation"};
    return {"delaunay step " + std::to_string(step + 1) + "/" + std::to_string(stageCount) + ": " +
                std::string(OverlayRenderer::delaunayStageNames()[std::size_t(step)]),
            kWhat[step],
            std::to_string(cache.input.size()) + " points, texture " + std::to_string(n) + "^2, " +
                std::to_string(d.missing().size()) + " missing, " +
                std::to_string(d.islands.reassigned) + " island pixels"};
}

} // namespace fl::overlay
