// The ray-traced ground truth's own costs (raytrace/ShadowRays.h): Embree BVH build and refit
// times for a scene, and shadow rays per second over the receivers of the default view (the
// surfaces of a real frame), at each N asked. Min and median over --repeats runs in one process.

#include <raytrace/ShadowRays.h>
#include <renderer/Renderer.h>
#include <renderer/context/EglContext.h>
#include <renderer/soft/ShadowRayInputs.h>
#include <scene/GltfLoader.h>
#include <scene/SceneGenerator.h>

#include <base/Parallel.h>
#include <base/Stats.h>

#include <BenchSupport.h>
#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <iostream>

namespace {

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"raytrace_bench: Embree build/refit times and shadow rays per second"};
    std::string scenePath;
    std::size_t triangles = 0;
    int size = 512, repeats = 3;
    float radius = 1.5f;
    std::vector<int> samples{64, 256};
    app.add_option("--scene", scenePath, "glTF scene (default: assets/default.glb)");
    app.add_option("--triangles", triangles,
                   "Generate the default-style scene with this many triangles instead");
    app.add_option("--size", size, "Frame width and height")->capture_default_str();
    app.add_option("--light-radius", radius)->capture_default_str();
    app.add_option("--samples", samples, "Rays per pixel to time (each)")->capture_default_str();
    app.add_option("--repeats", repeats)->check(CLI::Range(1, 1000))->capture_default_str();
    return fl::bench::parseAndRun(app, argc, argv, [&] {
        fl::Scene scene =
            triangles
                ? fl::generateScene({triangles, 1})
                : fl::loadGltf(scenePath.empty()
                                   ? std::string(FLOODLIGHT_SOURCE_DIR) + "/assets/default.glb"
                                   : scenePath);
        if (scene.light) scene.light->radius = radius;
        const fl::rt::Triangles world = fl::worldTriangles(scene); // as the method gathers them
        std::vector<double> buildMs, refitMs;
        for (int r = 0; r < repeats; ++r) {
            const auto t = Clock::now();
            fl::rt::RayScene s(world);
            buildMs.push_back(msSince(t));
            const auto t2 = Clock::now();
            s.refit(world.vertices);
            refitMs.push_back(msSince(t2));
        }
        const fl::rt::RayScene rays(world);

        // Receivers: the surfaces of the default view (one hard-shadow frame).
        auto ctx = fl::EglContext::create(false);
        const fl::gl::ShaderLibrary shaders;
        fl::RenderSettings settings;
        fl::Renderer renderer(shaders, scene, settings);
        renderer.resize(size, size);
        renderer.render(fl::makeCameraView(scene, {}, 1.0f));
        const std::vector<fl::rt::Receiver> receivers = fl::surfaceReceivers(renderer.surfaces());
        const fl::DiskLight& d = renderer.disk();
        const fl::rt::Disk disk{d.center, d.normal, d.radius};

        std::printf("scene: %s, %zu triangles; %d cores\n", scene.source.c_str(),
                    rays.triangleCount(), fl::resolveThreads(0));
        std::printf("BVH build: min %.1f ms, median %.1f ms; refit: min %.1f ms, median %.1f ms\n",
                    fl::minimum(buildMs), fl::median(buildMs), fl::minimum(refitMs),
                    fl::median(refitMs));
        for (int n : samples) {
            fl::rt::VisibilitySettings vs;
            vs.samples = n;
            std::vector<double> ms, rate;
            std::uint64_t cast = 0;
            for (int r = 0; r < repeats; ++r) {
                const auto t = Clock::now();
                (void)fl::rt::diskVisibility(rays, disk, receivers, vs, &cast);
                ms.push_back(msSince(t));
                rate.push_back(static_cast<double>(cast) / (ms.back() / 1000.0) / 1e6);
            }
            std::printf("N = %d at %dx%d: %llu rays; frame min %.0f ms, median %.0f ms; "
                        "%.2f / %.2f Mrays/s (max / median)\n",
                        n, size, size, static_cast<unsigned long long>(cast), fl::minimum(ms),
                        fl::median(ms), *std::max_element(rate.begin(), rate.end()),
                        fl::median(rate));
        }
        return 0;
    });
}
