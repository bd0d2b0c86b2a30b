#include "Commands.h"

#include <renderer/Capture.h>
#include <renderer/EglContext.h>

#include <iostream>

namespace fl::app {

int renderHeadless(const SceneOptions& o, int width, int height,
                   const std::filesystem::path& outDir, const std::string& stem) {
    const Scene scene = loadScene(o);
    const CameraView camera = initialCamera(scene, o, width, height);
    auto context = EglContext::create();
    std::cout << "context: " << context->description() << "\n";
    const ShaderLibrary shaders = makeShaderLibrary(o);
    Renderer renderer(shaders, scene, makeRenderSettings(o));
    renderer.resize(width, height);
    renderer.render(camera);
    const CapturePaths paths = writeFrame(readFrame(renderer), outDir, stem);
    std::cout << "scene: " << scene.source << " (" << scene.triangleCount() << " triangles)\n"
              << "frame " << width << "x" << height << ", shadow map "
              << renderer.settings().shadow.size << "^2:\n";
    printTimings(renderer, std::cout);
    std::cout << "wrote " << paths.png.string() << "\n"
              << "wrote " << paths.visibilityPng.string() << "\n"
              << "wrote " << paths.exr.string() << "\n";
    return 0;
}

Runner addRenderCommand(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand("render", "Render one frame headless (EGL) to PNG and EXR");
    struct State {
        SceneOptions scene;
        std::string out = "captures";
        std::string name = "frame";
        int width = 512, height = 512;
    };
    auto s = std::make_shared<State>();
    addSceneOptions(*cmd, s->scene, true);
    addSizeOptions(*cmd, s->width, s->height);
    cmd->add_option("--out", s->out, "Output folder")->capture_default_str();
    cmd->add_option("--name", s->name, "File name stem: NAME.png and NAME.exr")
        ->capture_default_str();
    return [s] { return renderHeadless(s->scene, s->width, s->height, s->out, s->name); };
}

} // namespace fl::app
