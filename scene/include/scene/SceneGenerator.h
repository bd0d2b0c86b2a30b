#pragma once
// Deterministic procedural scenes in the spirit of the thesis' "fantasy" test scene, and GLB
// output.

#include <scene/Scene.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace fl {

struct SceneGenParams {
    std::size_t triangles = 6320; // exact triangle count of the result (minimum kMinTriangles)
    std::uint32_t seed = 1;       // same params -> bit-identical scene on every machine
};

/// The smallest triangle count generateScene accepts.
inline constexpr std::size_t kMinTriangles = 600;

/// The thesis' scene sizes (Table 5.1) by name: knight 634, teapot 6320, bunny 69451,
/// fantasy 101861, fantasy2 216440.
struct NamedSize {
    const char* name;
    std::size_t triangles;
};
const std::vector<NamedSize>& thesisSceneSizes();

/// Builds the scene: terrain, tree, pergola, mushrooms, rock, flower, characters, and a light.
/// Each character is skinned to a skeleton and either walks in place (animation "walk") or waves
/// its raised arm ("wave"), both looping every second; time 0 of both is the rest pose. Throws
/// std::invalid_argument if params.triangles < kMinTriangles.
Scene generateScene(const SceneGenParams& params);

/// Writes a scene as binary glTF (.glb) that loadGltf reads back to the same scene.
/// Writes to a temporary name and renames, so a failed write never leaves a partial file.
void writeGlb(const Scene& scene, const std::filesystem::path& file);

} // namespace fl
