// The overlays of the renderer's last frame: shadow map, seeds, penumbra map, the flood pass by
// pass, the Voronoi diagram / distance transform of the seeds, and JFA vs standard flooding.

#include "OverlayState.h"

#include <renderer/overlays/SiteDiagram.h>
#include <renderer/soft/EyeSoftShadow.h>
#include <renderer/soft/PenumbraCriterion.h>
#include <renderer/soft/PenumbraMap.h>

#include <algorithm>
#include <chrono>
#include <cstdio>

namespace fl::overlay {

namespace {

std::string percent(std::int64_t n, std::int64_t total) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3f%%", total > 0 ? 100.0 * double(n) / double(total) : 0.0);
    return buf;
}

// The flood of the last frame's method (light space: JFA-L, flood-L on the shadow map's grid;
// eye space: JFA-E, flood-E on the frame's pixels), as the method keeps it.
using Soft = FloodFrame;

std::optional<Soft> softOf(const Renderer& r) {
    const FloodFrame* f = r.flood();
    if (!f || !f->seeds || !r.shadow()) return std::nullopt;
    return *f;
}

std::string timing(const SiteDiagram& d) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "GL flood + read-back %.1f ms, exact diagram (CPU) %.1f ms",
                  d.floodMs, d.exactMs);
    return buf;
}

// "needs a soft method's last frame (jfa-l, ...)": the flooding methods of the table.
const std::string kNeedsSoft =
    "needs a soft method's last frame (" +
    methodNamesWhere([](const MethodDescriptor& m) { return m.floods; }) + ")";

glm::ivec4 viewportOf(const Soft& soft, const Frame& f) {
    return soft.eye ? glm::ivec4(0, 0, f.width, f.height) : squareViewport(f.width, f.height);
}

// The frame's flood plan, with JFA or standard flooding.
jfa::Plan framePlan(const Soft& soft, bool standardFlooding) {
    if (soft.eye) {
        const int w = soft.seeds->width(), h = soft.seeds->height();
        return eyeSoftPlan(soft.passes, standardFlooding, w, h);
    }
    PenumbraSettings ps;
    ps.passes = soft.passes;
    ps.standardFlooding = standardFlooding;
    return penumbraPlan(ps, soft.seeds->width());
}

// Runs `plan` on the frame's seeds with the frame's criterion, over the frame's flood region
// and penumbra bound (the same band the method used; identical to the full grid either way);
// the texture is the kernel's.
const gl::Texture& floodFrame(State& s, const Renderer& r, const Soft& soft,
                              const jfa::Plan& plan) {
    const int tile = soft.kernel ? soft.kernel->bandTile() : jfa::kDefaultBandTile;
    if (soft.eye) {
        EyeSoftCriterion c;
        c.reachBound = soft.reach;
        s.eyeKernel.setRegion(soft.region, tile);
        c.light = r.disk();
        c.objectIdFix = soft.objectIdFix;
        c.midpointFix = soft.midpointFix;
        c.cells = soft.eyeCells;
        return s.eyeKernel.run(plan, *soft.seeds, c);
    }
    PenumbraCriterion c;
    c.reachBound = soft.reach;
    c.umbraDepth = soft.umbraDepth;
    s.penumbraKernel.setRegion(soft.region, tile);
    c.light = r.disk();
    c.map = *soft.map;
    return s.penumbraKernel.run(plan, *soft.seeds, c);
}

// A grid of the frame's flood read back as cells, and a texture of them the canvas can draw:
// the GPU's grids are packed (PenumbraCriterion/EyeSoftCriterion::packedCells), so they are
// drawn from an upload of their cells.
struct Cells {
    jfa::Grid grid;
    gl::Texture unpacked;
    [[nodiscard]] const gl::Texture& texture() const { return unpacked; }
};

Cells readCells(const FloodGridReader& reader, const gl::Texture& grid) {
    Cells c;
    c.grid = reader.read(grid);
    c.unpacked = jfa::uploadGrid(c.grid);
    return c;
}

std::int64_t nonEmpty(const jfa::Grid& g) {
    return std::count_if(g.cells.begin(), g.cells.end(),
                         [](const jfa::Cell& c) { return c.w != 0.0f; });
}

} // namespace

Lines drawShadowMap(State& s, const Frame& f) {
    const ShadowMapPass::Outputs* sh = f.renderer.shadow();
    if (!sh) return {"no frame rendered yet"};
    const glm::ivec4 vp = squareViewport(f.width, f.height);
    f.bindTarget();
    s.canvas.drawGrid({GridMode::Depth, &sh->depth}, vp);
    s.result.viewport = vp;
    s.result.drawn = true;
    return {"shadow map " + std::to_string(sh->depth.width()) + "^2 (" +
                std::string(providerName(sh->provider)) + "), light depth: near bright, far dark",
            "black: nothing seen"};
}

Lines drawSeeds(State& s, const Frame& f) {
    const std::optional<Soft> soft = softOf(f.renderer);
    if (!soft) return {kNeedsSoft};
    const glm::ivec4 vp = viewportOf(*soft, f);
    Cells seeds = readCells(FloodGridReader(*soft), *soft->seeds);
    f.bindTarget();
    s.canvas.drawGrid({GridMode::Seeds, &seeds.texture()}, vp);
    s.result.grid = std::move(seeds.grid);
    s.result.viewport = vp;
    s.result.drawn = true;
    return {std::string(soft->eye ? "boundary seeds (eye space, JFA-E phase 3): "
                                  : "silhouette seeds (light space, JFA-L phase 2): ") +
            std::to_string(nonEmpty(s.result.grid)) + " seeds"};
}

// Draws a flood's occluder grid (penumbra map or eye-space flood) coloured by light fraction,
// and keeps it as the overlay's result.
static void drawOccluders(State& s, const Frame& f, const Soft& soft, const gl::Texture& grid) {
    const glm::ivec4 vp = viewportOf(soft, f);
    Cells cells = readCells(FloodGridReader(soft), grid);
    // Light space: the map's positions decoded (the bits the flood's criterion read).
    GridDraw g{GridMode::Occluder, &cells.texture(),
               soft.eye ? &soft.eyeCells->decoded().first : &f.renderer.decodedShadowReceivers()};
    g.eyeSpace = soft.eye;
    g.light = &f.renderer.disk();
    f.bindTarget();
    s.canvas.drawGrid(g, vp);
    s.result.grid = std::move(cells.grid);
    s.result.viewport = vp;
    s.result.drawn = true;
}

Lines drawPenumbraMap(State& s, const Frame& f) {
    const std::optional<Soft> soft = softOf(f.renderer);
    if (!soft) return {kNeedsSoft};
    drawOccluders(s, f, *soft, *soft->flooded);
    return {std::string(soft->eye ? "eye-space flood (JFA-E phase 4)" : "penumbra map (JFA-L)") +
                ": " + std::to_string(nonEmpty(s.result.grid)) + " texels hold an occluder",
            "colour: light fraction from the occluder (dark 0 .. pale 1); grey: none"};
}

Lines drawFloodPasses(State& s, const Frame& f) {
    const std::optional<Soft> soft = softOf(f.renderer);
    if (!soft) return {kNeedsSoft};
    const jfa::Plan full = framePlan(*soft, soft->standardFlooding);
    const int total = full.passCount();
    int& k = f.controls.floodPass;
    if (k > total) k = total;
    if (k < -1) k = -1;
    const int shown = k < 0 ? total : k;
    const jfa::Plan plan = truncatePlan(full, shown);
    const gl::Texture& out = floodFrame(s, f.renderer, *soft, plan);
    drawOccluders(s, f, *soft, out);
    const std::vector<int> steps = full.steps();
    std::string step =
        shown == 0 ? "seeds only" : "last step " + std::to_string(steps[std::size_t(shown - 1)]);
    return {full.name() + ": after " + std::to_string(shown) + " of " + std::to_string(total) +
                " passes (" + step + ")",
            std::to_string(nonEmpty(s.result.grid)) + " texels hold an occluder"};
}

Lines drawSiteDiagram(State& s, const Frame& f, bool distance) {
    const std::optional<Soft> soft = softOf(f.renderer);
    if (!soft) return {kNeedsSoft};
    const jfa::Grid sites = sitesFromSeeds(readFloodGrid(*soft, *soft->seeds));
    const jfa::Plan plan = variantPlan(f.controls.variant, sites.width, sites.height);
    SiteDiagram d = floodSites(s.siteKernel, plan, sites);
    const gl::Texture grid = jfa::uploadGrid(d.flooded);
    const gl::Texture mask = uploadMask(d.errors, sites.width, sites.height);
    GridDraw g{distance ? GridMode::Distance : GridMode::Voronoi, &grid, nullptr, &mask};
    g.scale = std::max(d.maxDistance, 1.0f);
    const glm::ivec4 vp = viewportOf(*soft, f);
    f.bindTarget();
    s.canvas.drawGrid(g, vp);
    s.result.grid = std::move(d.flooded);
    s.result.mask = std::move(d.errors);
    s.result.count = d.errorCount;
    s.result.viewport = vp;
    s.result.drawn = true;
    return {std::string(distance ? "distance transform" : "Voronoi diagram") + " of the " +
                std::to_string(d.sites) + (soft->eye ? " boundary" : " silhouette") + " seeds, " +
                plan.describe(),
            "errors vs exact (red): " + std::to_string(d.errorCount) + " (" +
                percent(d.errorCount, std::int64_t(sites.cells.size())) + ")",
            timing(d)};
}

Lines drawJfaVsFlood(State& s, const Frame& f) {
    const std::optional<Soft> soft = softOf(f.renderer);
    if (!soft) return {kNeedsSoft};
    // The other method's flood of the same seeds: JFA for a flood-L/E frame, else standard
    // flooding (2^passes - 1 step-1 passes: the cost of this overlay, see the benchmarks).
    const jfa::Plan plan = framePlan(*soft, !soft->standardFlooding);
    // Everything the reference flood depends on besides the seeds: the camera (eye-space
    // points), the shadow map's matrices (receivers), the light, the plan and the criterion.
    std::vector<float> key;
    const auto add = [&](const float* v, std::size_t n) { key.insert(key.end(), v, v + n); };
    const ShadowMapPass::Outputs& sh = *f.renderer.shadow();
    for (const glm::mat4* m : {&f.camera.view, &f.camera.proj, &sh.lightViewProj, &sh.warp})
        add(&(*m)[0][0], 16);
    const DiskLight& disk = f.renderer.disk();
    add(&disk.center.x, 3);
    add(&disk.normal.x, 3);
    key.push_back(disk.radius);
    key.push_back(float(plan.passCount()));
    key.push_back(soft->eye ? 1.0f : 0.0f);
    key.push_back(soft->objectIdFix ? 1.0f : 0.0f);
    key.push_back(soft->midpointFix ? 1.0f : 0.0f);
    const FloodGridReader reader(*soft); // the unpacking source read once for all three grids
    jfa::Grid seeds = reader.read(*soft->seeds);
    ReferenceCache& cache = s.reference;
    const bool reused = cache.key == key && cache.seeds == seeds;
    if (!reused) {
        const auto t0 = std::chrono::steady_clock::now();
        cache.reference = reader.read(floodFrame(s, f.renderer, *soft, plan));
        cache.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                       .count();
        cache.texture = jfa::uploadGrid(cache.reference);
        cache.key = std::move(key);
        cache.seeds = std::move(seeds);
    }
    const gl::Texture& other = cache.texture;
    const double ms = cache.ms;
    s.result.reference = cache.reference;
    Cells flooded = readCells(reader, *soft->flooded);
    s.result.grid = flooded.grid;
    s.result.mask.assign(s.result.grid.cells.size(), 0);
    for (std::size_t i = 0; i < s.result.mask.size(); ++i)
        s.result.mask[i] = s.result.grid.cells[i] == s.result.reference.cells[i] ? 0 : 1;
    s.result.count = std::count(s.result.mask.begin(), s.result.mask.end(), std::uint8_t(1));
    const glm::ivec4 vp = viewportOf(*soft, f);
    f.bindTarget();
    s.canvas.drawGrid({GridMode::Diff, &flooded.texture(), &other}, vp);
    s.result.viewport = vp;
    s.result.drawn = true;
    char msText[32];
    std::snprintf(msText, sizeof msText, "%.1f ms", ms);
    return {std::string("frame's ") + (soft->standardFlooding ? "flood" : "JFA") + " vs " +
                plan.name() + ": " + std::to_string(s.result.count) +
                " texels hold another "
                "occluder (" +
                percent(s.result.count, std::int64_t(s.result.mask.size())) + ")",
            "red: differ; grey: same occluder; reference flood + read-back took " +
                std::string(msText) + (reused ? " (reused: same seeds and view)" : "")};
}

} // namespace fl::overlay
