// The exact repair's GL compute twin (shaders/jfa_exact_repair.comp.glsl) against the CPU repair
// (jfa/ExactRepair.h): texel for texel equal on every case of VoronoiCases.h (uniform, clustered,
// collinear, co-circular, masks; grids <= 96^2), from JFA's result, from flood:1 (most texels
// empty: walks from vertex 0) and from a grid where every texel holds a far site, and end to end
// after each backend's own JFA. The comparison is exact: both sides compare the same integer
// squared distances and copy cells verbatim, so no rounding boundary is involved.

#include "GlTest.h"
#include "VoronoiCases.h"

#include <geometry/SiteGraph.h>

#include <jfa/CpuKernel.h>
#include <jfa/ExactRepair.h>
#include <jfa/Plan.h>
#include <jfa/Reference.h>
#include <jfa_gl/GlExactRepair.h>
#include <jfa_gl/GlKernel.h>

#include <gtest/gtest.h>

namespace fl::jfa {
namespace {

class ExactRepairGl : public test::GlTest {};

const NearestSite kCriterion{true};

// Texels where two grids differ, for the failure message.
std::int64_t differences(const Grid& a, const Grid& b) {
    std::int64_t n = 0;
    for (std::size_t i = 0; i < a.cells.size(); ++i) n += !(a.cells[i] == b.cells[i]);
    return n;
}

TEST_F(ExactRepairGl, EqualsTheCpuRepairTexelForTexel) {
    GlExactRepair repair(test::testShaders());
    GlFloodKernel<NearestSite> kernel(test::testShaders(), GlKernelKind::Compute);
    for (const test::VoronoiCase& c : test::voronoiCases(96)) {
        SCOPED_TRACE(c.name);
        Grid seeds = c.seeds;
        const SiteGraph graph = geom::buildSiteGraph(seeds);
        repair.setGraph(graph);
        const int w = seeds.width, h = seeds.height;
        Grid wrong = seeds;
        if (!graph.vertices.empty())
            for (Cell& cell : wrong.cells)
                if (kCriterion.empty(cell)) cell = graph.vertices.back();
        const ExactField exact = exactNearest(seeds, kCriterion);
        for (const Grid& start : {flood(Plan::jfa(w, h), seeds, kCriterion),
                                  flood(Plan::flood(1, w, h), seeds, kCriterion), wrong}) {
            Grid cpu = start;
            repairNearest(cpu, graph, 2);
            const gl::Texture in = uploadGrid(start);
            const Grid gpu = readGrid(repair.run(in));
            EXPECT_EQ(differences(cpu, gpu), 0);
            EXPECT_EQ(countErrors(gpu, exact, kCriterion), 0);
        }
        // End to end: each backend floods its own JFA, then repairs.
        const gl::Texture tagged = uploadGrid(seeds);
        const Grid gpu = readGrid(repair.run(kernel.run(Plan::jfa(w, h), tagged, kCriterion)));
        Grid cpu = flood(Plan::jfa(w, h), seeds, kCriterion);
        repairNearest(cpu, graph);
        EXPECT_EQ(differences(cpu, gpu), 0);
    }
}

} // namespace
} // namespace fl::jfa
