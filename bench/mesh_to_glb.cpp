// A mesh file (Wavefront OBJ, STL, PLY) as a GLB the renderer loads: one mesh, one instance, no
// light (the renderer places its default one). Normals are the file's, or smooth ones that keep
// edges sharper than the crease angle (bench/support/MeshImport.h). For the real-model benchmark
// (bench/real_models.sh), whose public models come in these formats too.

#include <scene/SceneGenerator.h>

#include <base/InputFile.h>
#include <base/Text.h>

#include <BenchSupport.h>
#include <CLI/CLI.hpp>
#include <MeshImport.h>

#include <cstdio>
#include <iostream>

int main(int argc, char** argv) {
    CLI::App app{"mesh_to_glb: a Wavefront OBJ, STL (binary or ASCII) or PLY (ASCII or binary "
                 "little-endian) mesh as a GLB of one mesh, one instance and no light"};
    std::string input, output;
    float crease = fl::bench::kCreaseDegrees;
    app.add_option(
           "input", input,
           fl::cat("Mesh file: .obj, .stl or .ply (at most ", fl::kSceneInputLimitMiB, " MiB)"))
        ->required();
    app.add_option("output", output, "The .glb to write")->required();
    app.add_option("--crease", crease,
                   "Where the file has no normals: faces meeting at a sharper angle than this "
                   "(degrees) keep separate normals")
        ->check(CLI::Range(0.0f, 180.0f))
        ->capture_default_str();
    return fl::bench::parseAndRun(app, argc, argv, [&] {
        std::size_t dropped = 0;
        fl::bench::ImportedMesh m = fl::bench::readMeshFile(input, &dropped, crease);
        const std::size_t triangles = m.mesh.triangleCount(), vertices = m.mesh.positions.size();
        fl::writeGlb(fl::bench::meshScene(std::move(m.mesh), input), output);
        std::printf("%s: %s, %zu faces -> %zu triangles, %zu vertices, normals %s", input.c_str(),
                    m.format.c_str(), m.polygons, triangles, vertices,
                    m.normalsComputed ? fl::cat("computed (crease ", crease, " degrees)").c_str()
                                      : "from the file");
        if (dropped) std::printf(" (%zu zero-area triangles dropped)", dropped);
        std::printf("\nwrote %s\n", output.c_str());
        return 0;
    });
}
