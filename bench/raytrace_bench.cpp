// The ray-traced ground truth's own costs (raytrace/ShadowRays.h): Embree BVH build and refit
// times for a scene, and shadow rays per second over the receivers of the default view (the
// surfaces of a real frame), at each N asked, as the `raytrace` method casts them (seen from the
// view's eye; --terminator-offset on by default, as the method's), with the share of rays the
// terminator offset moved. Min and median over --repeats runs in one process.

#include <raytrace/ShadowRays.h>
#include <renderer/Renderer.h>
#include <renderer/context/EglContext.h>
#include <renderer/soft/ShadowRayInputs.h>
#include <scene/Camera.h>
#include <scene/GltfLoader.h>
#include <scene/Ground.h>
#include <scene/SceneGenerator.h>

#include <base/Parallel.h>
#include <base/Stats.h>

#include <BenchSupport.h>
#include <CLI/CLI.hpp>
#include <glm/geometric.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace {

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

struct Options {
    std::string scenePath;
    std::size_t triangles = 0;
    int size = 512, repeats = 3;
    float radius = 1.5f, fraction = 0.0f;
    std::vector<int> samples{64, 256};
    std::string offset = "on", ground = "auto";
    bool check = false;
};

fl::Scene loadScene(const Options& o) {
    fl::Scene scene =
        o.triangles ? fl::generateScene({o.triangles, 1})
                    : fl::loadGltf(o.scenePath.empty()
                                       ? std::string(FLOODLIGHT_SOURCE_DIR) + "/assets/default.glb"
                                       : o.scenePath);
    fl::applyGround(scene, fl::parseGroundMode(o.ground).value_or(fl::GroundMode::Auto));
    if (o.fraction > 0.0f) {
        fl::Light light = fl::sceneLight(scene);
        light.radius = o.fraction * scene.bounds.radius();
        scene.light = light;
    } else if (scene.light) {
        scene.light->radius = o.radius;
    }
    return scene;
}

void timeBuild(const fl::rt::Triangles& world, int repeats) {
    std::vector<double> buildMs, refitMs;
    for (int r = 0; r < repeats; ++r) {
        const auto t = Clock::now();
        fl::rt::RayScene s(world);
        buildMs.push_back(msSince(t));
        const auto t2 = Clock::now();
        s.refit(world.vertices);
        refitMs.push_back(msSince(t2));
    }
    std::printf("BVH build: min %.1f ms, median %.1f ms; refit: min %.1f ms, median %.1f ms\n",
                fl::minimum(buildMs), fl::median(buildMs), fl::minimum(refitMs),
                fl::median(refitMs));
}

/// The receivers of one view, what the `raytrace` method is handed.
struct Frame {
    std::vector<fl::rt::Receiver> receivers;
    fl::rt::Disk disk;
    glm::vec3 eye{0.0f};
};

void timeRays(const fl::rt::RayScene& rays, const Frame& f, const Options& o, int n) {
    fl::rt::VisibilitySettings vs;
    vs.samples = n;
    vs.terminatorOffset = o.offset == "on";
    vs.eye = f.eye;
    std::vector<double> ms, rate;
    fl::rt::RayCounts counts;
    for (int r = 0; r < o.repeats; ++r) {
        const auto t = Clock::now();
        (void)fl::rt::diskVisibility(rays, f.disk, f.receivers, vs, &counts);
        ms.push_back(msSince(t));
        rate.push_back(static_cast<double>(counts.cast) / (ms.back() / 1000.0) / 1e6);
    }
    std::printf("N = %d at %dx%d: %llu rays; frame min %.0f ms, median %.0f ms; "
                "%.2f / %.2f Mrays/s (max / median)\n",
                n, o.size, o.size, static_cast<unsigned long long>(counts.cast), fl::minimum(ms),
                fl::median(ms), *std::max_element(rate.begin(), rate.end()), fl::median(rate));
    std::printf("  terminator offset %s: %llu rays offset (%.2f%% of those cast); %llu "
                "receivers on no triangle\n",
                o.offset.c_str(), static_cast<unsigned long long>(counts.offset),
                100.0 * static_cast<double>(counts.offset) /
                    static_cast<double>(std::max<std::uint64_t>(counts.cast, 1)),
                static_cast<unsigned long long>(counts.unplaced));
}

/// --check: each pixel at epsilon 1e-5 against 1e-7 x the diagonal (offset on and off), and
/// the offset on against off (RMSE over the surface pixels), at N rays.
void check(const fl::rt::RayScene& rays, const Frame& f, int n) {
    std::vector<float> v[2][2];
    for (int on = 0; on < 2; ++on)
        for (int e = 0; e < 2; ++e) {
            fl::rt::VisibilitySettings vs;
            vs.samples = n;
            vs.terminatorOffset = on == 1;
            vs.eye = f.eye;
            vs.epsilon = e == 0 ? 1e-5f : 1e-7f;
            v[on][e] = fl::rt::diskVisibility(rays, f.disk, f.receivers, vs);
        }
    for (int on = 0; on < 2; ++on) {
        float worst = 0.0f;
        std::size_t over = 0;
        for (std::size_t i = 0; i < f.receivers.size(); ++i) {
            const float d = std::abs(v[on][0][i] - v[on][1][i]);
            worst = std::max(worst, d);
            over += d > 0.001f;
        }
        std::printf("check, offset %s: epsilon 1e-5 vs 1e-7 x the diagonal: %zu pixels differ by "
                    "more than 0.001, at most %.4f\n",
                    on ? "on" : "off", over, worst);
    }
    // All surface pixels, and those whose triangle faces the disk's centre by 0.2 or more (off
    // the terminator, where the offset should change nothing).
    double sum[2] = {0.0, 0.0};
    std::size_t count[2] = {0, 0};
    for (std::size_t i = 0; i < f.receivers.size(); ++i) {
        const fl::rt::Receiver& r = f.receivers[i];
        if (!r.valid) continue;
        const double d = v[1][0][i] - v[0][0][i];
        const bool facing =
            glm::length(r.normal) > 0.0f &&
            glm::dot(glm::normalize(r.normal), glm::normalize(f.disk.center - r.position)) >= 0.2f;
        for (int k = 0; k < (facing ? 2 : 1); ++k) {
            sum[k] += d * d;
            ++count[k];
        }
    }
    const auto rmse = [&](int k) {
        return std::sqrt(sum[k] / static_cast<double>(std::max<std::size_t>(count[k], 1)));
    };
    std::printf("check: offset on vs off, RMSE %.4f over %zu surface pixels, %.4f over the %zu "
                "facing the light (Ng.L >= 0.2 to the disk's centre)\n",
                rmse(0), count[0], rmse(1), count[1]);
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"raytrace_bench: Embree build/refit times and shadow rays per second"};
    Options o;
    app.add_option("--scene", o.scenePath, "glTF scene (default: assets/default.glb)");
    app.add_option("--triangles", o.triangles,
                   "Generate the default-style scene with this many triangles instead");
    app.add_option("--size", o.size, "Frame width and height")->capture_default_str();
    app.add_option("--light-radius", o.radius, "The scene's own light's radius")
        ->capture_default_str();
    app.add_option("--light-fraction", o.fraction,
                   "Instead: the light (the scene's or the default) of this radius x the scene's "
                   "bounding radius (0: off)")
        ->capture_default_str();
    app.add_option("--samples", o.samples, "Rays per pixel to time (each)")->capture_default_str();
    app.add_option("--repeats", o.repeats)->check(CLI::Range(1, 1000))->capture_default_str();
    app.add_option("--terminator-offset", o.offset, "The truth's terminator offset")
        ->check(CLI::IsMember({"on", "off"}))
        ->capture_default_str();
    app.add_option("--ground", o.ground, "A ground under a model on nothing, as `render` adds it")
        ->check(CLI::IsMember({"auto", "on", "off"}))
        ->capture_default_str();
    app.add_flag("--check", o.check,
                 "Also: each pixel at ray epsilon 1e-5 vs 1e-7 x the diagonal, and the offset on "
                 "vs off (at the last --samples)");
    return fl::bench::parseAndRun(app, argc, argv, [&] {
        const fl::Scene scene = loadScene(o);
        const fl::rt::Triangles world = fl::worldTriangles(scene); // as the method gathers them
        std::printf("scene: %s, %zu triangles; %d cores\n", scene.source.c_str(),
                    world.indices.size() / 3, fl::resolveThreads(0));
        timeBuild(world, o.repeats);
        const fl::rt::RayScene rays(world);

        // Receivers: the surfaces of the default view (one hard-shadow frame).
        auto ctx = fl::EglContext::create(false);
        const fl::gl::ShaderLibrary shaders;
        fl::RenderSettings settings;
        fl::Renderer renderer(shaders, scene, settings);
        renderer.resize(o.size, o.size);
        const fl::CameraView view = fl::makeCameraView(scene, {}, 1.0f);
        renderer.render(view);
        const fl::DiskLight& d = renderer.disk();
        const Frame frame{
            fl::surfaceReceivers(renderer.surfaces()), {d.center, d.normal, d.radius}, view.eye};
        for (int n : o.samples) timeRays(rays, frame, o, n);
        if (o.check && !o.samples.empty()) check(rays, frame, o.samples.back());
        return 0;
    });
}
