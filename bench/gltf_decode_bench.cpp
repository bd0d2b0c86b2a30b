// Loading compressed meshes: the same generated grid (about 1M triangles by default) as an
// ordinary .glb, a KHR_draco_mesh_compression .glb and an EXT_meshopt_compression .glb, each
// loaded with loadGltf several times; prints file size and min/median load time. The meshopt
// file stores quantised attributes (as gltfpack writes them), so it is compared with the
// ordinary file of the same quantised data as well as with the float one the Draco file encodes.
// The files are built with the encoders of the test support (tests/support/CompressedGltf.h).

#include <scene/GltfLoader.h>

#include "CompressedGltf.h"

#include <BenchSupport.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <vector>

namespace {

struct Timing {
    double min = 0, median = 0;
};

/// loadGltf(path) `runs` times; the milliseconds' min and median.
Timing timeLoad(const std::filesystem::path& path, int runs, std::size_t& triangles) {
    std::vector<double> ms;
    for (int r = 0; r < runs; ++r) {
        const auto start = std::chrono::steady_clock::now();
        const fl::Scene scene = fl::loadGltf(path);
        const auto end = std::chrono::steady_clock::now();
        triangles = scene.triangleCount();
        ms.push_back(std::chrono::duration<double, std::milli>(end - start).count());
    }
    std::sort(ms.begin(), ms.end());
    return {ms.front(), ms[ms.size() / 2]};
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"gltf_decode_bench: load times of Draco / meshopt compressed meshes"};
    int grid = 708, runs = 7;
    app.add_option("--grid", grid, "Vertices per side of the grid (2*(n-1)^2 triangles)")
        ->check(CLI::Range(2, 4000))
        ->capture_default_str();
    app.add_option("--runs", runs, "Loads per file")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    return fl::bench::parseAndRun(app, argc, argv, [&] {
        using fl::test::Container;
        const fl::test::GridMesh mesh = fl::test::gridMesh(grid);
        const auto draco = fl::test::dracoGltf(mesh);
        const auto meshopt = fl::test::meshoptGltf(mesh);
        const std::vector<std::pair<std::string, std::filesystem::path>> files = {
            {"plain (float)", fl::test::plainGltf(mesh).write("bench_plain.glb", Container::Glb)},
            {"draco (14/10/12 bits)", draco.gltf.write("bench_draco.glb", Container::Glb)},
            {"plain (quantised)", meshopt.plain.write("bench_quantised.glb", Container::Glb)},
            {"meshopt", meshopt.compressed.write("bench_meshopt.glb", Container::Glb)},
        };
        std::printf("grid %dx%d: %zu vertices, %zu triangles; loadGltf, %d runs each\n", grid, grid,
                    mesh.positions.size(), mesh.indices.size() / 3, runs);
        std::printf("%-24s %12s %12s %12s %12s\n", "file", "MiB", "triangles", "min ms",
                    "median ms");
        for (const auto& [name, path] : files) {
            std::size_t triangles = 0;
            const Timing t = timeLoad(path, runs, triangles);
            std::printf("%-24s %12.2f %12zu %12.1f %12.1f\n", name.c_str(),
                        static_cast<double>(std::filesystem::file_size(path)) / (1 << 20),
                        triangles, t.min, t.median);
        }
        return 0;
    });
}
