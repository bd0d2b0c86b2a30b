#pragma once
// Visibility of a disk light by casting shadow rays (Intel Embree 3): the ground truth that uses
// no shadow map, so it shares none of the errors of the techniques it judges (depth bias, texel
// aliasing, the map's resolution). Per receiver point, N rays go to stratified points of the
// disk; its visibility is the share of them that nothing blocks. Pure CPU, all cores.
//
// Where rays start (as Blender Cycles does): each receiver is found on the
// triangle the eye's ray meets there (RayScene::surface), and its rays start on that triangle and
// skip it (Cycles' self-intersection rule: intern/cycles/kernel/bvh/util.h,
// intersection_skip_self_shadow) rather than starting an epsilon off it. A ray nearly parallel to
// its triangle then meets what it meets whatever the epsilon, where a ray started above the
// plane crossed it past the triangle's edge, or grazed an occluder's edge, by the epsilon's size.
// A start on an edge or a corner moves into its triangle (each barycentric at least 1e-4), so the
// neighbour sharing that edge does not pass through the ray's start.
// Rays stop `epsilon` x the scene's diagonal short of the disk (the disk is no geometry; this only
// keeps a triangle lying in the disk from blocking it). A receiver on no triangle (a point the
// scene's surfaces do not hold) starts `epsilon` x the diagonal along its normal instead: 1e-5 by
// default, far above float rounding at the scene's scale and far below any feature a shadow map
// resolves.
//
// With VisibilitySettings::terminatorOffset, the smooth surface the vertex normals describe
// decides which light a receiver faces, and a ray near the shadow terminator starts on that
// surface: moved by Hanika's offset (raytrace/Terminator.h) times Cycles' amount for that ray
// (offsetAmount: 0 unless the ray grazes the triangle or its smooth surface), decided per ray
// since each ray is one of Cycles' light samples. Such a ray skips its triangle only while the
// triangle's plane faces its light point (Ng.L > 0): otherwise it is meant to meet it, as in
// Cycles.

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

/// A receiver's place on its triangle (RayScene::surface).
struct SurfacePoint {
    std::uint32_t triangle = 0;        // the triangle: its rays skip it
    glm::vec3 position{0.0f};          // on it (barycentrics at least 1e-4: off its edges)
    glm::vec3 normal{0.0f};            // its plane's unit normal, on the side it is seen from
    std::optional<SmoothPoint> smooth; // Hanika's point on its smooth surface; nullopt where the
                                       // scene has no normals or the triangle is flat
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
    /// True when a triangle other than `skip` (an index into the triangles; none for nullopt)
    /// crosses the ray from `from` towards `to`, up to `shortOf` before `to` (`to` excluded).
    /// The ray's direction is the same for any `shortOf`, so what it meets on the way is too.
    [[nodiscard]] bool occluded(glm::vec3 from, glm::vec3 to,
                                std::optional<std::uint32_t> skip = std::nullopt,
                                float shortOf = 0.0f) const;
    /// The surface under `point`, seen on the side `side` (unit): the first triangle that the
    /// ray from `eye` through the point meets within 1e-3 of the distance (at least 1.6e-4 x the
    /// diagonal) of it, as the rasteriser drew it there; without an eye, the first the line
    /// along `side` meets within 1.6e-4 x the diagonal. nullopt where none lies there or it has
    /// no area.
    [[nodiscard]] std::optional<SurfacePoint> surface(glm::vec3 point, glm::vec3 side,
                                                      std::optional<glm::vec3> eye) const;
    /// The length of the diagonal of the vertices' bounding box: the scale of every offset.
    [[nodiscard]] float diagonal() const { return diagonal_; }
    [[nodiscard]] std::size_t triangleCount() const { return triangleCount_; }
    /// Wall time of the last build or refit, ms.
    [[nodiscard]] double lastBuildMs() const { return buildMs_; }

  private:
    struct Embree;
    std::unique_ptr<Embree> e_;
    float diagonal_ = 0.0f;
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

/// The default ray offset, x the scene's diagonal.
inline constexpr float kRayEpsilon = 1e-5f;

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
    /// true: the smooth surface of a receiver's triangle (its vertex normals) decides which
    /// light it faces, and each ray that grazes the triangle or that surface starts on the
    /// surface, by Cycles' amount (the header comment; raytrace/Terminator.h). false: the flat
    /// triangle decides, and every ray starts on it. The same on flat triangles or in a scene
    /// without normals.
    bool terminatorOffset = false;
    /// Cycles' Geometry Offset: the cosine under which a ray counts as grazing (offsetAmount).
    float geometryOffset = kGeometryOffset;
    /// The eye the receivers were seen from: it finds each receiver's triangle (RayScene::surface;
    /// without it, the line along the receiver's normal does).
    std::optional<glm::vec3> eye;
    /// The ray epsilon as a share of RayScene::diagonal(), in (0, 0.01): what a ray stops short
    /// of the disk, and a receiver on no triangle starts off it (the header comment).
    float epsilon = kRayEpsilon;
    /// Called on the caller's thread with the share of receivers done (up to about 100 times,
    /// rising, the last call 1); empty: not called.
    std::function<void(double)> progress;
};

/// The N points of the disk a receiver's rays go to: a stratified grid over the disk
/// (geom::stratifiedGrid, geom::concentricDisk), jittered per `receiver` index when asked. The
/// same for any thread count. Throws std::invalid_argument for N out of range.
std::vector<glm::vec3> diskSamples(const Disk& disk, const VisibilitySettings& settings,
                                   std::uint64_t receiver);

/// What diskVisibility cast.
struct RayCounts {
    std::uint64_t cast = 0;     // rays cast
    std::uint64_t offset = 0;   // of them, started off their triangle by the terminator offset
    std::uint64_t unplaced = 0; // receivers on no triangle (RayScene::surface found none)
};

/// The visible share of the disk from each receiver: receivers[i] -> result[i] in [0, 1]. A
/// sample counts as blocked when a triangle crosses its ray, when the receiver's surface faces
/// away from it, or when it lies behind the disk (a disk lights one side). `counts`, if set,
/// receives what was cast. Throws std::invalid_argument for settings out of range.
std::vector<float> diskVisibility(const RayScene& scene, const Disk& disk,
                                  std::span<const Receiver> receivers,
                                  const VisibilitySettings& settings, RayCounts* counts = nullptr);

} // namespace fl::rt
