#include "Common.h"

#include <renderer/SceneGenerator.h>

#include <cmath>
#include <iomanip>
#include <iostream>

namespace fl::app {

namespace {
constexpr int kMaxImageSize = 8192; // per side: 8192² RGBA16F + R32F + depth ≈ 768 MiB
constexpr int kMaxShadowMapSize = 8192;
} // namespace

void addSceneOptions(CLI::App& cmd, SceneOptions& o, bool sceneAsOption) {
    if (sceneAsOption)
        cmd.add_option("--scene", o.scene, "glTF 2.0 scene (.gltf/.glb); default: built-in scene");
    else
        cmd.add_option("scene", o.scene, "glTF 2.0 scene (.gltf/.glb); default: built-in scene");
    // 0 is allowed: a point light, for which every soft method gives exactly the hard shadows.
    cmd.add_option("--light-radius", o.lightRadius,
                   "Disk light radius in scene units (0 = a point light: hard shadows)")
        ->check(CLI::Validator(
            [](const std::string& text) -> std::string {
                double v = 0.0;
                if (!CLI::detail::lexical_cast(text, v) || !std::isfinite(v) || v < 0.0)
                    return "must be a finite number >= 0, got '" + text + "'";
                return {};
            },
            "RADIUS>=0"));
    cmd.add_option("--shader-dir", o.shaderDir,
                   "Load shaders from this folder instead of the binary");
    cmd.add_option("--shadow-map-size", o.shadowMapSize, "Shadow map texels per side")
        ->check(CLI::Range(16, kMaxShadowMapSize))
        ->capture_default_str();
    cmd.add_option("--shadow-map", o.shadowMap,
                   "Shadow-map provider: uniform (fitted to the scene) or tsm (trapezoidal)")
        ->check(CLI::IsMember({"uniform", "tsm"}))
        ->capture_default_str();
    cmd.add_option("--method", o.method,
                   "Shadow method: hard, jfa-l (JFA penumbra map, thesis 5.3), flood-l (its "
                   "standard-flooding reference), jfa-e (JFA in eye space, thesis 5.4), flood-e "
                   "(its standard-flooding reference), pcf, pcss (baselines), reference "
                   "(ground truth: N point-light maps over the disk)")
        ->check(CLI::IsMember(
            {"hard", "jfa-l", "flood-l", "jfa-e", "flood-e", "pcf", "pcss", "reference"}))
        ->capture_default_str();
    cmd.add_option("--pcf-kernel", o.pcfKernel,
                   "pcf: taps per side of the kernel (N x N depth comparisons one uniform-map "
                   "texel apart, in the light's unwarped plane)")
        ->check(CLI::Range(1, kMaxPcfKernel))
        ->capture_default_str();
    cmd.add_option("--pcss-preset", o.pcssPreset, "pcss: blocker-search/filter samples")
        ->check(CLI::IsMember({"16/16", "16/24", "32/64"}))
        ->capture_default_str();
    cmd.add_option("--reference-samples", o.referenceSamples,
                   "reference: point lights (shadow maps) over the disk light")
        ->check(CLI::Range(1, 65536))
        ->capture_default_str();
    cmd.add_option("--reference-map-size", o.referenceMapSize,
                   "reference: texels per side of each point light's shadow map")
        ->check(CLI::Range(16, kMaxShadowMapSize))
        ->capture_default_str();
    cmd.add_flag("--full-jfa", o.fullJfa,
                 "Full JFA: as many passes as the grid allows (log2 of the shadow-map size for "
                 "-l, of the frame for -e), instead of --jfa-passes");
    cmd.add_option("--jfa-passes", o.jfaPasses,
                   "Flooding passes of jfa-l / flood-l / jfa-e / flood-e: penumbrae up to 2^N - 1 "
                   "shadow-map texels (-l) or pixels (-e) wide; 1 to log2(size)")
        ->check(CLI::Range(1, 13))
        ->capture_default_str();
    cmd.add_flag("--no-object-id-fix", o.noObjectIdFix,
                 "jfa-e / flood-e: let occluders flood into the hard shadows of other objects "
                 "(thesis 5.4.2, first jump-too-far fix off)");
    cmd.add_flag("--no-midpoint-fix", o.noMidpointFix,
                 "jfa-e / flood-e: no midpoint continuity check (thesis 5.4.2, second fix off)");
    cmd.add_option("--boundary-threshold", o.boundaryThreshold,
                   "jfa-e / flood-e: largest 3D distance from a shadowed boundary pixel to its lit "
                   "neighbour, in scene units; 0 = 6 pixel footprints")
        ->check(CLI::Range(0.0f, 1e6f))
        ->capture_default_str();
    cmd.add_option("--bias-slope", o.slopeBias,
                   "Slope-scaled depth bias (polygon offset factor, in light depth)")
        ->check(CLI::Range(0.0f, 64.0f))
        ->capture_default_str();
    cmd.add_option("--bias-constant", o.constantBias,
                   "Constant depth bias (polygon offset units, in light depth)")
        ->check(CLI::Range(0.0f, 4096.0f))
        ->capture_default_str();
    cmd.add_option("--timing", o.timing, "Pass timing: auto, query (GL timers), finish (glFinish)")
        ->check(CLI::IsMember({"auto", "query", "finish"}))
        ->capture_default_str();
    cmd.add_option(
           "--camera", o.camera,
           "default (scene camera, else auto), auto (frame the bounds), or a glTF camera index")
        ->capture_default_str();
    cmd.add_option("--eye", o.eye, "Camera position x,y,z (with --target)")
        ->delimiter(',')
        ->expected(3);
    cmd.add_option("--target", o.target, "Camera target x,y,z (with --eye)")
        ->delimiter(',')
        ->expected(3);
    cmd.add_option("--fov", o.fov, "Vertical field of view, degrees")
        ->check(CLI::Range(1.0f, 170.0f));
}

void addSizeOptions(CLI::App& cmd, int& width, int& height) {
    cmd.add_option("--width", width, "Image width in pixels")
        ->check(CLI::Range(1, kMaxImageSize))
        ->capture_default_str();
    cmd.add_option("--height", height, "Image height in pixels")
        ->check(CLI::Range(1, kMaxImageSize))
        ->capture_default_str();
}

Scene loadDefaultScene(const LoadOptions& options) {
    const std::filesystem::path asset =
        std::filesystem::path(FLOODLIGHT_SOURCE_DIR) / "assets" / "default.glb";
    if (std::filesystem::exists(asset)) return loadGltf(asset, options);
    Scene s = generateScene({kDefaultSceneTriangles, kDefaultSceneSeed});
    if (options.lightRadius && s.light) s.light->radius = *options.lightRadius;
    return s;
}

Scene loadScene(const SceneOptions& o) {
    LoadOptions lo;
    lo.lightRadius = o.lightRadius;
    lo.warn = [](const std::string& w) { std::cerr << "warning: " << w << "\n"; };
    try {
        return o.scene.empty() ? loadDefaultScene(lo) : loadGltf(o.scene, lo);
    } catch (const SceneError& e) {
        throw InputError(e.what());
    }
}

ShaderLibrary makeShaderLibrary(const SceneOptions& o) {
    try {
        return o.shaderDir.empty() ? ShaderLibrary() : ShaderLibrary(o.shaderDir);
    } catch (const std::runtime_error& e) {
        throw InputError(e.what());
    }
}

void checkEyePasses(const SceneOptions& o, const RenderSettings& s, int width, int height) {
    if (o.fullJfa || (s.method != ShadowMethod::JfaE && s.method != ShadowMethod::FloodE)) return;
    try {
        (void)eyeSoftPlan(s.penumbra.passes, false, width, height);
    } catch (const std::invalid_argument& e) {
        throw InputError(std::string("--jfa-passes: ") + e.what());
    }
}

RenderSettings makeRenderSettings(const SceneOptions& o) {
    RenderSettings s;
    s.shadow.size = o.shadowMapSize;
    s.shadow.provider = parseProvider(o.shadowMap).value_or(ShadowMapProvider::Uniform);
    s.method = parseMethod(o.method).value_or(ShadowMethod::Hard);
    s.penumbra.passes = o.jfaPasses;
    const bool eyeSpace = s.method == ShadowMethod::JfaE || s.method == ShadowMethod::FloodE;
    if (o.fullJfa) {
        // Full JFA: steps down from half the grid. JFA-E's grid is the frame, whose size is only
        // known per frame: the largest count is capped there (EyeSoftShadowPass::execute).
        int full = 0;
        while ((2 << full) <= s.shadow.size) ++full;
        s.penumbra.passes = eyeSpace ? 13 : full;
    }
    // Validated here so that a bad count is one clear input error before any rendering (the
    // eye-space methods are checked against the frame: checkEyePasses).
    if (!eyeSpace) try {
            (void)penumbraPlan(s.penumbra, s.shadow.size);
        } catch (const std::invalid_argument& e) {
            throw InputError(std::string("--jfa-passes: ") + e.what());
        }
    s.eyeSoft.objectIdFix = !o.noObjectIdFix;
    s.eyeSoft.midpointFix = !o.noMidpointFix;
    s.eyeSoft.boundaryThreshold = o.boundaryThreshold;
    s.filtered.pcfKernel = o.pcfKernel;
    s.filtered.pcss = parsePcssPreset(o.pcssPreset).value_or(PcssPreset{});
    s.reference.samples = o.referenceSamples;
    s.reference.mapSize = o.referenceMapSize;
    s.shadow.slopeBias = o.slopeBias;
    s.shadow.constantBias = o.constantBias;
    s.timing = o.timing == "query"    ? TimingMode::Query
               : o.timing == "finish" ? TimingMode::Finish
                                      : TimingMode::Auto;
    return s;
}

CameraSpec makeCameraSpec(const SceneOptions& o) {
    CameraSpec c;
    c.yfovDegrees = o.fov;
    if (!o.eye.empty() || !o.target.empty()) {
        if (o.eye.size() != 3 || o.target.size() != 3)
            throw InputError("--eye and --target must be given together, as x,y,z each");
        c.kind = CameraSpec::Kind::LookAt;
        c.eye = {o.eye[0], o.eye[1], o.eye[2]};
        c.target = {o.target[0], o.target[1], o.target[2]};
        return c;
    }
    if (o.camera == "default") return c;
    if (o.camera == "auto") {
        c.kind = CameraSpec::Kind::Auto;
        return c;
    }
    try {
        size_t used = 0;
        c.gltfIndex = std::stoi(o.camera, &used);
        if (used != o.camera.size()) throw std::invalid_argument("trailing characters");
    } catch (const std::exception&) {
        throw InputError("--camera " + o.camera + ": expected default, auto or a camera index");
    }
    c.kind = CameraSpec::Kind::Gltf;
    return c;
}

CameraView initialCamera(const Scene& scene, const SceneOptions& o, int width, int height) {
    try {
        return makeCameraView(scene, makeCameraSpec(o),
                              static_cast<float>(width) / static_cast<float>(height));
    } catch (const std::invalid_argument& e) {
        throw InputError(e.what());
    }
}

void printTimings(const Renderer& renderer, std::ostream& out) {
    out << std::fixed << std::setprecision(2);
    for (const PassTime& p : renderer.timer().passes())
        out << "  " << p.name << ": " << p.ms << " ms\n";
    out << "  frame total: " << renderer.timer().frameMs() << " ms (" << renderer.timer().modeName()
        << ")\n";
    out << std::defaultfloat;
}

} // namespace fl::app
