#pragma once
// Parts of `floodlight delaunay` shared between its command and its step pictures: the default
// texture size and the step pictures of --steps.

#include <geometry/Delaunay.h>

#include <cstddef>
#include <filesystem>
#include <ostream>
#include <vector>

namespace fl::app {

/// Above this many points the SVG pictures (--steps, and --format all's SVG) are skipped: every
/// point and edge is an SVG element, and beyond ~20k a browser shows a grey blob, slowly.
inline constexpr std::size_t kMaxPicturePoints = 20000;

/// The default texture side N depends on the backend:
///
/// - GL: the smallest power of two with N^2 >= kTexelsPerSiteGl * points, clamped to
///   [kMinAutoTexture, kMaxAutoTexture]. 7 texels per site is the thesis' crossover: a larger
///   texture makes T' closer to the Delaunay triangulation (fewer missing sites for C3, fewer
///   flips for C4) while the GPU steps stay nearly constant in time; §6.5 (Figs. 6.13, 6.16)
///   finds the best size growing with the site count and switches from 2048^2 to 4096^2 at
///   ~600k sites, i.e. at ~7 texels per site on the smaller texture.
/// - CPU: geom::kCpuDefaultTexture: the G-steps cost ~N^2 on the CPU and a site
///   that keeps its pixel saves C3 less than it costs the other steps, so the smallest side
///   wins for uniform and clustered points alike.
///
/// 256 keeps tiny inputs from snapping onto a handful of pixels; 8192 is the largest texture the
/// pipeline takes (geom::kMaxDiscreteSize).
inline constexpr double kTexelsPerSiteGl = 7.0;
inline constexpr int kMinAutoTexture = 256;
inline constexpr int kMaxAutoTexture = 8192;

/// The texture side `floodlight delaunay` uses for `points` without --texture.
int defaultTextureSize(std::size_t points, bool glBackend);

/// Writes 01_sites.svg ... 09_flipped.svg into `dir` (created if needed) from a result computed
/// with keepStages; prints one line per file to `log`.
void writeStepPictures(const std::filesystem::path& dir, const std::vector<glm::dvec2>& points,
                       const geom::DelaunayResult& result, std::ostream& log);

} // namespace fl::app
