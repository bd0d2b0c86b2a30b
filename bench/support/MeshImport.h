#pragma once
// Triangle meshes from the formats public models come in besides glTF (issue 41's real-model
// benchmark): Wavefront OBJ, STL (binary and ASCII) and PLY (ASCII and binary little-endian),
// each read into one fl::Mesh and made a one-instance scene that writeGlb stores. Polygons are
// fan-triangulated; every group of an OBJ goes into the one mesh; materials and textures are
// not read. A file without normals gets smooth ones that keep hard edges (computeCreaseNormals).
//
// Bad input is one MeshFileError naming the file, and the line (text) or element (binary) and
// the problem: "spider.obj:12: face index 0 (OBJ counts from 1)". Files are read through
// base/InputFile.h with the scene size limit.

#include <scene/Scene.h>

#include <cstddef>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

namespace fl::bench {

/// A mesh file that cannot be read: what() is "FILE:LINE: problem" or "FILE: problem".
class MeshFileError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

/// Where a reader is in its file, for messages: "name:line: problem" (line 0: "name: problem").
struct MeshWhere {
    std::string name;
    std::size_t line = 0;
    [[noreturn]] void fail(const std::string& problem) const;
    /// Checks a coordinate (finite, within kMaxWorldCoordinate); `what` names it ("vertex 3 y").
    float coordinate(double v, std::string_view what) const;
};

/// The default crease angle: faces meeting at a sharper angle than this keep separate normals.
inline constexpr float kCreaseDegrees = 60.0f;

/// What a reader made of a file.
struct ImportedMesh {
    Mesh mesh;                    // triangles; normals empty when the file has none
    std::size_t polygons = 0;     // faces as the file lists them (before triangulation)
    std::string format;           // "OBJ", "binary STL", "ASCII PLY", ...
    bool normalsComputed = false; // readMeshFile made them (computeCreaseNormals)
};

/// Readers of the file's bytes; `name` is the file name their messages start with.
ImportedMesh readObj(std::string_view text, const std::string& name);
ImportedMesh readStl(std::span<const unsigned char> bytes, const std::string& name);
ImportedMesh readPly(std::span<const unsigned char> bytes, const std::string& name);

/// Reads `path` by its extension (.obj, .stl, .ply, any case), with normals: the file's, or
/// computeCreaseNormals' where it has none. Drops zero-area triangles (counted in `dropped`).
ImportedMesh readMeshFile(const std::filesystem::path& path, std::size_t* dropped = nullptr,
                          float creaseDegrees = kCreaseDegrees);

/// Replaces `mesh`'s normals by smooth vertex normals: at each position (vertices at exactly the
/// same place count as one), a corner's normal is the sum of the unit normals of the faces
/// around the position that meet its face at less than `creaseDegrees`, each weighted by its
/// corner's angle, normalised. Corners that get the same normal share a vertex; the others
/// split it, so a crease stays sharp. Zero-area triangles are dropped first; returns how many.
std::size_t computeCreaseNormals(Mesh& mesh, float creaseDegrees = kCreaseDegrees);

/// A scene of `mesh` alone: one default grey material, one instance at the origin, no light
/// (the renderer places its default one), bounds computed. Throws MeshFileError "source: no
/// triangles" for an empty mesh.
Scene meshScene(Mesh mesh, const std::string& source);

} // namespace fl::bench
