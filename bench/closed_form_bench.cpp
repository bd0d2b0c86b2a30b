// Every method of the table on the closed-form cases (scene/ClosedForm.h): straight
// occluder edges at several angles and heights and a disk occluder, each under a disk light
// straight above. Per case and method: RMSE against the exact visibility over the ground pixels
// in view, RMSE and mean signed error (bias) over the exact penumbra. No estimate stands between
// a method and the answer here, not even a ground truth.

#include <io/ImageIO.h>
#include <renderer/Renderer.h>
#include <renderer/context/EglContext.h>
#include <renderer/run/Capture.h>
#include <renderer/run/ClosedFormRender.h>
#include <scene/ClosedForm.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>

int main(int argc, char** argv) {
    CLI::App app{"closed_form_bench: every method against closed-form soft shadows"};
    int size = 256, shadowMap = 1024;
    std::string only;
    app.add_option("--size", size, "Frame width and height")->capture_default_str();
    app.add_option("--shadow-map-size", shadowMap)->capture_default_str();
    app.add_option("--method", only, "Only this method (default: every method of the table)");
    std::string saveDir;
    app.add_option("--save", saveDir,
                   "Write each frame's visibility and the closed form here (caseK.METHOD.png, "
                   "caseK.exact.png; grey)");
    std::vector<std::string> sets;
    app.add_option("--set", sets,
                   "A method option for every method that takes it, as FLAG=VALUE (repeatable; "
                   "e.g. --set --occluder-points=centre)");
    CLI11_PARSE(app, argc, argv);
    fl::MethodOptions options;
    for (const std::string& kv : sets) {
        const std::size_t eq = kv.find('=');
        if (eq == std::string::npos || kv.rfind("--", 0) != 0) {
            std::cerr << "error: --set " << kv << ": expected --FLAG=VALUE\n";
            return 2;
        }
        const std::string flag = kv.substr(0, eq);
        const auto known = fl::allMethodOptions();
        if (std::none_of(known.begin(), known.end(),
                         [&](const fl::MethodOption* o) { return o->flag == flag; })) {
            std::cerr << "error: --set " << kv << ": no method takes " << flag << "\n";
            return 2;
        }
        options.set(flag, kv.substr(eq + 1));
    }
    try {
        auto ctx = fl::EglContext::create(false);
        const fl::gl::ShaderLibrary shaders;
        const std::vector<fl::ClosedFormCase> cases = fl::closedFormCases();
        std::printf("%dx%d frames, %d^2 uniform map, every method at its defaults\n", size, size,
                    shadowMap);
        int k = 0;
        for (const fl::ClosedFormCase& c : cases) {
            const std::string stem = saveDir + "/case" + std::to_string(k++);
            std::printf("\n%s\n%-10s %8s %8s %10s %10s %8s\n", c.name.c_str(), "method", "ground",
                        "RMSE", "penumbra", "bias pen.", "max|d|");
            for (const fl::MethodDescriptor& m : fl::methodTable()) {
                if (!only.empty() && m.name != only) continue;
                fl::RenderSettings s;
                s.shadow.size = shadowMap;
                s.method = std::string(m.name);
                for (const fl::MethodOption* o : m.options)
                    if (options.has(o->flag)) s.options.set(o->flag, options.text(*o)); // checked
                const fl::ClosedFormFrame f = fl::renderClosedForm(shaders, c, s, size);
                const fl::FloatImage& visibility = f.visibility;
                const fl::ClosedFormError& e = f.error;
                if (!saveDir.empty()) {
                    std::filesystem::create_directories(saveDir);
                    fl::writePng(stem + "." + std::string(m.name) + ".png",
                                 fl::visibilityToGrey(visibility));
                    fl::writePng(stem + ".exact.png", fl::visibilityToGrey(e.exact));
                }
                std::printf("%-10s %8zu %8.4f %10.4f %+10.4f %8.3f\n", std::string(m.name).c_str(),
                            e.ground, e.rmse, e.rmsePenumbra, e.biasPenumbra, e.maxAbs);
                std::fflush(stdout);
            }
        }
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
