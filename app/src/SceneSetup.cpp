// The scene, shaders, render settings and camera that a rendering subcommand's options ask for.
#include <app/Common.h>

#include <scene/CameraPath.h>
#include <scene/Ground.h>
#include <scene/Pose.h>

#include <base/Text.h>

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <sstream>

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
    // A disk wider than its distance to the scene wraps around it: no shadow a user means. The
    // range is the scene's own, so it is checked here, after loading (--light-size's 0..1 of
    // the model stays inside it: the light stands 2.5 scene radii away).
    const float reach = l.type == Light::Type::Directional
                            ? 2.5f * scene.bounds.radius()
                            : glm::length(scene.bounds.center() - l.position);
    if (!(l.radius <= reach))
        throw InputError(cat(o.lightRadius ? "--light-radius " : "the scene's light radius ",
                             l.radius, ": wider than the light's distance to the scene's centre (",
                             reach,
                             "); at most that, or use --light-size (a fraction of the "
                             "model's radius ",
                             modelRadius, ")"));
    scene.light = l;
}

} // namespace

Scene loadScene(const SceneOptions& o) {
    LoadOptions lo;
    // --light-radius and --light-size are applied once, by placeLight, for any scene.
    lo.warn = [](const std::string& w) { std::cerr << "warning: " << w << "\n"; };
    Scene scene;
    try {
        scene = o.scene.empty() ? loadDefaultScene(lo) : loadGltf(o.scene, lo);
    } catch (const SceneError& e) {
        throw InputError(e.what());
    }
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
    // --light-size is relative to the model itself, not to the ground added under it.
    placeLight(scene, o, scene.modelBounds.radius());
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
    // A file opens framed with its shadow, as model viewers open it; its own cameras
    // are --camera N. The built-in scene keeps its camera.
    if (o.camera == "default" && o.scene.empty()) return c;
    if (o.camera == "auto" || o.camera == "default") {
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
        CameraSpec spec = makeCameraSpec(o);
        // An animated or skinned model is framed as it stands at --time, not at rest.
        std::optional<Pose> pose;
        if (isAnimated(scene)) {
            std::vector<int> chosen;
            try {
                chosen = chooseAnimations(scene, o.animation);
            } catch (const std::invalid_argument& e) { // as applyAnimation says it
                throw UsageError(std::string("--") + e.what());
            }
            pose = evaluatePose(scene, chosen, o.time);
            spec.pose = &*pose;
        }
        return makeCameraView(scene, spec, static_cast<float>(width) / static_cast<float>(height));
    } catch (const std::invalid_argument& e) {
        throw InputError(e.what());
    }
}

std::variant<CameraView, CameraPath> namedCamera(const std::string& name, const Scene& scene,
                                                 const SceneOptions& o, int width, int height) {
    if (name == "default")
        return defaultWalkthrough(initialCamera(scene, o, width, height), scene.bounds);
    SceneOptions framed = o;
    framed.camera = "auto";
    const CameraView start = initialCamera(scene, framed, width, height);
    if (name == "auto") return start;
    if (name == "orbit") return orbitPath(start, scene.modelBounds);
    // Scripts are checked against kCameraPathNames when read; a new name needs its camera here.
    throw UsageError("camera path '" + name + "': no camera for it (kCameraPathNames)");
}

std::string setupLine(const Scene& scene, const RenderSettings& s, int width, int height,
                      const Renderer* rendered) {
    const Light l = sceneLight(scene);
    const float model = scene.modelBounds.valid() ? scene.modelBounds.radius() : 0.0f;
    std::ostringstream line;
    line << std::setprecision(4) << "light: " << (l.name.empty() ? "unnamed" : l.name)
         << ", centre (" << l.position.x << ", " << l.position.y << ", " << l.position.z
         << "), disk radius " << l.radius;
    if (model > 0.0f)
        line << " = " << std::setprecision(3) << l.radius / model
             << " of the model's radius (--light-size)";
    line << "; shadow map: " << s.shadow.size << "^2 " << providerName(s.shadow.provider);
    const MethodDescriptor& m = methodOrThrow(s.method);
    if (m.floods) {
        const FloodFrame* frame = rendered ? rendered->flood() : nullptr;
        const int asked = requestedPasses(m, s.options, s.shadow.size, width, height);
        line << "; flood: ";
        if (frame)
            line << frame->passes << " passes" << (asked == kAutoPasses ? " (auto chose)" : "");
        else if (asked == kAutoPasses)
            line << "auto passes (chosen per frame)";
        else
            line << asked << " passes";
    }
    return line.str();
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
