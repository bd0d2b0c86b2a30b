#pragma once
// Visibility of a disk light by casting shadow rays (Intel Embree 3): the ground truth that uses
// no shadow map, so it shares none of the errors of the techniques it judges (depth bias, texel
// aliasing, the map's resolution). Per receiver point, N rays go to stratified points of the
// disk; its visibility is the share of them that nothing blocks. Pure CPU, all cores.
//
// Ray offsets: a ray leaves the receiver `epsilon()` along the receiver's geometric normal
// (on the side it is seen from) and stops `epsilon()` short of the disk, with epsilon() = 1e-5 of
// the scene's bounding-box diagonal. That is far above float rounding at the scene's scale and
// far below any feature a shadow map resolves (a 4096^2 map's texel is 1/4096 of the scene).
// With VisibilitySettings::terminatorOffset the ray first moves from the flat triangle onto the
// smooth surface its vertex normals describe (raytrace/Terminator.h), then by epsilon().

#include <base/Numbers.h>
#include <raytrace/Terminator.h>

#include <glm/vec3.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace fl::rt {

/// A disk light: centre, normal (the side it lights; any length > 0), radius (>= 0).
struct Disk {
    glm::vec3 center{0.0f};
    glm::vec3 normal{0.0f, -1.0f, 0.0f};
    float radius = 0.0f;
};

/// World-space triangles: three indices per triangle into `vertices`.
struct Triangles {
    std::vector<glm::vec3> vertices;
    std::vector<std::uint32_t> indices;
    /// Alpha cut-outs (leaves, fences): empty, or one flag per triangle. For a flagged triangle
    /// a ray asks `transmits(triangle, u, v)` whether it passes the point (1-u-v) a + u b + v c
    /// it hits; unflagged triangles block everywhere. Called from many threads at once.
    std::vector<std::uint8_t> cutOut;
    std::function<bool(std::uint32_t triangle, float u, float v)> transmits;
    /// Empty, or one normal per vertex: the smooth surface the shading interpolates, which the
    /// terminator offset moves a ray's start onto (raytrace/Terminator.h; a triangle with a
    /// normal that is not of unit length has none).
    std::vector<glm::vec3> normals;
};

/// Largest |coordinate| a vertex may have (fl::kMaxWorldCoordinate): Embree works in float, and
/// the BVH's bounds and the ray offsets lose all precision far beyond the scene's own scale.
inline constexpr float kMaxCoordinate = static_cast<float>(kMaxWorldCoordinate);

/// The scene's triangles in an Embree BVH. Move-only.
class RayScene {
  public:
    /// Builds the BVH. Throws std::invalid_argument naming the vertex or triangle for a
    /// non-finite or too large coordinate or an index out of range, or for cut-out flags that are
    /// not one per triangle or come without `transmits`; std::runtime_error for an Embree failure.
    /// Degenerate triangles (zero area) block nothing and are kept.
    explicit RayScene(const Triangles& triangles);
    ~RayScene();
    RayScene(RayScene&&) noexcept;
    RayScene& operator=(RayScene&&) noexcept;
    RayScene(const RayScene&) = delete;
    RayScene& operator=(const RayScene&) = delete;

    /// Moves the vertices (an animated frame: same triangles, new positions) and updates the
    /// BVH (Embree rebuilds it; a refit was measured no faster); the same checks as the
    /// constructor. `normals`: the vertices' new normals, or empty (the scene then has none).
    void refit(std::span<const glm::vec3> vertices, std::span<const glm::vec3> normals = {});
    /// True when a triangle crosses the segment from `from` to `to` (both ends excluded).
    [[nodiscard]] bool occluded(glm::vec3 from, glm::vec3 to) const;
    /// The smooth surface (terminatorOffset) under `point`, a point of the surface the eye at
    /// `eye` sees, on the side `side`: the triangle is the first the ray from `eye` meets within
    /// 1e-3 of the distance (or 16 epsilon()) of `point`. nullopt when the scene has no normals,
    /// no triangle lies there or the triangle is flat.
    [[nodiscard]] std::optional<SmoothPoint> smoothSurface(glm::vec3 eye, glm::vec3 point,
                                                           glm::vec3 side) const;
    /// The ray offset (see the header comment).
    [[nodiscard]] float epsilon() const { return epsilon_; }
    [[nodiscard]] std::size_t triangleCount() const { return triangleCount_; }
    /// Wall time of the last build or refit, ms.
    [[nodiscard]] double lastBuildMs() const { return buildMs_; }

  private:
    struct Embree;
    std::unique_ptr<Embree> e_;
    float epsilon_ = 0.0f;
    std::size_t triangleCount_ = 0;
    double buildMs_ = 0.0;
};

/// A point whose visibility is wanted, on a surface whose geometric normal is `normal`, pointing
/// to the side the point is seen from (the eye's side; zero when unknown). Light from behind that
/// plane cannot reach the seen side. `valid` false: not a surface (background), visibility 1.
struct Receiver {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f};
    bool valid = true;
};

/// Limits of N, the rays per receiver.
inline constexpr int kMinSamples = 1;
inline constexpr int kMaxSamples = 16384;

struct VisibilitySettings {
    int samples = 256; // N rays per receiver, in [kMinSamples, kMaxSamples]
    /// true: one random point in each stratum, drawn per receiver (noise, unbiased; what the
    /// ground truth uses). false: the strata's centres for every receiver, as the shadow-map
    /// reference places its point lights (its bands along straight edges are this pattern's).
    bool jitter = true;
    int threads = 0; // 0: every core
    /// true: each ray starts on the smooth surface of its receiver's triangle (Hanika's terminator
    /// offset; RayScene::smoothSurface, seen from `eye`), and that surface's tangent plane, not
    /// the triangle's, blocks the light behind it. Changes nothing on flat triangles or in a
    /// scene without normals.
    bool terminatorOffset = false;
    glm::vec3 eye{0.0f}; // the eye the receivers were seen from (terminatorOffset only)
    /// Called on the caller's thread with the share of receivers done (up to about 100 times,
    /// rising, the last call 1); empty: not called.
    std::function<void(double)> progress;
};

/// The N points of the disk a receiver's rays go to: a stratified grid over the disk
/// (geom::stratifiedGrid, geom::concentricDisk), jittered per `receiver` index when asked. The
/// same for any thread count. Throws std::invalid_argument for N out of range.
std::vector<glm::vec3> diskSamples(const Disk& disk, const VisibilitySettings& settings,
                                   std::uint64_t receiver);

/// The visible share of the disk from each receiver: receivers[i] -> result[i] in [0, 1]. A
/// sample counts as blocked when a triangle crosses its ray, when the receiver's surface faces
/// away from it, or when it lies behind the disk (a disk lights one side). `raysCast`, if set,
/// receives the number of rays cast. Throws std::invalid_argument for settings out of range.
std::vector<float> diskVisibility(const RayScene& scene, const Disk& disk,
                                  std::span<const Receiver> receivers,
                                  const VisibilitySettings& settings,
                                  std::uint64_t* raysCast = nullptr);

} // namespace fl::rt
