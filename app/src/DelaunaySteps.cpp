// The step pictures of `floodlight delaunay --steps DIR`: one SVG per stage of the pipeline, so
// that each step of thesis §6.3.2 can be seen doing its job on a real input.

#include <app/DelaunaySteps.h>

#include <base/OutputFiles.h>

#include <geometry/MeshSvg.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <unordered_set>

namespace fl::app {

namespace {

// Label grids larger than this per side are sampled: a 4096^2 texture is ~100 MB of SVG runs.
constexpr int kMaxGridSide = 1024;
// Highlighted island pixels drawn at most (each is an SVG rectangle).
constexpr std::size_t kMaxIslandPixels = 200000;

const char* const kSiteColour = "#202020";
const char* const kEdgeColour = "#9a9a9a";
const char* const kNewColour = "#e07000";  // what a step added
const char* const kFlipColour = "#108a30"; // edges made by C4 flips
const char* const kMissColour = "#d01010"; // missing sites, island pixels

// World position of pixel (or corner) p of the texture.
glm::dvec2 world(const geom::TextureMapping& m, glm::dvec2 p) {
    return m.toWorld(p);
}

// The sites at their pixel positions (what G2-C1 work on).
std::vector<glm::dvec2> pixelPositions(const geom::DiscreteDelaunay& d) {
    std::vector<glm::dvec2> out;
    out.reserve(d.snapped.pixels.size());
    for (const glm::ivec2 p : d.snapped.pixels)
        out.push_back(world(d.snapped.mapping, glm::dvec2(p)));
    return out;
}

// An id texture as a label grid in world space, sampled down to kMaxGridSide per side.
geom::SvgLabelGrid labelGrid(const geom::IdTexture& ids, const geom::TextureMapping& m) {
    const int stride = (std::max(ids.width, ids.height) + kMaxGridSide - 1) / kMaxGridSide;
    geom::SvgLabelGrid g;
    g.width = (ids.width + stride - 1) / stride;
    g.height = (ids.height + stride - 1) / stride;
    g.origin = world(m, glm::dvec2(-0.5));
    g.pixelSize = glm::dvec2(double(stride) * m.texelSize());
    g.labels.reserve(std::size_t(g.width) * std::size_t(g.height));
    for (int y = 0; y < g.height; ++y)
        for (int x = 0; x < g.width; ++x) {
            const std::uint32_t id = ids.at(std::min(x * stride + stride / 2, ids.width - 1),
                                            std::min(y * stride + stride / 2, ids.height - 1));
            g.labels.push_back(id == geom::kNoSite ? -1 : std::int32_t(id));
        }
    return g;
}

std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
    if (a > b) std::swap(a, b);
    return std::uint64_t(a) << 32 | b;
}

// End points (pairs) of the edges of `now` that `before` lacks.
std::vector<glm::dvec2> newEdges(const std::vector<std::uint32_t>& before,
                                 const std::vector<std::uint32_t>& now,
                                 const std::vector<glm::dvec2>& at) {
    std::unordered_set<std::uint64_t> old;
    for (std::size_t t = 0; t + 2 < before.size(); t += 3)
        for (int k = 0; k < 3; ++k) old.insert(edgeKey(before[t + k], before[t + (k + 1) % 3]));
    std::unordered_set<std::uint64_t> drawn;
    std::vector<glm::dvec2> ends;
    for (std::size_t t = 0; t + 2 < now.size(); t += 3)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = now[t + k], b = now[t + (k + 1) % 3];
            const std::uint64_t key = edgeKey(a, b);
            if (old.count(key) || !drawn.insert(key).second) continue;
            ends.push_back(at[a]);
            ends.push_back(at[b]);
        }
    return ends;
}

// Sites as markers, without the duplicates and (if given) without the missing ones.
void addSites(geom::SvgPicture& pic, const std::vector<glm::dvec2>& at,
              const geom::DelaunayResult& r, double radius = 1.0) {
    geom::SvgLayer& layer = pic.addLayer("sites", geom::SvgStyle::markers(kSiteColour, radius));
    for (std::size_t i = 0; i < at.size(); ++i)
        if (r.duplicateOf.empty() || r.duplicateOf[i] == i) layer.addPoint(at[i]);
}

void addMissing(geom::SvgPicture& pic, const std::vector<glm::dvec2>& at,
                const geom::DiscreteDelaunay& d) {
    geom::SvgLayer& layer = pic.addLayer("missing", geom::SvgStyle::markers(kMissColour, 1.6));
    for (const geom::MissingSite& m : d.missing()) layer.addPoint(at[m.site]);
}

void addMesh(geom::SvgPicture& pic, const std::vector<glm::dvec2>& at,
             const std::vector<std::uint32_t>& triangles) {
    pic.addLayer("triangles", geom::SvgStyle::lines(kEdgeColour)).addTriangleEdges(at, triangles);
}

// The mesh after a step, with the edges the step made (absent from `before`) drawn over it.
void addMeshStep(geom::SvgPicture& pic, const std::vector<glm::dvec2>& at,
                 const std::vector<std::uint32_t>& before, const std::vector<std::uint32_t>& after,
                 const char* id, const char* colour) {
    addMesh(pic, at, after);
    pic.addLayer(id, geom::SvgStyle::lines(colour, 2.0)).addSegments(newEdges(before, after, at));
}

void addGrid(geom::SvgPicture& pic, const char* id, const geom::IdTexture& ids,
             const geom::TextureMapping& m, double opacity) {
    geom::SvgStyle style = geom::SvgStyle::areas("none", opacity);
    style.crispEdges = true;
    pic.addLayer(id, style).addLabelGrid(labelGrid(ids, m));
}

// The pixels G3 recoloured, as red squares (full resolution, up to kMaxIslandPixels).
void addIslandPixels(geom::SvgPicture& pic, const geom::DiscreteDelaunay& d) {
    const geom::TextureMapping& m = d.snapped.mapping;
    geom::SvgLayer& layer = pic.addLayer("island-pixels", geom::SvgStyle::areas(kMissColour));
    std::size_t drawn = 0;
    for (int y = 0; y < d.voronoi.height && drawn < kMaxIslandPixels; ++y)
        for (int x = 0; x < d.voronoi.width && drawn < kMaxIslandPixels; ++x)
            if (d.voronoi.at(x, y) != d.cleaned.at(x, y)) {
                layer.addRect(world(m, glm::dvec2(x - 0.5, y - 0.5)),
                              world(m, glm::dvec2(x + 0.5, y + 0.5)));
                ++drawn;
            }
}

void addVertices(geom::SvgPicture& pic, const geom::DiscreteDelaunay& d) {
    geom::SvgLayer& layer = pic.addLayer("vertices", geom::SvgStyle::markers("#1050d0", 0.8));
    for (const geom::VoronoiVertex& v : d.mesh.vertices)
        layer.addPoint(world(d.snapped.mapping, glm::dvec2(v.pixel) + 0.5),
                       v.kind == geom::CornerCase::Four ? kMissColour : std::string());
}

// Shift vectors of C2: from each kept site's pixel to its continuous position.
void addShifts(geom::SvgPicture& pic, const std::vector<glm::dvec2>& pixels,
               const std::vector<glm::dvec2>& points, const geom::DiscreteDelaunay& d) {
    std::vector<glm::dvec2> ends;
    for (const std::uint32_t i : d.snapped.kept) {
        ends.push_back(pixels[i]);
        ends.push_back(points[i]);
    }
    pic.addLayer("shifts", geom::SvgStyle::lines("#1050d0", 1.5)).addSegments(ends);
}

} // namespace

void writeStepPictures(const std::filesystem::path& dir, const std::vector<glm::dvec2>& points,
                       const geom::DelaunayResult& r, std::ostream& log) {
    if (r.stages.size() < 5)
        throw std::runtime_error("--steps: the pipeline kept " + std::to_string(r.stages.size()) +
                                 " stages, expected 5 (T', C1, C2, C3, C4)");
    makeOutputFolder(dir, "--steps");
    const geom::DiscreteDelaunay& d = r.discrete;
    const geom::TextureMapping& m = d.snapped.mapping;
    const std::vector<glm::dvec2> pixels = pixelPositions(d);
    // One picture: `draw` fills it, then it is written to dir/name and logged with `what`.
    auto save = [&](const char* name, const std::string& what, const auto& draw) {
        geom::SvgPicture pic;
        draw(pic);
        geom::writeSvg(dir / name, pic);
        log << "wrote " << (dir / name).string() << ": " << what << "\n";
    };
    save("01_sites.svg", "input points; red: lose their pixel in G1", [&](geom::SvgPicture& pic) {
        addSites(pic, points, r);
        addMissing(pic, points, d);
    });
    save("02_voronoi.svg", "G2 discrete Voronoi diagram, sites on their pixels",
         [&](geom::SvgPicture& pic) {
             addGrid(pic, "voronoi", d.voronoi, m, 1.0);
             addSites(pic, pixels, r);
         });
    save("03_islands.svg", "G3: red pixels were islands and got recoloured",
         [&](geom::SvgPicture& pic) {
             addGrid(pic, "cleaned", d.cleaned, m, 0.6);
             addIslandPixels(pic, d);
             addSites(pic, pixels, r);
         });
    save("04_vertices.svg", "G4 Voronoi vertices (blue: three colours, red: four)",
         [&](geom::SvgPicture& pic) {
             addGrid(pic, "cleaned", d.cleaned, m, 0.35);
             addVertices(pic, d);
             addSites(pic, pixels, r, 0.7);
         });
    save("05_mesh.svg", "G6 mesh T' on the pixel positions", [&](geom::SvgPicture& pic) {
        addMesh(pic, pixels, r.stages[0]);
        addSites(pic, pixels, r);
    });
    save("06_hull.svg", "C1 convex hull completed (orange: new edges)", [&](geom::SvgPicture& pic) {
        addMeshStep(pic, pixels, r.stages[0], r.stages[1], "added", kNewColour);
        addSites(pic, pixels, r);
    });
    save("07_shifted.svg", "C2 sites shifted to their positions (blue: shift vectors)",
         [&](geom::SvgPicture& pic) {
             addMesh(pic, points, r.stages[2]);
             addShifts(pic, pixels, points, d);
             addSites(pic, points, r);
         });
    save("08_missing.svg", "C3 missing sites (red) inserted (orange: new edges)",
         [&](geom::SvgPicture& pic) {
             addMeshStep(pic, points, r.stages[2], r.stages[3], "added", kNewColour);
             addSites(pic, points, r);
             addMissing(pic, points, d);
         });
    save("09_flipped.svg", "C4 edges flipped (green) into the Delaunay triangulation",
         [&](geom::SvgPicture& pic) {
             addMeshStep(pic, points, r.stages[3], r.stages[4], "flipped", kFlipColour);
             addSites(pic, points, r);
         });
}

} // namespace fl::app
