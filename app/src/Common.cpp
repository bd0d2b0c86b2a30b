#include "Common.h"

#include <renderer/scene/Ground.h>

#include <renderer/scene/SceneGenerator.h>

#include <base/InputFile.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>

namespace fl::app {

namespace {
constexpr int kMaxImageSize = 8192; // per side: 8192² RGBA16F + R32F + depth ≈ 768 MiB
constexpr int kMaxShadowMapSize = 8192;
} // namespace

void addSceneOptions(CLI::App& cmd, SceneOptions& o, bool sceneAsOption) {
    const std::string sceneHelp = "glTF 2.0 scene (.gltf/.glb, at most " +
                                  std::to_string(kSceneInputLimitMiB) +
                                  " MiB); default: built-in scene";
    cmd.add_option(sceneAsOption ? "--scene" : "scene", o.scene, sceneHelp);
    // 0 is allowed: a point light, for which every soft method gives exactly the hard shadows.
    cmd.add_option("--light-radius", o.lightRadius,
                   "Disk light radius in scene units (0 = a point light: hard shadows)")
        ->check(number(0.0));
    cmd.add_option("--shader-dir", o.shaderDir,
                   "Load shaders from this folder instead of the binary (files of at most " +
                       std::to_string(kTextInputLimitMiB) + " MiB)");
    cmd.add_option("--shadow-map-size", o.shadowMapSize, "Shadow map texels per side")
        ->check(integer(16, kMaxShadowMapSize))
        ->capture_default_str();
    cmd.add_option("--shadow-map", o.shadowMap,
                   "Shadow-map provider: uniform (fitted to the scene) or tsm (trapezoidal)")
        ->check(CLI::IsMember({"uniform", "tsm"}))
        ->capture_default_str();
    for (const TsmOption& t : tsmOptions()) // out of range: a usage error naming flag and range
        cmd.add_option(std::string(t.flag), o.tsm.*t.field, std::string(t.help))
            ->check(number(t.min, t.max))
            ->capture_default_str();
    std::string methodHelp = "Shadow method:";
    std::vector<std::string> names;
    for (const MethodDescriptor& m : methodTable()) {
        methodHelp += "\n  " + std::string(m.name) + ": " + std::string(m.help);
        names.emplace_back(m.name);
    }
    cmd.add_option("--method", o.method, methodHelp)
        ->check(CLI::IsMember(names))
        ->capture_default_str();
    addMethodOptions(cmd, o);
    cmd.add_option("--bias-slope", o.slopeBias,
                   "Slope-scaled depth bias (polygon offset factor, in light depth)")
        ->check(number(0.0, 64.0))
        ->capture_default_str();
    cmd.add_option("--bias-constant", o.constantBias,
                   "Constant depth bias (polygon offset units, in light depth)")
        ->check(number(0.0, 4096.0))
        ->capture_default_str();
    cmd.add_option("--timing", o.timing, "Pass timing: auto, query (GL timers), finish (glFinish)")
        ->check(CLI::IsMember({"auto", "query", "finish"}))
        ->capture_default_str();
    cmd.add_option(
           "--camera", o.camera,
           "default (scene camera, else auto), auto (frame the bounds; on an added ground, the "
           "model and its shadow), or a glTF camera index")
        ->capture_default_str();
    cmd.add_option("--eye", o.eye, "Camera position x,y,z (with --target)")
        ->check(number())
        ->delimiter(',')
        ->expected(3);
    cmd.add_option("--target", o.target, "Camera target x,y,z (with --eye)")
        ->check(number())
        ->delimiter(',')
        ->expected(3);
    cmd.add_option("--fov", o.fov, "Vertical field of view, degrees")->check(number(1.0, 170.0));
    cmd.add_option("--time", o.time,
                   "Seconds into the scene's animations (glTF animations, skins, morph targets)")
        ->check(number(0.0, kMaxAnimationTime))
        ->capture_default_str();
    cmd.add_option("--animation", o.animation,
                   "Which animations play: all, none, or one by name or index")
        ->capture_default_str();
    cmd.add_option("--ground", o.ground,
                   "A ground plane to receive the shadow: auto (added when the scene has no "
                   "surface under it, as a single model has not), on, off")
        ->check(CLI::IsMember(
            std::vector<std::string>(kGroundModeNames.begin(), kGroundModeNames.end())))
        ->capture_default_str();
    auto* dir = cmd.add_option("--light-dir", o.lightDir,
                               "Light travel direction x,y,z (0,-1,0: straight down): moves the "
                               "scene's light 2.5 scene radii back along it")
                    ->check(number(-kMaxWorldCoordinate, kMaxWorldCoordinate))
                    ->delimiter(',')
                    ->expected(3);
    cmd.add_option("--light-position", o.lightPosition,
                   "Light position x,y,z: moves the scene's light there, aimed at the scene's "
                   "centre")
        ->check(number(-kMaxWorldCoordinate, kMaxWorldCoordinate))
        ->delimiter(',')
        ->expected(3)
        ->excludes(dir);
}

void addMethodOptions(CLI::App& cmd, SceneOptions& o) {
    for (const MethodOption* opt : allMethodOptions()) {
        // "jfa-l, flood-l: ..." — which methods take it, from the table.
        const std::string takers =
            methodNamesWhere([&](const MethodDescriptor& m) { return m.takesFlag(opt->flag); });
        const std::string help = takers + ": " + std::string(opt->help);
        const std::string flag(opt->flag);
        if (opt->kind == OptionKind::Flag) {
            cmd.add_flag_callback(
                flag, [&o, flag] { o.methodOptions[flag] = "true"; }, help);
            continue;
        }
        cmd.add_option_function<std::string>(
               flag, [&o, flag](const std::string& v) { o.methodOptions[flag] = v; }, help)
            ->check(CLI::Validator(
                [opt](const std::string& text) { return checkOptionValue(*opt, text); },
                opt->kind == OptionKind::Choice ? std::string(opt->choices)
                : opt->kind == OptionKind::Int  ? std::string("INT")
                                                : std::string("FLOAT")))
            ->default_str(std::string(opt->defaultValue));
    }
}

void addSizeOptions(CLI::App& cmd, int& width, int& height) {
    cmd.add_option("--width", width, "Image width in pixels")
        ->check(integer(1, kMaxImageSize))
        ->capture_default_str();
    cmd.add_option("--height", height, "Image height in pixels")
        ->check(integer(1, kMaxImageSize))
        ->capture_default_str();
}

CLI::Validator number(double lo, double hi) {
    return CLI::Validator(
        [lo, hi](const std::string& text) { return numberProblem(text, lo, hi, false); }, "NUMBER");
}

CLI::Validator integer(double lo, double hi) {
    return CLI::Validator(
        [lo, hi](const std::string& text) { return numberProblem(text, lo, hi, true); }, "INT");
}

CLI::Validator outputFolder() {
    return CLI::Validator(
        [](const std::string& text) -> std::string {
            if (text.empty()) return "empty folder name (use . for the current folder)";
            return {};
        },
        "FOLDER");
}

CLI::Validator outputStem() {
    return CLI::Validator(
        [](const std::string& text) -> std::string {
            if (text.empty()) return "empty file name (the files would be hidden: .png, .exr)";
            if (text.find('/') != std::string::npos)
                return "'" + text +
                       "' contains '/'; a name stays inside --out (give folders there)";
            if (text.front() == '.')
                return "'" + text + "' starts with '.' (hidden files, or a path outside --out)";
            return {};
        },
        "NAME");
}

CLI::Validator outputFile() {
    return CLI::Validator(
        [](const std::string& text) -> std::string {
            if (text.empty()) return "empty file name";
            const std::string last = std::filesystem::path(text).filename().string();
            if (last.empty() || last == "." || last == "..")
                return "'" + text + "' names a folder, not a file";
            return {};
        },
        "FILE");
}

CLI::Option* addOutOption(CLI::App& cmd, std::string& out, const std::string& help) {
    return cmd.add_option("--out", out, help)->check(outputFolder())->capture_default_str();
}

CLI::Option* addNameOption(CLI::App& cmd, std::string& name, const std::string& help) {
    return cmd.add_option("--name", name, help)->check(outputStem())->capture_default_str();
}

namespace {

// The scene's light, else the default one (Renderer.h sceneLight: above the scene, off to one
// side, so that the shadow falls beside the model in the default view), placed by hand with
// --light-dir or --light-position (keeping its radius, colour and intensity); --light-radius
// applies to whichever it is.
void placeLight(Scene& scene, const SceneOptions& o) {
    Light l = sceneLight(scene);
    if (!o.lightDir.empty() || !o.lightPosition.empty()) {
        l.name = "--light-" + std::string(o.lightDir.empty() ? "position" : "dir");
        l.type = Light::Type::Point;
        const glm::vec3 centre = scene.bounds.center();
        const float r = std::max(scene.bounds.radius(), 1e-3f);
        if (!o.lightDir.empty()) {
            const glm::vec3 d(o.lightDir[0], o.lightDir[1], o.lightDir[2]);
            if (!(glm::length(d) > 0.0f))
                throw InputError("--light-dir: the zero vector has no direction");
            l.direction = glm::normalize(d);
            l.position = centre - l.direction * (2.5f * r);
        } else {
            l.position = {o.lightPosition[0], o.lightPosition[1], o.lightPosition[2]};
            if (glm::length(centre - l.position) <= 1e-6f * r)
                throw InputError(
                    "--light-position: at the scene's centre, it has no direction to the scene");
            l.direction = glm::normalize(centre - l.position);
        }
    }
    if (o.lightRadius) l.radius = *o.lightRadius;
    scene.light = l;
}

} // namespace

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
    Scene scene;
    try {
        scene = o.scene.empty() ? loadDefaultScene(lo) : loadGltf(o.scene, lo);
    } catch (const SceneError& e) {
        throw InputError(e.what());
    }
    // The ground first: the default light and the camera are placed from the bounds with it.
    if (applyGround(scene, parseGroundMode(o.ground).value_or(GroundMode::Auto)))
        std::cout
            << "ground: added under the scene ("
            << (o.ground == "on"
                    ? "--ground on"
                    : "it has no surface under it to receive a shadow; --ground off leaves it out")
            << ")\n";
    placeLight(scene, o);
    return scene;
}

gl::ShaderLibrary makeShaderLibrary(const SceneOptions& o) {
    try {
        return o.shaderDir.empty() ? gl::ShaderLibrary() : gl::ShaderLibrary(o.shaderDir);
    } catch (const std::runtime_error& e) {
        throw InputError(e.what());
    }
}

void checkMethodOptions(const RenderSettings& s, int width, int height) {
    const MethodDescriptor& m = methodOrThrow(s.method);
    try {
        if (m.check) m.check(s.options, m, s.shadow.size, width, height);
    } catch (const std::invalid_argument& e) {
        throw InputError(e.what());
    }
}

void applyAnimation(Renderer& renderer, const Scene& scene, const SceneOptions& o) {
    std::vector<int> chosen;
    try { // checked for every scene: a name the scene does not have is a usage error
        chosen = chooseAnimations(scene, o.animation);
    } catch (const std::invalid_argument& e) {
        throw UsageError(std::string("--") + e.what());
    }
    if (!isAnimated(scene)) return;
    renderer.setAnimations(std::move(chosen));
    renderer.setTime(o.time);
}

RenderSettings makeRenderSettings(const SceneOptions& o) {
    RenderSettings s;
    s.shadow.size = o.shadowMapSize;
    s.shadow.provider = parseProvider(o.shadowMap).value_or(ShadowMapProvider::Uniform);
    s.shadow.tsm = o.tsm;
    // A TSM stability step on the uniform map would do nothing: refused like a method option
    // the method does not take (the window, which can switch providers, lets it through).
    if (o.strictMethodOptions && s.shadow.provider != ShadowMapProvider::Tsm)
        for (const TsmOption& t : tsmOptions())
            if (o.tsm.*t.field != 0.0f)
                throw UsageError(std::string(t.flag) + ": only with --shadow-map tsm (the " +
                                 "shadow map is " + o.shadowMap + ")");
    const MethodDescriptor* method = findMethod(o.method);
    if (!method)
        throw UsageError("--method " + o.method + ": unknown method (valid: " + methodNames() +
                         ")");
    s.method = o.method;
    for (const auto& [flag, value] : o.methodOptions) {
        if (o.strictMethodOptions && !method->takesFlag(flag)) {
            const std::string takers =
                // flag is captured by name: clang 14 cannot capture a structured binding.
                methodNamesWhere([&f = flag](const MethodDescriptor& m) { return m.takesFlag(f); });
            throw UsageError(flag + ": method " + o.method + " does not take it (only " + takers +
                             " do)");
        }
        s.options.set(flag, value);
    }
    s.shadow.slopeBias = o.slopeBias;
    s.shadow.constantBias = o.constantBias;
    s.timing = o.timing == "query"    ? gl::TimingMode::Query
               : o.timing == "finish" ? gl::TimingMode::Finish
                                      : gl::TimingMode::Auto;
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

std::array<std::uint8_t, 3> regionColour(std::int64_t id) {
    std::uint32_t h = std::uint32_t(std::max<std::int64_t>(id, 0)) * 2654435761u;
    h ^= h >> 15;
    return {std::uint8_t(64 + (h & 0x7f)), std::uint8_t(64 + ((h >> 8) & 0x7f)),
            std::uint8_t(64 + ((h >> 16) & 0x7f))};
}

void printTimings(const Renderer& renderer, std::ostream& out) {
    out << std::fixed << std::setprecision(2);
    for (const gl::PassTime& p : renderer.timer().passes())
        out << "  " << p.name << ": " << p.ms << " ms\n";
    out << "  frame total: " << renderer.timer().frameMs() << " ms (" << renderer.timer().modeName()
        << ")\n";
    out << std::defaultfloat;
}

} // namespace fl::app
