#pragma once
// Options and helpers shared by the subcommands.

#include <gpu/ShaderLibrary.h>
#include <renderer/Renderer.h>
#include <scene/CameraPath.h>
#include <scene/GltfLoader.h>
#include <scene/Scene.h>

#include <CLI/CLI.hpp>

#include <base/Numbers.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace fl::app {

/// A bad-input failure: printed as one line, exit code 1.
class InputError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// A usage error found after parsing (options that do not go together): one line, exit code 2.
class UsageError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// Options every rendering subcommand takes.
struct SceneOptions {
    std::string scene;                // empty = the built-in default scene
    std::optional<float> lightRadius; // --light-radius
    /// --light-size: the disk's radius as a fraction of the model's bounding radius (the bounds
    /// before an added ground), so one value means the same softness on any model.
    std::optional<float> lightSize;
    std::string shaderDir; // --shader-dir
    int shadowMapSize = 1024;
    std::string shadowMap = "uniform"; // provider: uniform | tsm
    geom::TrapezoidParams tsm;         // --tsm-quantize, --tsm-snap, --tsm-hysteresis
    std::string method = "hard";       // a name of the method table
    /// The methods' options given on the command line, by flag (the table's MethodOption).
    std::map<std::string, std::string> methodOptions;
    /// Refuse options the chosen method does not take (false where methods are switched or
    /// all run: the window, the main job).
    bool strictMethodOptions = true;
    float slopeBias = 2.0f;
    float constantBias = 2.0f;
    std::string timing = "auto";
    std::string camera = "default";             // default | auto | N (glTF camera index)
    std::vector<float> eye, target;             // explicit look-at
    std::optional<float> fov;                   // degrees
    std::string ground = "auto";                // auto | on | off (scene/Ground.h)
    std::vector<float> lightDir, lightPosition; // x,y,z: the light placed by hand
    double time = 0.0;                          // --time: seconds into the animations
    std::string animation = "all";              // --animation: all | none | NAME | INDEX
};

/// Registers the scene/shadow/camera options on a subcommand.
void addSceneOptions(CLI::App& cmd, SceneOptions& o, bool sceneAsOption);
/// Registers every method option of the table (--jfa-passes, --pcf-kernel, ...), once each.
void addMethodOptions(CLI::App& cmd, SceneOptions& o);
/// Registers --width/--height with the accepted range.
void addSizeOptions(CLI::App& cmd, int& width, int& height);

/// For a command line CLI11 refused with arguments left over (ExtrasError): a line per unknown
/// flag naming it and, when one is close (a typo: --lightradius -> --light-radius), the nearest
/// flag `cmd` (the subcommand that ran) takes; empty when no leftover is a flag.
std::string suggestFlags(const CLI::App& cmd);

/// "in [lo, hi]", ">= lo", "<= hi", or `unbounded` when neither bound is finite: a range in
/// --help's words.
std::string rangeText(double lo, double hi, const char* unbounded);

// Numbers, checked once here for every command with fl::numberProblem (base/Numbers.h), the
// same rule the method options and the scripts use: finite, in range, whole for integers (NaN
// and inf passed CLI11's Range, and "abc" was called "not in range"). Usage errors, exit 2.
/// A validator for a finite number in [lo, hi] (either may be kUnbounded); vector options check
/// each element.
CLI::Validator number(double lo = -kUnbounded, double hi = kUnbounded);
/// A validator for an integer in [lo, hi].
CLI::Validator integer(double lo, double hi);

// Output locations, checked once here for every command (usage errors, exit 2): an empty folder
// silently meant the current one, and a --name with '/' or ".." wrote outside --out.
/// A validator for an output folder (--out, --steps, --screenshot-dir): not empty.
CLI::Validator outputFolder();
/// A validator for a file-name stem inside an output folder (--name): not empty, no '/', not
/// starting with '.' (no hidden files, no "." or ".."), so NAME.* stays directly in the folder.
CLI::Validator outputStem();
/// A validator for an output file or file prefix (make-scene --out, delaunay --out, --record):
/// not empty and ending in a file name (not '/', "." or "..").
CLI::Validator outputFile();
/// Registers --out as an output folder (outputFolder) with its default shown.
CLI::Option* addOutOption(CLI::App& cmd, std::string& out, const std::string& help);
/// Registers --name as a file-name stem inside --out (outputStem) with its default shown.
CLI::Option* addNameOption(CLI::App& cmd, std::string& name, const std::string& help);

/// The committed default scene, assets/default.glb, as built into the binary (DefaultScene.cpp):
/// the same scene wherever the binary runs from.
Scene loadDefaultScene(const LoadOptions& options);
/// Loads o.scene (or the default), printing warnings to stderr; throws InputError.
Scene loadScene(const SceneOptions& o);
/// The shader library for --shader-dir (or the embedded shaders); throws InputError.
gl::ShaderLibrary makeShaderLibrary(const SceneOptions& o);
/// The render settings the options ask for; throws UsageError for a method option the chosen
/// method does not take (with o.strictMethodOptions).
RenderSettings makeRenderSettings(const SceneOptions& o);
/// Plays --animation at --time on `renderer` (of `scene`); throws UsageError naming the scene's
/// animations for an --animation it does not have.
void applyAnimation(Renderer& renderer, const Scene& scene, const SceneOptions& o);
/// Checks the method's options for a width x height frame before rendering (e.g. JFA passes that
/// the map or the frame cannot use); throws InputError naming the option and the valid range.
void checkMethodOptions(const RenderSettings& s, int width, int height);
CameraSpec makeCameraSpec(const SceneOptions& o);
/// The camera the options ask for at width x height; throws InputError (e.g. no such camera).
CameraView initialCamera(const Scene& scene, const SceneOptions& o, int width, int height);

/// Parameters of the built-in default scene (also how assets/default.glb was made).
inline constexpr std::size_t kDefaultSceneTriangles = 6320;
inline constexpr std::uint32_t kDefaultSceneSeed = 1;

/// The colour of region `id` in Voronoi pictures (voronoi, voronoi3d): a hash of the id in mid
/// tones, so that black sites and red error cells stand out; negative ids as 0.
std::array<std::uint8_t, 3> regionColour(std::int64_t id);

/// The camera of a named path at width x height (capture scripts' "path"): "default", the
/// walkthrough from the scene's camera (defaultWalkthrough); "auto", the auto frame, still; or
/// "orbit", circling the auto frame (orbitPath). Throws UsageError for another name.
std::variant<CameraView, CameraPath> namedCamera(const std::string& name, const Scene& scene,
                                                 const SceneOptions& o, int width, int height);

/// The one line every rendering command prints about what it used: the light (centre, disk
/// radius, and that radius as a fraction of the model's, --light-size's unit), the shadow map
/// (size, provider) and, for a flooding method, its flood passes: what `rendered` ran in its
/// last frame when given, else what the options ask for ("auto": chosen per frame).
std::string setupLine(const Scene& scene, const RenderSettings& settings, int width, int height,
                      const Renderer* rendered = nullptr);

/// Prints per-pass times and the frame total on one line each.
void printTimings(const Renderer& renderer, std::ostream& out);

} // namespace fl::app
