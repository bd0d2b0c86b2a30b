#pragma once
// Private to the glTF loader: compressed meshes (KHR_draco_mesh_compression,
// EXT_meshopt_compression). Both are decoded into ordinary buffers, bufferViews and accessors of
// the model before the meshes are converted, so that the accessor readers (GltfAccessors.cpp)
// and the mesh conversion (GltfMeshes.cpp) read decoded data exactly as they read an
// uncompressed file, with the same checks (types, ranges, indices, finite positions).
//
//   prepareCompressedJson  before tinygltf parses: rewrites the two things tinygltf 2.7 refuses
//                          in such files (GltfCompressed.cpp)
//   decodeCompressed       after the scene's nodes are placed: decodes what their meshes read
//                          (GltfCompressed.cpp, with GltfMeshopt.cpp and GltfDraco.cpp)

#include "GltfInternal.h"

#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace fl::gltf {

/// The data URI prepareCompressedJson gives every meshopt fallback buffer.
inline constexpr std::string_view kFallbackPlaceholderUri =
    "data:application/octet-stream;base64,AA==";

/// Rewrites the JSON (bytes [range.first, range.second)) of a file using either extension so
/// that tinygltf 2.7 parses it, and for a .glb rebuilds the container around the new JSON chunk;
/// `bytes` keeps `padding` zero bytes past `size`. Leaves everything as it is (and returns false)
/// when nothing needs rewriting or the JSON does not parse (tinygltf then reports the problem):
/// - a meshopt fallback buffer (extensions.EXT_meshopt_compression.fallback): only compressed
///   bufferViews may use it (spec), so its data, if any, is never read. It usually has no uri,
///   which tinygltf fails in a .gltf and hands the BIN chunk in a .glb; when it has one, its file
///   need not be there. It gets a one-byte data URI placeholder (decodeMeshoptView rejects an
///   uncompressed bufferView over it).
/// - a Draco primitive's indices accessor without bufferView, which tinygltf refuses. It points
///   at the Draco bufferView until decodeDraco gives it the decoded faces.
bool prepareCompressedJson(std::vector<unsigned char>& bytes, std::size_t& size,
                           std::pair<std::size_t, std::size_t> range, bool binary,
                           std::size_t padding);

/// Decodes the compressed data the meshes of `placed` read, into new buffers of `model` (the
/// model `ctx` refers to): EXT_meshopt_compression bufferViews their accessors read, then
/// KHR_draco_mesh_compression primitives. Bad data fails through ctx.
void decodeCompressed(const Context& ctx, tinygltf::Model& model,
                      const std::vector<PlacedNode>& placed);

// --- GltfMeshopt.cpp -----------------------------------------------------------------------

/// Whether buffer carries extensions.EXT_meshopt_compression.fallback = true (no real data).
bool isMeshoptFallback(const tinygltf::Buffer& buffer);

/// Decodes bufferViews[view] if it has EXT_meshopt_compression, and makes it read the decoded
/// bytes (a new buffer); fails when an uncompressed view uses a fallback buffer.
void decodeMeshoptView(const Context& ctx, tinygltf::Model& model, int view);

// --- GltfDraco.cpp -------------------------------------------------------------------------

/// Decodes meshes[mesh].primitives[primitive] if it has KHR_draco_mesh_compression: the
/// accessors of its compressed attributes and its indices accessor then read the decoded data
/// (new buffers and bufferViews), converted to each accessor's componentType.
/// `decoded` maps each accessor decoded so far to its source (Draco bufferView, attribute id;
/// -1 for indices): two primitives may share accessors only over the same Draco data.
void decodeDraco(const Context& ctx, tinygltf::Model& model, std::size_t mesh,
                 std::size_t primitive, std::map<int, std::pair<int, int>>& decoded);

/// Appends a buffer holding `bytes` and a bufferView over all of it; returns the view's index.
int appendDecodedView(tinygltf::Model& model, std::vector<unsigned char> bytes, int byteStride);

} // namespace fl::gltf
