// The scene, shaders, render settings and camera that a rendering subcommand's options ask for.
#include <app/Common.h>

#include <scene/Ground.h>
#include <scene/SceneGenerator.h>

#include <algorithm>
#include <iomanip>
#include <iostream>

namespace fl::app {

namespace {

// The scene's light, else the default one (Renderer.h sceneLight: above the scene, off to one
// side, so that the shadow falls beside the model in the default view), placed by hand with
// --light-dir or --light-position (keeping its radius, colour and intensity); --light-radius
// applies to whichever it is.
void placeLight(Scene& scene, const SceneOptions& o, float modelRadius) {
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
    if (o.lightSize) l.radius = *o.lightSize * modelRadius;
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
    // --light-size is relative to the model itself, not to the ground added under it.
    const float modelRadius = scene.bounds.radius();
    // The ground first: the default light and the camera are placed from the bounds with it.
    const float lowest = scene.bounds.min.y;
    if (applyGround(scene, parseGroundMode(o.ground).value_or(GroundMode::Auto)))
        std::cout
            << "ground: added under the scene at y = " << scene.bounds.min.y
            << " (its lowest vertex: " << lowest << "; "
            << (o.ground == "on"
                    ? "--ground on"
                    : "it has no surface under it to receive a shadow; --ground off leaves it out")
            << ")\n";
    placeLight(scene, o, modelRadius);
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
void printTimings(const Renderer& renderer, std::ostream& out) {
    out << std::fixed << std::setprecision(2);
    for (const gl::PassTime& p : renderer.timer().passes())
        out << "  " << p.name << ": " << p.ms << " ms\n";
    out << "  frame total: " << renderer.timer().frameMs() << " ms (" << renderer.timer().modeName()
        << ")\n";
    out << std::defaultfloat;
}

} // namespace fl::app
