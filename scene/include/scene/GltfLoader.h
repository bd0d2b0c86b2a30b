#pragma once
// glTF 2.0 (.gltf / .glb) loading with validation of everything Floodlight uses.

#include <scene/Scene.h>

#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>

namespace fl {

/// Thrown for a scene that cannot be used; what() names the file, the element and the problem,
/// e.g. "scene.gltf: accessors[3]: index 812 past vertex count 800".
class SceneError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

struct LoadOptions {
    /// Overrides the light's disk radius (else extras.radius, else kDefaultLightSize of the
    /// scene's radius).
    std::optional<float> lightRadius;
    /// Receives warnings about repaired or skipped content ("file: element: what was done").
    std::function<void(const std::string&)> warn;
};

/// Loads a .gltf or .glb file into a Scene; throws SceneError on anything unusable.
Scene loadGltf(const std::filesystem::path& file, const LoadOptions& options = {});
/// Loads a .glb held in memory (the binary's built-in scene), named `name` in messages and in
/// Scene::source; it can have no external files. Throws SceneError as loadGltf does.
Scene loadGlbBytes(std::span<const unsigned char> glb, const std::string& name,
                   const LoadOptions& options = {});

} // namespace fl
