// Compressed meshes: the JSON rewrite tinygltf 2.7 needs for them, and the decoding pass that
// turns them into ordinary buffers before the meshes are converted (see GltfCompressed.h).

#include "GltfCompressed.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <set>
#include <string_view>
#include <utility>

namespace fl::gltf {
namespace {

using nlohmann::json;

constexpr std::string_view kDraco = "KHR_draco_mesh_compression";
constexpr std::string_view kMeshopt = "EXT_meshopt_compression";

bool mentions(const std::vector<unsigned char>& bytes, std::size_t begin, std::size_t end,
              std::string_view name) {
    const auto first = bytes.begin() + static_cast<std::ptrdiff_t>(begin);
    const auto last = bytes.begin() + static_cast<std::ptrdiff_t>(end);
    return std::search(first, last, name.begin(), name.end()) != last;
}

/// object[key] when it is a JSON object, else nullptr.
json* member(json& object, std::string_view key) {
    if (!object.is_object()) return nullptr;
    const auto it = object.find(key);
    return it != object.end() && it->is_object() ? &*it : nullptr;
}

/// Gives meshopt fallback buffers a one-byte data URI in place of their data, if any (see
/// GltfCompressed.h).
bool placeholderFallbackBuffers(json& doc) {
    bool changed = false;
    const auto buffers = doc.find("buffers");
    if (buffers == doc.end() || !buffers->is_array()) return false;
    for (json& buffer : *buffers) {
        json* ext = member(buffer, "extensions");
        json* meshopt = ext ? member(*ext, kMeshopt) : nullptr;
        if (!meshopt) continue;
        const auto fallback = meshopt->find("fallback");
        if (fallback == meshopt->end() || *fallback != true) continue;
        buffer["uri"] = kFallbackPlaceholderUri;
        buffer["byteLength"] = 1;
        changed = true;
    }
    return changed;
}

/// Points the indices accessor of Draco primitives that lack a bufferView at the Draco
/// bufferView (or bufferView 0 when that index is invalid: decodeDraco reports it), so that
/// tinygltf accepts it (see GltfCompressed.h).
bool placeholderDracoIndices(json& doc) {
    const auto meshes = doc.find("meshes");
    const auto accessors = doc.find("accessors");
    const auto views = doc.find("bufferViews");
    if (meshes == doc.end() || !meshes->is_array() || accessors == doc.end() ||
        !accessors->is_array() || views == doc.end() || !views->is_array() || views->empty())
        return false;
    bool changed = false;
    for (json& mesh : *meshes) {
        if (!mesh.is_object() || !mesh.contains("primitives") || !mesh["primitives"].is_array())
            continue;
        for (json& prim : mesh["primitives"]) {
            json* ext = member(prim, "extensions");
            json* draco = ext ? member(*ext, kDraco) : nullptr;
            if (!draco || !prim.contains("indices") || !prim["indices"].is_number_unsigned())
                continue;
            const auto index = prim["indices"].get<std::size_t>();
            if (index >= accessors->size()) continue; // tinygltf reports it
            json& accessor = (*accessors)[index];
            if (!accessor.is_object() || accessor.contains("bufferView")) continue;
            std::size_t view = 0;
            if (draco->contains("bufferView") && (*draco)["bufferView"].is_number_unsigned() &&
                (*draco)["bufferView"].get<std::size_t>() < views->size())
                view = (*draco)["bufferView"].get<std::size_t>();
            accessor["bufferView"] = view;
            changed = true;
        }
    }
    return changed;
}

void putU32(std::vector<unsigned char>& out, std::size_t at, std::uint32_t v) {
    for (std::size_t i = 0; i < 4; ++i) out[at + i] = static_cast<unsigned char>(v >> (8 * i));
}

std::uint32_t getU32(const std::vector<unsigned char>& in, std::size_t at) {
    std::uint32_t v = 0;
    for (std::size_t i = 0; i < 4; ++i) v |= std::uint32_t{in[at + i]} << (8 * i);
    return v;
}

} // namespace

bool prepareCompressedJson(std::vector<unsigned char>& bytes, std::size_t& size,
                           std::pair<std::size_t, std::size_t> range, bool binary,
                           std::size_t padding) {
    const auto [begin, end] = range;
    if (binary && begin != 20) return false; // broken GLB header: tinygltf reports it
    if (!mentions(bytes, begin, end, kDraco) && !mentions(bytes, begin, end, kMeshopt))
        return false;
    json doc = json::parse(bytes.begin() + static_cast<std::ptrdiff_t>(begin),
                           bytes.begin() + static_cast<std::ptrdiff_t>(end), nullptr,
                           /*allow_exceptions=*/false);
    if (!doc.is_object()) return false;
    const bool buffers = placeholderFallbackBuffers(doc);
    const bool indices = placeholderDracoIndices(doc);
    if (!buffers && !indices) return false;
    std::string text;
    try {
        text = doc.dump();
    } catch (const json::exception&) {
        return false; // not representable again (cannot happen for parsed text): leave as is
    }

    std::vector<unsigned char> out;
    if (!binary) {
        out.assign(text.begin(), text.end());
        size = out.size();
    } else {
        // Same container around the new JSON chunk: header, JSON chunk (space padded to 4 bytes,
        // as the GLB spec asks), then everything that followed the old JSON chunk.
        while (text.size() % 4 != 0) text += ' ';
        const std::uint64_t length = std::uint64_t{getU32(bytes, 8)} - (end - begin) + text.size();
        if (length > 0xFFFFFFFFull) return false;
        out.assign(bytes.begin(), bytes.begin() + 20);
        putU32(out, 8, static_cast<std::uint32_t>(length));
        putU32(out, 12, static_cast<std::uint32_t>(text.size()));
        out.insert(out.end(), text.begin(), text.end());
        out.insert(out.end(), bytes.begin() + static_cast<std::ptrdiff_t>(end),
                   bytes.begin() + static_cast<std::ptrdiff_t>(size));
        size = out.size();
    }
    out.resize(size + padding, 0);
    bytes = std::move(out);
    return true;
}

int appendDecodedView(tinygltf::Model& model, std::vector<unsigned char> bytes, int byteStride) {
    tinygltf::BufferView view;
    view.buffer = static_cast<int>(model.buffers.size());
    view.byteOffset = 0;
    view.byteLength = bytes.size();
    view.byteStride = static_cast<std::size_t>(byteStride);
    tinygltf::Buffer buffer;
    buffer.data = std::move(bytes);
    model.buffers.push_back(std::move(buffer));
    model.bufferViews.push_back(view);
    return static_cast<int>(model.bufferViews.size()) - 1;
}

void decodeCompressed(const Context& ctx, tinygltf::Model& model,
                      const std::vector<PlacedNode>& placed) {
    // Only what the converted meshes read is decoded (and so checked), as for uncompressed data;
    // every attribute of those primitives counts, not just the ones read today.
    std::set<int> meshes, views;
    std::vector<std::pair<std::size_t, std::size_t>> draco;
    auto addAccessor = [&](int index) {
        if (!Context::inRange(model.accessors, index)) return; // the readers report it
        const tinygltf::Accessor& acc = model.accessors[static_cast<std::size_t>(index)];
        views.insert(acc.bufferView);
        if (acc.sparse.isSparse)
            views.insert({acc.sparse.indices.bufferView, acc.sparse.values.bufferView});
    };
    for (const PlacedNode& p : placed) {
        const int mesh = model.nodes[static_cast<std::size_t>(p.node)].mesh;
        if (!Context::inRange(model.meshes, mesh) || !meshes.insert(mesh).second) continue;
        const auto& primitives = model.meshes[static_cast<std::size_t>(mesh)].primitives;
        for (std::size_t i = 0; i < primitives.size(); ++i) {
            const tinygltf::Primitive& prim = primitives[i];
            if (prim.extensions.count(std::string(kDraco)) != 0)
                draco.emplace_back(static_cast<std::size_t>(mesh), i);
            for (const auto& attribute : prim.attributes) addAccessor(attribute.second);
            addAccessor(prim.indices);
        }
    }
    for (const int view : views)
        if (Context::inRange(model.bufferViews, view)) decodeMeshoptView(ctx, model, view);
    std::map<int, std::pair<int, int>> decoded;
    for (const auto& [mesh, prim] : draco) decodeDraco(ctx, model, mesh, prim, decoded);
}

} // namespace fl::gltf
