#pragma once
// Options and helpers shared by the subcommands.

#include <gpu/ShaderLibrary.h>
#include <renderer/GltfLoader.h>
#include <renderer/Renderer.h>
#include <renderer/Scene.h>

#include <CLI/CLI.hpp>

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace fl::app {

/// A bad-input failure: printed as one line, exit code 1.
class InputError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// Options every rendering subcommand takes.
struct SceneOptions {
    std::string scene;                // empty = the built-in default scene
    std::optional<float> lightRadius; // --light-radius
    std::string shaderDir;            // --shader-dir
    int shadowMapSize = 1024;
    std::string shadowMap = "uniform"; // provider: uniform | tsm
    std::string method = "hard";       // hard | jfa-l | flood-l | jfa-e | flood-e | pcf | pcss |
                                       // reference
    int jfaPasses = 6;                 // JFA-L / flood-L reach: 2^passes - 1 texels
    bool fullJfa = false;              // --full-jfa: log2(grid size) passes
    bool noObjectIdFix = false;        // JFA-E: first jump-too-far fix off
    bool noMidpointFix = false;        // JFA-E: second jump-too-far fix off
    float boundaryThreshold = 0.0f;    // JFA-E boundary distance; 0 = automatic
    int pcfKernel = 3;                 // pcf: kernel x kernel taps
    std::string pcssPreset = "16/24";  // pcss: blocker/filter samples
    int referenceSamples = 256;        // reference: point lights over the disk
    int referenceMapSize = 2048;       // reference: texels per side of each map
    float slopeBias = 2.0f;
    float constantBias = 2.0f;
    std::string timing = "auto";
    std::string camera = "default"; // default | auto | N (glTF camera index)
    std::vector<float> eye, target; // explicit look-at
    std::optional<float> fov;       // degrees
};

/// Registers the scene/shadow/camera options on a subcommand.
void addSceneOptions(CLI::App& cmd, SceneOptions& o, bool sceneAsOption);
/// Registers --width/--height with the accepted range.
void addSizeOptions(CLI::App& cmd, int& width, int& height);

/// The committed default scene (assets/default.glb) or, if that file is absent, the same scene
/// generated in memory.
Scene loadDefaultScene(const LoadOptions& options);
/// Loads o.scene (or the default), printing warnings to stderr; throws InputError.
Scene loadScene(const SceneOptions& o);
/// The shader library for --shader-dir (or the embedded shaders); throws InputError.
ShaderLibrary makeShaderLibrary(const SceneOptions& o);
RenderSettings makeRenderSettings(const SceneOptions& o);
/// JFA-E / flood-E flood the frame: their pass count must fit a width x height frame; throws
/// InputError naming the valid range (the other methods are checked by makeRenderSettings).
void checkEyePasses(const SceneOptions& o, const RenderSettings& s, int width, int height);
CameraSpec makeCameraSpec(const SceneOptions& o);
/// The camera the options ask for at width x height; throws InputError (e.g. no such camera).
CameraView initialCamera(const Scene& scene, const SceneOptions& o, int width, int height);

/// Parameters of the built-in default scene (also how assets/default.glb was made).
inline constexpr std::size_t kDefaultSceneTriangles = 6320;
inline constexpr std::uint32_t kDefaultSceneSeed = 1;

/// Prints per-pass times and the frame total on one line each.
void printTimings(const Renderer& renderer, std::ostream& out);

} // namespace fl::app
