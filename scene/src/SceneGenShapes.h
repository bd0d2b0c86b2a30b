#pragma once
// Private building blocks of the scene generator: a deterministic PRNG, a mesh builder that can
// also just count triangles (the budget search runs every object in that mode many times), and
// the primitive shapes the objects are made of. Everything here uses only + - * /, sqrt, sin and
// cos, so the generated numbers are the same on every IEEE-754 machine.

#include <scene/Scene.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace fl::gen {

/// PCG32 (O'Neill), seeded through splitmix64 so that nearby seeds give unrelated streams.
/// We use our own generator because std:: distributions are implementation-defined.
class Rng {
  public:
    explicit Rng(std::uint64_t seed);
    std::uint32_t next();
    /// Uniform in [0, 1) with 24 bits, exactly representable as float.
    float unit();
    /// Uniform in [lo, hi).
    float uniform(float lo, float hi) { return lo + (hi - lo) * unit(); }
    /// A new independent generator (for one object's design) derived from this one.
    Rng fork();

  private:
    std::uint64_t state_ = 0;
    std::uint64_t inc_ = 0;
};

/// Collects one mesh. In count-only mode it only adds up triangles and the shape functions skip
/// all geometry work, which makes trying many tessellation levels cheap.
class MeshBuilder {
  public:
    explicit MeshBuilder(bool countOnly = false) : countOnly_(countOnly) {}

    [[nodiscard]] bool countOnly() const { return countOnly_; }
    [[nodiscard]] std::size_t triangles() const { return triangles_; }
    /// Records n triangles without geometry (count-only mode).
    void countTriangles(std::size_t n) { triangles_ += n; }

    [[nodiscard]] std::uint32_t vertexCount() const {
        return static_cast<std::uint32_t>(positions_.size());
    }
    std::uint32_t vertex(const glm::vec3& p, const glm::vec3& n);
    void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c);
    /// Replaces the normals of vertices [firstVertex, end) by the normalised, area-weighted sum
    /// of the face normals of triangles [firstIndex / 3, end): smooth normals for displaced shapes.
    void smoothNormals(std::uint32_t firstVertex, std::size_t firstIndex);

    [[nodiscard]] std::size_t indexCount() const { return indices_.size(); }
    /// Moves the collected geometry into `mesh` (positions, normals, indices).
    void moveInto(Mesh& mesh);

  private:
    bool countOnly_ = false;
    std::size_t triangles_ = 0;
    std::vector<glm::vec3> positions_;
    std::vector<glm::vec3> normals_;
    std::vector<std::uint32_t> indices_;
};

/// A point of a surface-of-revolution profile in the (radius, height) half plane. r == 0 makes a
/// pole (a single vertex closing the surface). `hard` starts a new smooth patch here: no band
/// joins this point to the previous one (give the previous point the same position for a crease).
struct ProfilePoint {
    float r = 0.0f;
    float y = 0.0f;
    bool hard = false;
};

/// Surface of revolution about local +Y with `segments` (>= 3) around. A profile that runs from
/// a bottom pole outward, up and back in to a top pole is a closed solid whose triangles face
/// outward. Normals are smooth within each patch.
void addLathe(MeshBuilder& b, const glm::mat4& xf, std::span<const ProfilePoint> profile,
              int segments);
[[nodiscard]] std::size_t latheTriangles(std::span<const ProfilePoint> profile, int segments);

/// Closed capsule of radius r from y = 0 to y = length (length >= 2r) along local +Y, with
/// `capRings` rings per hemisphere (0: a cone tip instead of a hemisphere).
void addCapsule(MeshBuilder& b, const glm::mat4& xf, float r, float length, int segments,
                int capRings);

/// UV sphere of radius 1 at the origin (scale it with xf) with `stacks` >= 2 bands.
void addSphere(MeshBuilder& b, const glm::mat4& xf, int segments, int stacks);

/// A few random plane waves on the sphere of directions; displaces blobs (rocks, leaf clusters).
struct Bumps {
    static constexpr int kWaves = 4;
    glm::vec3 dir[kWaves]{};
    float freq[kWaves]{};
    float phase[kWaves]{};
    float amp[kWaves]{};
    [[nodiscard]] float operator()(const glm::vec3& unitDir) const;
    /// Random bumps whose amplitudes add up to `roughness`.
    static Bumps random(Rng& rng, float roughness);
};

/// Unit sphere displaced radially by 1 + bumps(direction), then transformed by xf; smooth
/// normals from the faces.
void addBlob(MeshBuilder& b, const glm::mat4& xf, int segments, int stacks, const Bumps& bumps);

/// Axis-aligned box centred at the origin with the given half extents, flat-shaded (12 triangles).
void addBox(MeshBuilder& b, const glm::mat4& xf, const glm::vec3& halfExtent);

/// Rigid frame whose +Y axis is `axis` (unit) at `origin`, so primitives built along +Y can be
/// pointed anywhere; right-handed, so triangle winding is preserved.
[[nodiscard]] glm::mat4 frameAlong(const glm::vec3& origin, const glm::vec3& axis);

/// Translation, rotation about +Y by `yaw` radians, then non-uniform scale.
[[nodiscard]] glm::mat4 placeYaw(const glm::vec3& origin, float yaw,
                                 const glm::vec3& scale = glm::vec3(1.0f));

/// A random unit vector (rejection sampling in the unit ball; sqrt only).
[[nodiscard]] glm::vec3 randomDirection(Rng& rng);

} // namespace fl::gen
