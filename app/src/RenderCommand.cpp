#include <app/Commands.h>
#include <renderer/io/TextureImage.h>

#include <base/OutputFiles.h>

#include <renderer/context/EglContext.h>
#include <renderer/metrics/ShadowStats.h>
#include <renderer/overlays/OverlayCapture.h>
#include <renderer/run/Capture.h>

#include <iomanip>
#include <iostream>
#include <unistd.h>

namespace fl::app {

namespace {

struct RenderRequest {
    SceneOptions scene;
    std::string out = "captures";
    std::string name = "frame";
    std::string aliasingMap; // --aliasing-map FILE.exr
    bool sideBySide = false; // --side-by-side: uniform and TSM, plus comparison pictures
    int width = 512, height = 512;
    std::string overlay;      // --overlay NAME: also write NAME.overlay-MODE.png
    OverlayControls controls; // --variant, --flood-pass, --delaunay-step
};

void printShadowStats(const ShadowMapStats& s, std::ostream& out) {
    out << std::setprecision(3) << "  texel footprint (screen pixels per shadow texel) over "
        << s.receivers << " receivers: median " << s.footprint.median << ", p95 " << s.footprint.p95
        << "\n"
        << "  near the viewer (nearest 25%, view depth <= " << s.nearDepth << "): median "
        << s.footprintNear.median << ", p95 " << s.footprintNear.p95 << "\n"
        << std::defaultfloat;
}

// "out.exr" with provider "tsm" -> "out.tsm.exr" (only when several providers are written).
std::filesystem::path withSuffix(const std::filesystem::path& p, std::string_view suffix) {
    std::filesystem::path q = p;
    q.replace_filename(p.stem().string() + "." + std::string(suffix) + p.extension().string());
    return q;
}

struct ProviderResult {
    FrameImages frame;
    FloatImage diagnostics;
    std::optional<OverlayCapture> overlay;
};

ProviderResult renderWith(const gl::ShaderLibrary& shaders, const Scene& scene,
                          const CameraView& camera, RenderSettings settings, int width, int height,
                          const RenderRequest& request) {
    settings.diagnostics = true;
    if (!request.overlay.empty())
        settings.wholeFlood = overlayReadsWholeFlood(*parseOverlay(request.overlay));
    // A slow frame (the ray tracer: seconds to minutes) shows how far it is, on a terminal.
    if (::isatty(STDOUT_FILENO)) {
        const std::string name = settings.method;
        settings.progress = [name](double done) {
            std::cout << "\r" << name << ": " << static_cast<int>(100.0 * done) << "%"
                      << (done >= 1.0 ? "\n" : "") << std::flush;
        };
    }
    Renderer renderer(shaders, scene, settings);
    applyAnimation(renderer, scene, request.scene);
    renderer.resize(width, height);
    renderer.render(camera);
    std::cout << "shadow map " << providerName(settings.shadow.provider) << " "
              << settings.shadow.size << "^2";
    if (const ShadowMapPass::Outputs* sm = renderer.shadow(); sm && sm->trapezoid)
        std::cout << " (trapezoid weight " << sm->trapezoid->weight
                  << (sm->trapezoid->degenerate ? ", blended towards a focused uniform map" : "")
                  << ")";
    std::cout << ", frame " << width << "x" << height << ":\n";
    std::cout << setupLine(scene, settings, width, height, &renderer) << "\n";
    printTimings(renderer, std::cout);
    ProviderResult result{readFrame(renderer), readTexture(*renderer.diagnostics(), 4), {}};
    if (!request.overlay.empty()) {
        OverlayRenderer overlays(shaders);
        OverlayControls controls = request.controls;
        result.overlay = captureOverlay(overlays, *parseOverlay(request.overlay), renderer, camera,
                                        controls, width, height);
        for (const std::string& line : result.overlay->hud) std::cout << "  " << line << "\n";
    }
    return result;
}

// Every file the request writes, checked before any work (an existing file as --out
// failed only after the whole frame, and a folder as --aliasing-map after the frame's files
// had appeared).
void checkOutputs(const RenderRequest& r, const std::vector<ShadowMapProvider>& providers) {
    try {
        checkOutputFolder(r.out, "--out");
        for (ShadowMapProvider p : providers) {
            const std::string stem =
                r.sideBySide ? r.name + "." + std::string(providerName(p)) : r.name;
            const CapturePaths paths = capturePaths(r.out, stem);
            for (const std::filesystem::path& f : {paths.png, paths.visibilityPng, paths.exr})
                checkOutputFile(f, "--name");
            if (!r.aliasingMap.empty())
                checkOutputFile(r.sideBySide ? withSuffix(r.aliasingMap, providerName(p))
                                             : std::filesystem::path(r.aliasingMap),
                                "--aliasing-map");
        }
    } catch (const OutputFileError& e) {
        throw InputError(e.what());
    }
}

int renderHeadless(const RenderRequest& r) {
    {
        const ShadowMapProvider p =
            parseProvider(r.scene.shadowMap).value_or(ShadowMapProvider::Uniform);
        checkOutputs(r, r.sideBySide
                            ? std::vector{ShadowMapProvider::Uniform, ShadowMapProvider::Tsm}
                            : std::vector{p});
    }
    const Scene scene = loadScene(r.scene);
    const CameraView camera = initialCamera(scene, r.scene, r.width, r.height);
    auto context = EglContext::create();
    std::cout << "context: " << context->description() << "\n"
              << "scene: " << scene.source << " (" << scene.triangleCount() << " triangles)\n";
    const gl::ShaderLibrary shaders = makeShaderLibrary(r.scene);
    const RenderSettings base = makeRenderSettings(r.scene);
    checkMethodOptions(base, r.width, r.height);
    std::vector<ShadowMapProvider> providers{base.shadow.provider};
    if (r.sideBySide) providers = {ShadowMapProvider::Uniform, ShadowMapProvider::Tsm};

    std::vector<ProviderResult> results;
    for (ShadowMapProvider p : providers) {
        RenderSettings settings = base;
        settings.shadow.provider = p;
        results.push_back(renderWith(shaders, scene, camera, settings, r.width, r.height, r));
        printShadowStats(summarizeShadowDiagnostics(results.back().diagnostics), std::cout);
    }
    // The outputs appear together or not at all (base/OutputFiles.h): an unwritable
    // --aliasing-map used to leave the PNG and EXR written before it.
    OutputSet outputs;
    std::vector<std::filesystem::path> written;
    for (std::size_t i = 0; i < results.size(); ++i) {
        const std::string stem =
            r.sideBySide ? r.name + "." + std::string(providerName(providers[i])) : r.name;
        const CapturePaths paths = writeFrame(results[i].frame, r.out, stem);
        written.insert(written.end(), {paths.png, paths.visibilityPng, paths.exr});
        if (results[i].overlay) {
            const std::filesystem::path o =
                std::filesystem::path(r.out) / (stem + ".overlay-" + r.overlay + ".png");
            writePng(o, results[i].overlay->image);
            written.push_back(o);
        }
        if (!r.aliasingMap.empty()) {
            const std::filesystem::path a =
                r.sideBySide ? withSuffix(r.aliasingMap, providerName(providers[i]))
                             : std::filesystem::path(r.aliasingMap);
            writeAliasingMap(a, results[i].diagnostics);
            written.push_back(a);
        }
    }
    if (r.sideBySide) {
        const std::filesystem::path dir(r.out);
        const std::string stem = r.name + ".uniform-vs-tsm";
        auto pair = [&](auto&& picture) {
            return sideBySide({picture(results[0]), picture(results[1])});
        };
        writePng(dir / (stem + ".png"),
                 pair([](const ProviderResult& x) { return toSrgb8(x.frame.color); }));
        writePng(dir / (stem + ".visibility.png"), pair([](const ProviderResult& x) {
                     return visibilityToGrey(x.frame.visibility);
                 }));
        writePng(dir / (stem + ".footprint.png"),
                 pair([](const ProviderResult& x) { return footprintHeatMap(x.diagnostics); }));
        for (const char* suffix : {".png", ".visibility.png", ".footprint.png"})
            written.push_back(dir / (stem + suffix));
    }
    outputs.commit();
    for (const std::filesystem::path& p : written) std::cout << "wrote " << p.string() << "\n";
    return 0;
}

} // namespace

int renderHeadless(const SceneOptions& o, int width, int height,
                   const std::filesystem::path& outDir, const std::string& stem) {
    RenderRequest r;
    r.scene = o;
    r.width = width;
    r.height = height;
    r.out = outDir.string();
    r.name = stem;
    return renderHeadless(r);
}

Runner addRenderCommand(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand("render", "Render one frame headless (EGL) to PNG and EXR");
    auto s = std::make_shared<RenderRequest>();
    addSceneOptions(*cmd, s->scene, true);
    addSizeOptions(*cmd, s->width, s->height);
    addOutOption(*cmd, s->out, "Output folder");
    addNameOption(*cmd, s->name, "File name stem: NAME.png and NAME.exr");
    cmd->add_option("--aliasing-map", s->aliasingMap,
                    "Also write the shadow-map texel footprint (screen pixels per texel), view "
                    "depth and visibility per pixel to this EXR file (its folder is created if "
                    "missing; with --side-by-side, FILE.uniform.exr and FILE.tsm.exr)")
        ->check(outputFile());
    cmd->add_flag("--side-by-side", s->sideBySide,
                  "Render with the uniform and the TSM provider and write NAME.uniform-vs-tsm.png "
                  "(colour), .visibility.png and .footprint.png (heat map) side by side")
        // Both providers are rendered: a --shadow-map choice would be ignored (exit 2).
        ->excludes(cmd->get_option("--shadow-map"));
    std::string overlayNames;
    for (OverlayMode m : allOverlayModes())
        if (m != OverlayMode::None)
            overlayNames += (overlayNames.empty() ? "" : ", ") + std::string(overlayName(m));
    cmd->add_option("--overlay", s->overlay,
                    "Also write NAME.overlay-MODE.png: the frame's overlay picture, one of " +
                        overlayNames)
        ->check([](const std::string& v) {
            const std::optional<OverlayMode> m = parseOverlay(v);
            return m && *m != OverlayMode::None ? std::string() : "unknown overlay '" + v + "'";
        });
    cmd->add_option(
           "--variant", s->controls.variant,
           "Overlay: JFA variant index (0 JFA, 1 JFA+1, 2 JFA+2, 3 JFA^2, 4 1+JFA, 5 half)")
        ->check(integer(0, 5));
    cmd->add_option("--flood-pass", s->controls.floodPass,
                    "Overlay flood-passes: show the state after this many passes (-1 = all)")
        ->check(integer(-1, 1 << 20));
    cmd->add_option("--delaunay-step", s->controls.delaunayStep,
                    "Overlay delaunay: stage index 0-8 (sites .. flipped)")
        ->check(integer(0, 8));
    return [s] { return renderHeadless(*s); };
}

} // namespace fl::app
