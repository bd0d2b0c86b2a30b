#pragma once
// The subcommands. Each registers its options on a CLI11 subcommand and returns a runner.

#include <app/Common.h>

#include <functional>

namespace fl::app {

using Runner = std::function<int()>;

/// `floodlight render`: one headless frame to PNG + EXR.
Runner addRenderCommand(CLI::App& app);
/// `floodlight view`: the interactive window.
Runner addViewCommand(CLI::App& app);
/// `floodlight voronoi`: jump-flooded Voronoi diagrams and distance transforms with errors.
Runner addVoronoiCommand(CLI::App& app);
/// `floodlight voronoi3d`: 3D Voronoi diagrams by 3D or slice-by-slice jump flooding, CPU or GL,
/// with error voxels against the exact diagram.
Runner addVoronoi3dCommand(CLI::App& app);
/// `floodlight delaunay`: Delaunay triangulation of a point file by 1+JFA and exact repair.
Runner addDelaunayCommand(CLI::App& app);
/// `floodlight compare`: a soft-shadow method against its standard-flooding reference.
Runner addCompareCommand(CLI::App& app);
/// `floodlight capture`: a capture script with every method and the ground truth, CSV, JSON
/// summary and HTML report.
Runner addCaptureCommand(CLI::App& app);
/// `floodlight make-scene`: writes a generated scene as .glb.
Runner addMakeSceneCommand(CLI::App& app);

/// Renders the default scene headless into `outDir`, prints the paths; returns the exit code.
int renderHeadless(const SceneOptions& scene, int width, int height,
                   const std::filesystem::path& outDir, const std::string& stem);
/// The main job without a display: the scene with every method of the table and the ground
/// truth, one labelled picture DIR/STEM.png (name, RMSE against the ground truth, time / hard)
/// and each method's DIR/STEM.METHOD.png/.visibility.png/.exr; returns the exit code.
int renderOverview(SceneOptions scene, int width, int height, const std::filesystem::path& outDir,
                   const std::string& stem);
/// The window could not be opened (no display, no GL 4.5): callers may fall back to headless.
class NoWindow : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// Opens the window on a scene; `frames` > 0 closes it after that many frames, `screenshot`
/// saves the last frame shown (PNG) on close. Throws NoWindow if no window can be opened.
/// With `autoMethod`, opens on jfa-e where it renders interactively here, else on hard shadows.
int runViewer(const SceneOptions& scene, int width, int height, int frames,
              const std::string& screenshot, bool autoMethod = false);

} // namespace fl::app
