#include <app/Commands.h>

#include <scene/SceneGenerator.h>

#include <chrono>
#include <iostream>

namespace fl::app {

Runner addMakeSceneCommand(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand(
        "make-scene", "Generate the deterministic test scene (thesis sizes or any count) as .glb");
    struct State {
        std::size_t triangles = kDefaultSceneTriangles;
        std::string size;
        std::uint32_t seed = kDefaultSceneSeed;
        std::string out;
    };
    auto s = std::make_shared<State>();
    std::string sizes;
    for (const NamedSize& n : thesisSceneSizes())
        sizes += std::string(sizes.empty() ? "" : ", ") + n.name + " (" +
                 std::to_string(n.triangles) + ")";
    cmd->add_option("--triangles", s->triangles, "Exact triangle count (at least 600)")
        ->check(integer(kMinTriangles, 50'000'000))
        ->capture_default_str();
    cmd->add_option("--size", s->size, "A thesis scene size by name: " + sizes);
    cmd->add_option("--seed", s->seed, "Random seed")->capture_default_str();
    cmd->add_option("--out", s->out, "Output .glb file")->required()->check(outputFile());
    return [s] {
        std::size_t triangles = s->triangles;
        if (!s->size.empty()) {
            bool found = false;
            for (const NamedSize& n : thesisSceneSizes())
                if (s->size == n.name) {
                    triangles = n.triangles;
                    found = true;
                }
            if (!found) throw InputError("--size " + s->size + ": not a thesis scene size");
        }
        const auto t0 = std::chrono::steady_clock::now();
        const Scene scene = generateScene({triangles, s->seed});
        writeGlb(scene, s->out);
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count();
        std::cout << "wrote " << s->out << ": " << scene.triangleCount() << " triangles, "
                  << scene.instances.size() << " objects, seed " << s->seed << " (" << ms
                  << " ms)\n";
        return 0;
    };
}

} // namespace fl::app
