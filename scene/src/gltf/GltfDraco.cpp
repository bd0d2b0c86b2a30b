// KHR_draco_mesh_compression: a primitive whose attributes and faces are one Draco mesh in a
// bufferView (extensions.KHR_draco_mesh_compression.{bufferView, attributes{NAME: unique id}}).
// It is decoded with libdraco; each compressed attribute's accessor and the indices accessor
// then read a new bufferView holding the decoded values in the accessor's componentType, so the
// mesh conversion reads and checks them as it reads any accessor. The accessors' count, type
// and componentType say what the decoded data must be (spec: they must match it), and are
// checked against it here.

#include "GltfCompressed.h"

#include <draco/compression/decode.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <memory>

namespace fl::gltf {
namespace {

constexpr const char* kDracoExtension = "KHR_draco_mesh_compression";

/// Every point's value of `attr` as `components` values of type T, in point order.
template <class T>
bool convertPoints(const draco::PointAttribute& attr, std::size_t points, int components,
                   std::vector<unsigned char>& out) {
    out.resize(points * static_cast<std::size_t>(components) * sizeof(T));
    T value[4] = {};
    for (std::size_t i = 0; i < points; ++i) {
        const draco::AttributeValueIndex avi =
            attr.mapped_index(draco::PointIndex(static_cast<std::uint32_t>(i)));
        if (avi.value() >= attr.size() ||
            !attr.ConvertValue<T>(avi, static_cast<std::int8_t>(components), value))
            return false;
        std::memcpy(out.data() + i * sizeof value[0] * static_cast<std::size_t>(components), value,
                    sizeof value[0] * static_cast<std::size_t>(components));
    }
    return true;
}

/// The decoded values of `attr` in `acc`'s componentType; false when a value does not convert.
bool convertAttribute(const draco::PointAttribute& attr, const tinygltf::Accessor& acc,
                      std::size_t points, int components, std::vector<unsigned char>& out) {
    switch (acc.componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
        return convertPoints<std::int8_t>(attr, points, components, out);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return convertPoints<std::uint8_t>(attr, points, components, out);
    case TINYGLTF_COMPONENT_TYPE_SHORT:
        return convertPoints<std::int16_t>(attr, points, components, out);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return convertPoints<std::uint16_t>(attr, points, components, out);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        return convertPoints<std::uint32_t>(attr, points, components, out);
    default:
        return convertPoints<float>(attr, points, components, out);
    }
}

/// Whether `acc` can hold Draco data: a glTF component type and a vector or scalar type.
bool convertible(const tinygltf::Accessor& acc) {
    const int type = acc.type;
    const int component = acc.componentType;
    return (type == TINYGLTF_TYPE_SCALAR || type == TINYGLTF_TYPE_VEC2 ||
            type == TINYGLTF_TYPE_VEC3 || type == TINYGLTF_TYPE_VEC4) &&
           (component == TINYGLTF_COMPONENT_TYPE_BYTE ||
            component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
            component == TINYGLTF_COMPONENT_TYPE_SHORT ||
            component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
            component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT ||
            component == TINYGLTF_COMPONENT_TYPE_FLOAT);
}

/// What decodeDraco works on: the primitive, its names for messages, the decoded mesh.
struct DracoPrimitive {
    const Context& ctx;
    tinygltf::Model& model;
    std::string element;    // "meshes[0].primitives[1]"
    std::string extElement; // element + ".extensions.KHR_draco_mesh_compression"
    int bufferView = -1;
    std::map<int, std::pair<int, int>>& decoded;

    /// Whether accessors[index] still needs decoding from (bufferView, id); fails when another
    /// primitive decoded it from other data.
    bool claim(int index, int id, std::string_view usage) {
        const auto [it, fresh] = decoded.emplace(index, std::pair{bufferView, id});
        if (!fresh && it->second != std::pair{bufferView, id})
            ctx.fail(element, cat(usage, ": accessors[", index,
                                  "] is also decoded from other Draco data by another primitive"));
        return fresh;
    }

    /// Points accessors[index] at a new bufferView holding `bytes`.
    void replaceData(int index, std::vector<unsigned char> bytes) {
        const int view = appendDecodedView(model, std::move(bytes), 0);
        tinygltf::Accessor& acc = model.accessors[static_cast<std::size_t>(index)];
        acc.bufferView = view;
        acc.byteOffset = 0;
    }
};

void decodeAttribute(DracoPrimitive& d, const draco::Mesh& mesh, const std::string& name,
                     const tinygltf::Value& idValue, const tinygltf::Primitive& prim) {
    const Context& ctx = d.ctx;
    const std::string usage = cat(d.extElement, ".attributes.", name);
    const auto attribute = prim.attributes.find(name);
    if (attribute == prim.attributes.end())
        ctx.fail(usage, "names an attribute the primitive does not have");
    const double idNumber = idValue.IsNumber() ? idValue.GetNumberAsDouble() : -1.0;
    if (!(idNumber >= 0.0 && idNumber <= 1e9 && idNumber == std::floor(idNumber)))
        ctx.fail(usage, "is not a Draco attribute id (a whole number >= 0)");
    const auto id = static_cast<int>(idNumber);
    const int index = attribute->second;
    const tinygltf::Accessor& acc =
        ctx.lookup(d.model.accessors, index, usage, "accessor", "accessors");
    if (!d.claim(index, id, usage)) return; // decoded already, from the same data
    const draco::PointAttribute* attr = mesh.GetAttributeByUniqueId(static_cast<std::uint32_t>(id));
    if (!attr) ctx.fail(usage, cat("the Draco data has no attribute with id ", id));
    const std::string accElement = elem("accessors", static_cast<std::size_t>(index));
    const std::size_t points = mesh.num_points();
    if (acc.count != points)
        ctx.fail(accElement, cat(name, ": count ", acc.count, " but the Draco data decodes ",
                                 points, " points"));
    if (!convertible(acc))
        ctx.fail(accElement, cat(name, ": type ", acc.type, " / componentType ", acc.componentType,
                                 " cannot hold Draco data"));
    const int components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(acc.type));
    if (attr->num_components() != components)
        ctx.fail(accElement, cat(name, ": ", components, " components, but Draco attribute ", id,
                                 " has ", int{attr->num_components()}));
    if (!attr->is_mapping_identity() && attr->indices_map_size() < points)
        ctx.fail(usage, "Draco attribute maps fewer points than the mesh has (corrupt data)");
    ctx.charge(points * static_cast<std::size_t>(components), usage);
    std::vector<unsigned char> bytes;
    if (!convertAttribute(*attr, acc, points, components, bytes))
        ctx.fail(usage, cat("Draco attribute ", id, " does not convert to ", accElement,
                            "'s componentType ", acc.componentType));
    d.replaceData(index, std::move(bytes));
}

template <class T>
std::vector<unsigned char> faceBytes(const draco::Mesh& mesh) {
    std::vector<unsigned char> out(std::size_t{mesh.num_faces()} * 3 * sizeof(T));
    for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f)
        for (int k = 0; k < 3; ++k) {
            const T v = static_cast<T>(mesh.face(f)[k].value());
            std::memcpy(out.data() +
                            (std::size_t{f.value()} * 3 + static_cast<std::size_t>(k)) * sizeof(T),
                        &v, sizeof v);
        }
    return out;
}

void decodeIndices(DracoPrimitive& d, const draco::Mesh& mesh, int index) {
    const Context& ctx = d.ctx;
    const std::string usage = d.element + ".indices";
    const tinygltf::Accessor& acc =
        ctx.lookup(d.model.accessors, index, usage, "accessor", "accessors");
    if (!d.claim(index, -1, usage)) return;
    const std::string accElement = elem("accessors", static_cast<std::size_t>(index));
    const std::size_t faces = mesh.num_faces();
    if (acc.count != 3 * faces)
        ctx.fail(accElement, cat("indices: count ", acc.count, " but the Draco data decodes ",
                                 faces, " triangles (", 3 * faces, " indices)"));
    // Point ids past the mesh would be caught later as indices past the vertex count; here they
    // must also fit the accessor's type, which the largest point id decides.
    std::uint64_t largest = 0;
    for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f)
        for (int k = 0; k < 3; ++k)
            largest = std::max<std::uint64_t>(largest, mesh.face(f)[k].value());
    if (faces > 0 && largest >= mesh.num_points())
        ctx.fail(usage, cat("Draco face refers to point ", largest, " of ", mesh.num_points(),
                            " (corrupt data)"));
    ctx.charge(3 * faces, usage);
    std::vector<unsigned char> bytes;
    switch (acc.componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        if (largest > 0xFF) break;
        bytes = faceBytes<std::uint8_t>(mesh);
        break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        if (largest > 0xFFFF) break;
        bytes = faceBytes<std::uint16_t>(mesh);
        break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        bytes = faceBytes<std::uint32_t>(mesh);
        break;
    default:
        ctx.fail(accElement, cat("indices: componentType ", acc.componentType,
                                 " is not UNSIGNED_BYTE/SHORT/INT"));
    }
    if (bytes.empty() && faces > 0)
        ctx.fail(accElement, cat("indices: componentType ", acc.componentType,
                                 " cannot hold the Draco point id ", largest));
    d.replaceData(index, std::move(bytes));
}

} // namespace

void decodeDraco(const Context& ctx, tinygltf::Model& model, std::size_t meshIndex,
                 std::size_t primitiveIndex, std::map<int, std::pair<int, int>>& decoded) {
    const tinygltf::Primitive& prim = model.meshes[meshIndex].primitives[primitiveIndex];
    const auto it = prim.extensions.find(kDracoExtension);
    if (it == prim.extensions.end()) return;
    // Points and lines are skipped by the mesh conversion without being read.
    if (prim.mode >= TINYGLTF_MODE_POINTS && prim.mode <= TINYGLTF_MODE_LINE_STRIP) return;
    DracoPrimitive d{
        ctx, model, cat(elem("meshes", meshIndex), elem(".primitives", primitiveIndex)),
        "",  -1,    decoded};
    d.extElement = d.element + ".extensions.KHR_draco_mesh_compression";
    if (prim.mode != TINYGLTF_MODE_TRIANGLES)
        ctx.fail(d.element, cat("mode ", prim.mode,
                                " with KHR_draco_mesh_compression (Draco "
                                "stores triangle lists: mode must be 4)"));
    const tinygltf::Value& ext = it->second;
    if (!ext.IsObject() || !ext.Has("bufferView") || !ext.Get("bufferView").IsInt() ||
        !ext.Has("attributes") || !ext.Get("attributes").IsObject())
        ctx.fail(d.extElement, "needs a bufferView index and an attributes object");
    if (prim.indices < 0)
        ctx.fail(d.element, "KHR_draco_mesh_compression without an indices accessor");
    d.bufferView = ext.Get("bufferView").GetNumberAsInt();
    const ByteSpan bytes = bufferViewBytes(ctx, d.bufferView, d.extElement);

    draco::DecoderBuffer buffer;
    buffer.Init(reinterpret_cast<const char*>(bytes.data), bytes.size);
    const auto type = draco::Decoder::GetEncodedGeometryType(&buffer);
    if (!type.ok() || type.value() != draco::TRIANGULAR_MESH)
        ctx.fail(d.extElement,
                 cat("bufferViews[", d.bufferView, "] is not a Draco triangle mesh",
                     type.ok() ? "" : cat(" (", type.status().error_msg_string(), ")")));
    draco::Decoder decoder;
    auto result = decoder.DecodeMeshFromBuffer(&buffer);
    if (!result.ok() || !result.value())
        ctx.fail(d.extElement, cat("Draco data in bufferViews[", d.bufferView,
                                   "] does not decode (", result.status().error_msg_string(), ")"));
    const std::unique_ptr<draco::Mesh> mesh = std::move(result).value();
    // The accessor limit, as for uncompressed data (the counts must match the accessors').
    if (mesh->num_points() > kMaxAccessorCount ||
        3 * std::size_t{mesh->num_faces()} > kMaxAccessorCount)
        ctx.fail(d.extElement, cat("the Draco data decodes ", mesh->num_points(), " points and ",
                                   mesh->num_faces(), " triangles (absurd size; limit ",
                                   kMaxAccessorCount, " vertices or indices)"));

    // Decoding appends buffers and bufferViews and edits accessors: `prim` and `ext` stay valid.
    const tinygltf::Value& attributes = ext.Get("attributes");
    for (const std::string& name : attributes.Keys())
        decodeAttribute(d, *mesh, name, attributes.Get(name), prim);
    decodeIndices(d, *mesh, prim.indices);
}

} // namespace fl::gltf
