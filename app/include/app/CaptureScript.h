#pragma once
// Capture scripts (`floodlight capture SCRIPT.json`): the scene, the camera path, an optional
// light path and radius, the resolutions, the shadow-map provider, the reference's settings and
// the methods, each with its own options. Format (every field but "methods" and "camera" is
// optional; paths are relative to the script's folder):
//   {"scene": "default" | "FILE.glb",
//    "camera": {"frames": N, "path": "default"}            // the walkthrough of `compare`
//            | {"frames": N, "path": "auto"}               // every frame at --camera auto
//            | {"frames": N, "path": "orbit"}              // circling the auto frame
//            | {"frames": N, "file": "PATH.json"}          // a camera-path file (CameraPath.h)
//            | {"frames": N, "fov": deg, "interpolation": "catmull-rom" | "linear",
//               "keys": [{"eye": [x,y,z], "target": [x,y,z]}, ...]},
//    "light": {"radius": R | "size": F,                     // scene units | a fraction of the
//              "keys": [[x,y,z], ...]},                    // model's radius (--light-size);
//                                                          // keys: positions, piecewise linear
//    "resolutions": [[W, H], ...],                         // default [[512, 512]]
//    "shadowMap": {"provider": "uniform" | "tsm", "size": S},
//    "jfaPasses": P | "auto",                              // default "auto" (as --jfa-passes)
//    "reference": {"kind": KIND, KEY: VALUE, ...},         // the ground truth every metric is
//                                                          // measured against: the method-table
//                                                          // row of truth KIND (groundTruthKinds;
//                                                          // default kCaptureTruth); keys: that
//                                                          // row's options
//    "methods": ["hard", "pcss:16/24", "pcf:5", {"method": "jfa-l", "passes": 7, "label": ".."}],
//                                                          // keys: the method's options in the
//                                                          // method table ("name:V" sets its
//                                                          first)
//    "animation": {"name": "all" | "none" | NAME | INDEX,  // the time axis: frame i is posed
//                  "start": S, "fps": F},                  // at S + i / F s (F 0 or absent:
//                                                          // all at S); default: all at 0
//    "saveFrames": true,                                   // PNG + EXR per frame x method
//    "ground": "auto" | "on" | "off"}                      // as --ground (default auto)
// Every problem is reported as "FILE: FIELD: problem".

#include <renderer/Renderer.h>
#include <renderer/soft/ReferenceShadow.h>
#include <scene/CameraPath.h>

#include <array>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace fl::app {

/// The named camera paths of "camera": {"path": NAME}: the walkthrough from the scene's camera,
/// the auto frame held still, and a circle around it (namedCamera in Common.h makes them).
inline constexpr std::array<std::string_view, 3> kCameraPathNames = {"default", "auto", "orbit"};

/// A malformed or incomplete script: the message names the file and the field.
class CaptureScriptError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// The most frames a script's camera may ask for (camera.frames; shown in capture --help).
inline constexpr int kMaxCaptureFrames = 100'000;

/// One row of the results: a method with its options.
struct MethodSpec {
    std::string label;           // unique: "jfa-l", "pcss:16/24", or the script's "label"
    std::string method = "hard"; // a name of the method table
    MethodOptions options;       // the entry's options, by flag (checked against the row)
};

struct CaptureScript {
    std::filesystem::path file;
    std::filesystem::path scene; // empty = the default scene
    int frames = 0;
    std::optional<CameraPath> camera; // nullopt: "path" (cameraPath) says
    /// "path": one of kCameraPathNames (namedCamera, Common.h).
    std::string cameraPath = "default";
    std::optional<float> lightRadius;
    std::optional<float> lightSize;   // "light.size": --light-size
    std::vector<glm::vec3> lightKeys; // empty: the scene's light stays where it is
    std::vector<std::pair<int, int>> resolutions;
    std::string shadowMapProvider = "uniform";
    int shadowMapSize = 1024;
    geom::TrapezoidParams tsm; // "shadowMap": the keys of tsmOptions()
    std::string jfaPasses{floodPassesOption().defaultValue}; // --jfa-passes of every flood method
    /// The ground truth the metrics use: a method of the table with a `truth` kind, with the
    /// options the script gives it, by flag (checked against its row; unset: the row's defaults).
    struct Reference {
        std::string kind{kCaptureTruth};
        MethodOptions options;
        /// Its row of the method table.
        [[nodiscard]] const MethodDescriptor& method() const { return groundTruth(kind); }
    } reference;
    std::vector<MethodSpec> methods;
    bool saveFrames = true;
    std::string ground = "auto"; // --ground: auto | on | off (scene/Ground.h)
    /// The time axis (scene/Pose.h): which animations play, from when, how fast.
    struct Clip {
        std::string name = "all";
        double start = 0.0;
        double fps = 0.0; // 0: every frame at `start`
    } animation;
};

/// Parses a script's JSON text; `file` names it in messages and anchors relative paths.
CaptureScript parseCaptureScript(const std::string& text, const std::filesystem::path& file);
/// Reads and parses a script file (a regular file of at most kTextInputLimitMiB); throws
/// CaptureScriptError.
CaptureScript readCaptureScript(const std::filesystem::path& file);

/// The reference in words, its kind and what its row says of its options: "maps: 256
/// point-light shadow maps of 2048^2 (spiral)" or "raytrace: 256 shadow rays per pixel (Embree)".
std::string referenceText(const CaptureScript::Reference& r);

/// `base` with the method and its options applied.
RenderSettings settingsFor(const RenderSettings& base, const MethodSpec& m);

} // namespace fl::app
