#pragma once
// Private: the terrain and the objects of the generated scene. Each object is fully described
// by an ObjectDesign (where it stands, its size, its random seed) and then tessellated at an
// integer detail level; the triangle count never decreases as the level rises, which is what the
// budget search in SceneGenerator.cpp relies on.

#include "SceneGenShapes.h"

#include <array>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

namespace fl::gen {

inline constexpr float kPi = std::numbers::pi_v<float>;

/// Gentle hills: a sum of four plane waves over a square centred at the origin.
class Terrain {
  public:
    static constexpr float kSize = 24.0f;            // metres along x and z
    static constexpr std::size_t kMinTriangles = 48; // coarsest grid we accept

    explicit Terrain(Rng& rng);
    /// The smooth height field (the mesh's vertices lie on it).
    [[nodiscard]] float height(float x, float z) const;
    [[nodiscard]] glm::vec3 normal(float x, float z) const;

    /// Fixes the tessellation: exactly `triangles` (>= kMinTriangles) triangles in a grid whose
    /// first and last rows are strips towards a coarser boundary polyline, which absorbs any
    /// remainder without T-junctions.
    void tessellate(std::size_t triangles);
    /// Height of the tessellated surface (of the height field before tessellate): objects are
    /// placed on what is drawn, which matters for coarse grids in small scenes.
    [[nodiscard]] float surfaceHeight(float x, float z) const;
    /// The lowest surface at the centre and at eight points around it at `radius`: an object
    /// whose base reaches below this (minus a sink depth) never floats on a slope.
    [[nodiscard]] float groundUnder(glm::vec2 centre, float radius) const;
    /// Emits the tessellated mesh.
    void build(MeshBuilder& b) const;

    /// Grid shape: nx columns, nz rows of cells; rows 0 and nz-1 are strips whose outer edge has
    /// m0 and m1 (1..nx) segments. Triangles: 2 nx (nz - 2) + (nx + m0) + (nx + m1).
    struct GridPlan {
        int nx = 0;
        int nz = 0;
        int m0 = 0;
        int m1 = 0;
    };

  private:
    /// Position of vertex i of grid line `line` (0..nz), on the height field.
    [[nodiscard]] glm::vec3 linePoint(int line, int i) const;
    [[nodiscard]] int lineSegments(int line) const;

    static constexpr int kWaves = 4;
    std::array<glm::vec2, kWaves> dir_{};
    std::array<float, kWaves> k_{};
    std::array<float, kWaves> amp_{};
    std::array<float, kWaves> phase_{};
    std::size_t triangles_ = 0;
    GridPlan plan_;
};

enum class Kind { Tree, Pergola, Mushroom, Rock, Flower, Character };

/// One object of the scene before tessellation. Objects with two colours (tree: bark and
/// leaves) have two parts, each becoming its own mesh, material and node.
struct ObjectDesign {
    Kind kind = Kind::Rock;
    std::string name;
    glm::vec2 at{0.0f}; // position on the terrain (x, z)
    float yaw = 0.0f;   // rotation about +Y, radians
    float scale = 1.0f; // overall size factor
    std::uint64_t seed = 0;
    int weight = 1;         // share of the triangle budget
    int variant = 0;        // index among the objects of its kind
    glm::vec3 origin{0.0f}; // world position of the local origin (filled by placeOnTerrain)
};

/// Number of parts (meshes) an object of this kind has: 1 or 2.
[[nodiscard]] int partCount(Kind kind);
/// Name suffix and base colour of part `part` (0 or 1); `variant` (the object's index among
/// its kind) and `rng` vary the colour between objects of one kind.
[[nodiscard]] std::string partSuffix(Kind kind, int part);
[[nodiscard]] glm::vec4 partColor(Kind kind, int part, int variant, Rng& rng);
/// Radius of the area the object covers on the ground (for layout) and of its base (for
/// ground contact).
[[nodiscard]] float layoutRadius(Kind kind, float scale);
[[nodiscard]] float baseRadius(Kind kind, float scale);

/// Sets design.origin: on the lowest ground under the object's base.
void placeOnTerrain(ObjectDesign& design, const Terrain& terrain);

struct RigPart; // SceneGenRig.h

/// Tessellates the object at `detail` >= 0 into parts[0] (and parts[1] for two-part kinds),
/// in the object's local frame (origin on the ground, +Y up). A character also lists in `rig`
/// (if given) which of its vertices each joint of its skeleton carries.
void buildObject(const ObjectDesign& design, const Terrain& terrain, int detail,
                 std::array<MeshBuilder, 2>& parts, std::vector<RigPart>* rig = nullptr);

/// Triangles buildObject produces at `detail` (a count-only run).
[[nodiscard]] std::size_t objectTriangles(const ObjectDesign& design, const Terrain& terrain,
                                          int detail);

/// How deep objects reach below the ground they stand on, metres.
inline constexpr float kSink = 0.06f;

} // namespace fl::gen
