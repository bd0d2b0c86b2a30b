#pragma once
// Compressed glTF files built in code with the encoders of libdraco
// (KHR_draco_mesh_compression) and libmeshoptimizer (EXT_meshopt_compression), each with the
// uncompressed file it must load as: for the loader tests and the decode benchmark.

#include "GltfBuilder.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace fl::test {

/// An n x n vertex height field over [0, 1]^2 (z within +-0.1) with unit normals, texcoords
/// (x, y) and two counter-clockwise triangles per cell.
struct GridMesh {
    std::vector<glm::vec3> positions, normals;
    std::vector<glm::vec2> texcoords;
    std::vector<std::uint32_t> indices;
};
GridMesh gridMesh(int n);

/// The grid as an ordinary file: FLOAT attributes, UNSIGNED_SHORT indices (UNSIGNED_INT past
/// 65536 vertices), placed by node 0 of scene 0.
Gltf plainGltf(const GridMesh& mesh);

/// A Draco-compressed grid and what a test checks it against.
struct DracoGltf {
    Gltf gltf;                                                // bufferViews[0]: the Draco bytes
    int positionId = -1, normalId = -1, texcoordId = -1;      // Draco attribute unique ids
    std::size_t points = 0, faces = 0;                        // as the Draco data decodes
    float positionStep = 0, normalStep = 0, texcoordStep = 0; // quantisation steps
};

/// Encodes `mesh` with draco::Encoder at the given quantisation bits (positionBits 0: positions
/// unquantised, as they are). Its accessors have no
/// bufferView (no uncompressed fallback); indices are UNSIGNED_SHORT or, past 65536 points,
/// UNSIGNED_INT. Throws std::runtime_error when Draco fails.
DracoGltf dracoGltf(const GridMesh& mesh, int positionBits = 14, int normalBits = 10,
                    int texcoordBits = 12);

/// The same meshopt-encoded data as an EXT_meshopt_compression file and as the ordinary file of
/// its decoded bytes, which the compressed one must load as, exactly.
struct MeshoptGltf {
    /// bufferViews 0..3 (POSITION, NORMAL, TEXCOORD_0, indices) are compressed views over
    /// fallback buffer 1, which has no uri; the encoded bytes are in buffer 0.
    Gltf compressed;
    Gltf plain;
};

/// The forms gltfpack writes, with KHR_mesh_quantization: positions FLOAT with the
/// EXPONENTIAL filter, normals normalized BYTE (stride 4) with OCTAHEDRAL, texcoords
/// normalized UNSIGNED_SHORT without filter, indices in TRIANGLES mode (or, with
/// `indexSequence`, INDICES mode).
MeshoptGltf meshoptGltf(const GridMesh& mesh, bool indexSequence = false);

} // namespace fl::test
