// floodlight: soft shadows and jump flooding. Subcommands: render, view, make-scene, voronoi,
// voronoi3d, delaunay, compare, capture; with no arguments, a window on the default scene when a
// display exists, else a headless render.

#include <app/Commands.h>

#include <gpu/Gl.h>
#include <renderer/context/EglContext.h>
#include <renderer/context/GlfwWindow.h>

#include <iostream>

int main(int argc, char** argv) {
    using namespace fl::app;
    CLI::App app{"Floodlight: real-time soft shadows and jump flooding (Rong 2007).\n"
                 "Without a subcommand: opens the default scene in a window when a display is\n"
                 "available, otherwise renders it headless into captures/.\n"
                 "Headless commands print the GL context they got on their first line;\n"
                 "FLOODLIGHT_EGL_DEVICE=N makes them use EGL device N (0, 1, ...) and no other."};
    app.set_help_all_flag("--help-all", "Help for every subcommand");
    const Runner render = addRenderCommand(app);
    const Runner view = addViewCommand(app);
    const Runner makeScene = addMakeSceneCommand(app);
    const Runner voronoi = addVoronoiCommand(app);
    const Runner voronoi3d = addVoronoi3dCommand(app);
    const Runner delaunay = addDelaunayCommand(app);
    const Runner compare = addCompareCommand(app);
    const Runner capture = addCaptureCommand(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        // A typo of a flag: name the nearest one the subcommand takes, not just the leftovers.
        if (dynamic_cast<const CLI::ExtrasError*>(&e))
            for (const CLI::App* sub : app.get_subcommands())
                if (const std::string hint = suggestFlags(*sub); !hint.empty()) {
                    std::cerr << hint << "Run with --help for the options of `" << sub->get_name()
                              << "`.\n";
                    return 2;
                }
        const int code = app.exit(e); // prints help or the message
        return code == 0 ? 0 : 2;
    }
    try {
        if (app.got_subcommand("render")) return render();
        if (app.got_subcommand("view")) return view();
        if (app.got_subcommand("make-scene")) return makeScene();
        if (app.got_subcommand("voronoi")) return voronoi();
        if (app.got_subcommand("voronoi3d")) return voronoi3d();
        if (app.got_subcommand("delaunay")) return delaunay();
        if (app.got_subcommand("compare")) return compare();
        if (app.got_subcommand("capture")) return capture();
        const SceneOptions defaults;
        if (fl::displayAvailable()) {
            try {
                return runViewer(defaults, 1024, 768, 0, "", true);
            } catch (const NoWindow& e) {
                std::cerr << "no window (" << e.what() << "); rendering headless instead\n";
            }
        }
        return renderOverview(defaults, 512, 512, "captures", "overview");
    } catch (const UsageError& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 2;
    } catch (const InputError& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 1;
    } catch (const fl::EglDeviceError& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 2;
    } catch (const fl::gl::GlError& e) {
        std::cerr << "GL error: " << e.what() << "\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "error: " << e.what() << "\n";
        return 1;
    }
}
