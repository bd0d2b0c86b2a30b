#include "CompressedGltf.h"

#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>
#include <meshoptimizer.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

namespace fl::test {
namespace {

constexpr int kByte = 5120;

/// Node 0 of scene 0 places mesh 0, whose one primitive is `primitive`.
void placeMesh(Gltf& g, json primitive) {
    g.push("meshes", {{"primitives", json::array({std::move(primitive)})}});
    g.push("nodes", {{"mesh", 0}, {"name", "grid"}});
    g.doc["scenes"] = json::array({{{"nodes", {0}}}});
    g.doc["scene"] = 0;
}

int indexType(std::size_t vertices) {
    return vertices > 65536 ? kU32 : kU16;
}

template <class T>
std::vector<std::uint8_t> bytesOf(const std::vector<T>& v) {
    std::vector<std::uint8_t> out(v.size() * sizeof(T));
    std::memcpy(out.data(), v.data(), out.size());
    return out;
}

/// The indices as UNSIGNED_SHORT or UNSIGNED_INT bytes.
std::vector<std::uint8_t> indexBytes(const std::vector<std::uint32_t>& indices, int type) {
    if (type == kU32) return bytesOf(indices);
    return bytesOf(std::vector<std::uint16_t>(indices.begin(), indices.end()));
}

/// Largest extent of the values' bounding box (what Draco quantises over).
template <class V>
float range(const std::vector<V>& values) {
    V lo = values.front(), hi = values.front();
    for (const V& v : values) {
        lo = glm::min(lo, v);
        hi = glm::max(hi, v);
    }
    float r = 0;
    for (int i = 0; i < V::length(); ++i) r = std::max(r, hi[i] - lo[i]);
    return r;
}

/// One meshopt stream: the filtered data the codec encodes, and its decoded (filter undone)
/// bytes, which an ordinary file stores.
struct Stream {
    std::vector<std::uint8_t> filtered, decoded, encoded;
    std::size_t count = 0, stride = 0;
    std::string mode = "ATTRIBUTES", filter = "NONE";
};

Stream vertexStream(std::vector<std::uint8_t> filtered, std::size_t count, std::size_t stride,
                    const std::string& filter) {
    Stream s{std::move(filtered), {}, {}, count, stride, "ATTRIBUTES", filter};
    s.decoded = s.filtered;
    if (filter == "EXPONENTIAL") meshopt_decodeFilterExp(s.decoded.data(), count, stride);
    if (filter == "OCTAHEDRAL") meshopt_decodeFilterOct(s.decoded.data(), count, stride);
    s.encoded.resize(meshopt_encodeVertexBufferBound(count, stride));
    s.encoded.resize(meshopt_encodeVertexBuffer(s.encoded.data(), s.encoded.size(),
                                                s.filtered.data(), count, stride));
    return s;
}

} // namespace

GridMesh gridMesh(int n) {
    GridMesh m;
    const float step = 1.0f / static_cast<float>(n - 1), tau = 6.2831853f;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const float x = static_cast<float>(i) * step, y = static_cast<float>(j) * step;
            const float z = 0.1f * std::sin(tau * x) * std::cos(tau * y);
            const float dx = 0.1f * tau * std::cos(tau * x) * std::cos(tau * y);
            const float dy = -0.1f * tau * std::sin(tau * x) * std::sin(tau * y);
            m.positions.emplace_back(x, y, z);
            m.normals.push_back(glm::normalize(glm::vec3(-dx, -dy, 1.0f)));
            m.texcoords.emplace_back(x, y);
        }
    for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i) {
            const auto v = static_cast<std::uint32_t>(j * n + i),
                       un = static_cast<std::uint32_t>(n);
            m.indices.insert(m.indices.end(), {v, v + 1, v + un + 1, v, v + un + 1, v + un});
        }
    return m;
}

Gltf plainGltf(const GridMesh& mesh) {
    Gltf g;
    const int type = indexType(mesh.positions.size());
    placeMesh(g, {{"attributes",
                   {{"POSITION", g.vec3(mesh.positions)},
                    {"NORMAL", g.vec3(mesh.normals)},
                    {"TEXCOORD_0",
                     g.accessor(g.view(mesh.texcoords), kFloat, "VEC2", mesh.texcoords.size())}}},
                  {"indices", g.accessor(g.view(indexBytes(mesh.indices, type)), type, "SCALAR",
                                         mesh.indices.size())}});
    return g;
}

DracoGltf dracoGltf(const GridMesh& mesh, int positionBits, int normalBits, int texcoordBits) {
    const int faces = static_cast<int>(mesh.indices.size() / 3);
    draco::TriangleSoupMeshBuilder builder;
    builder.Start(faces);
    const int pos = builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
    const int nrm = builder.AddAttribute(draco::GeometryAttribute::NORMAL, 3, draco::DT_FLOAT32);
    const int tex = builder.AddAttribute(draco::GeometryAttribute::TEX_COORD, 2, draco::DT_FLOAT32);
    for (int f = 0; f < faces; ++f) {
        const std::uint32_t* t = &mesh.indices[static_cast<std::size_t>(3 * f)];
        const draco::FaceIndex face(static_cast<std::uint32_t>(f));
        builder.SetAttributeValuesForFace(pos, face, &mesh.positions[t[0]], &mesh.positions[t[1]],
                                          &mesh.positions[t[2]]);
        builder.SetAttributeValuesForFace(nrm, face, &mesh.normals[t[0]], &mesh.normals[t[1]],
                                          &mesh.normals[t[2]]);
        builder.SetAttributeValuesForFace(tex, face, &mesh.texcoords[t[0]], &mesh.texcoords[t[1]],
                                          &mesh.texcoords[t[2]]);
    }
    const std::unique_ptr<draco::Mesh> source = builder.Finalize();
    if (!source) throw std::runtime_error("draco: building the mesh failed");
    draco::Encoder encoder;
    if (positionBits > 0) // else positions are stored as they are (lossless)
        encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, positionBits);
    encoder.SetAttributeQuantization(draco::GeometryAttribute::NORMAL, normalBits);
    encoder.SetAttributeQuantization(draco::GeometryAttribute::TEX_COORD, texcoordBits);
    draco::EncoderBuffer encoded;
    if (const draco::Status s = encoder.EncodeMeshToBuffer(*source, &encoded); !s.ok())
        throw std::runtime_error("draco: " + s.error_msg_string());

    DracoGltf d;
    d.positionId = static_cast<int>(source->attribute(pos)->unique_id());
    d.normalId = static_cast<int>(source->attribute(nrm)->unique_id());
    d.texcoordId = static_cast<int>(source->attribute(tex)->unique_id());
    // The counts the accessors must state are the decoded ones (Draco may add points).
    draco::DecoderBuffer in;
    in.Init(encoded.data(), encoded.size());
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&in);
    if (!decoded.ok()) throw std::runtime_error("draco: " + decoded.status().error_msg_string());
    d.points = decoded.value()->num_points();
    d.faces = decoded.value()->num_faces();
    d.positionStep = positionBits > 0
                         ? range(mesh.positions) / static_cast<float>((1 << positionBits) - 1)
                         : 0.0f;
    d.normalStep = 2.0f / static_cast<float>((1 << normalBits) - 1);
    d.texcoordStep = range(mesh.texcoords) / static_cast<float>((1 << texcoordBits) - 1);

    Gltf& g = d.gltf;
    const int view = g.view(encoded.data(), encoded.size());
    auto placeholder = [&](int componentType, const char* type, std::size_t count) {
        return g.push("accessors",
                      {{"componentType", componentType}, {"type", type}, {"count", count}});
    };
    const int p = placeholder(kFloat, "VEC3", d.points);
    const int n = placeholder(kFloat, "VEC3", d.points);
    const int t = placeholder(kFloat, "VEC2", d.points);
    const int i = placeholder(indexType(d.points), "SCALAR", 3 * d.faces);
    placeMesh(g, {{"attributes", {{"POSITION", p}, {"NORMAL", n}, {"TEXCOORD_0", t}}},
                  {"indices", i},
                  {"extensions",
                   {{"KHR_draco_mesh_compression",
                     {{"bufferView", view},
                      {"attributes",
                       {{"POSITION", d.positionId},
                        {"NORMAL", d.normalId},
                        {"TEXCOORD_0", d.texcoordId}}}}}}}});
    g.doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    g.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    return d;
}

MeshoptGltf meshoptGltf(const GridMesh& mesh, bool indexSequence) {
    const std::size_t count = mesh.positions.size();
    std::vector<Stream> streams;
    {
        std::vector<std::uint32_t> exp(count * 3);
        meshopt_encodeFilterExp(exp.data(), count, 12, 15, &mesh.positions[0].x);
        streams.push_back(vertexStream(bytesOf(exp), count, 12, "EXPONENTIAL"));
    }
    {
        std::vector<float> xyzw;
        for (const glm::vec3& n : mesh.normals) xyzw.insert(xyzw.end(), {n.x, n.y, n.z, 0.0f});
        std::vector<std::int8_t> oct(count * 4);
        meshopt_encodeFilterOct(oct.data(), count, 4, 8, xyzw.data());
        streams.push_back(vertexStream(bytesOf(oct), count, 4, "OCTAHEDRAL"));
    }
    {
        std::vector<std::uint16_t> uv;
        for (const glm::vec2& t : mesh.texcoords)
            for (int c = 0; c < 2; ++c)
                uv.push_back(static_cast<std::uint16_t>(std::lround(t[c] * 65535.0f)));
        streams.push_back(vertexStream(bytesOf(uv), count, 4, "NONE"));
    }
    const int type = indexType(count);
    Stream idx{indexBytes(mesh.indices, type),
               {},
               {},
               mesh.indices.size(),
               type == kU32 ? 4u : 2u,
               indexSequence ? "INDICES" : "TRIANGLES",
               "NONE"};
    idx.encoded.resize(indexSequence ? meshopt_encodeIndexSequenceBound(idx.count, count)
                                     : meshopt_encodeIndexBufferBound(idx.count, count));
    idx.encoded.resize(indexSequence
                           ? meshopt_encodeIndexSequence(idx.encoded.data(), idx.encoded.size(),
                                                         mesh.indices.data(), idx.count)
                           : meshopt_encodeIndexBuffer(idx.encoded.data(), idx.encoded.size(),
                                                       mesh.indices.data(), idx.count));
    // TRIANGLES mode may rotate a triangle's corners: the plain file stores what decodes.
    idx.decoded.resize(idx.filtered.size());
    const int rc = indexSequence
                       ? meshopt_decodeIndexSequence(idx.decoded.data(), idx.count, idx.stride,
                                                     idx.encoded.data(), idx.encoded.size())
                       : meshopt_decodeIndexBuffer(idx.decoded.data(), idx.count, idx.stride,
                                                   idx.encoded.data(), idx.encoded.size());
    if (rc != 0) throw std::runtime_error("meshopt: the encoded indices do not decode");
    streams.push_back(std::move(idx));

    MeshoptGltf out;
    std::size_t fallbackSize = 0;
    for (const Stream& s : streams) {
        const bool vertex = s.mode == "ATTRIBUTES";
        json ext = {{"buffer", 0},
                    {"byteOffset", out.compressed.append(s.encoded.data(), s.encoded.size())},
                    {"byteLength", s.encoded.size()},
                    {"byteStride", s.stride},
                    {"count", s.count},
                    {"mode", s.mode}};
        if (s.filter != "NONE") ext["filter"] = s.filter;
        json view = {{"buffer", 1},
                     {"byteOffset", fallbackSize},
                     {"byteLength", s.decoded.size()},
                     {"extensions", {{"EXT_meshopt_compression", ext}}}};
        if (vertex) view["byteStride"] = s.stride;
        out.compressed.push("bufferViews", view);
        fallbackSize += (s.decoded.size() + 3) / 4 * 4;
        out.plain.view(s.decoded.data(), s.decoded.size(), vertex ? static_cast<int>(s.stride) : 0);
    }
    out.compressed.extraBuffers = {
        {{"byteLength", fallbackSize},
         {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}}};
    for (Gltf* g : {&out.compressed, &out.plain}) {
        const int p = g->accessor(0, kFloat, "VEC3", count);
        const int n = g->accessor(1, kByte, "VEC3", count);
        g->accessorAt(n)["normalized"] = true;
        const int t = g->accessor(2, kU16, "VEC2", count);
        g->accessorAt(t)["normalized"] = true;
        const int i = g->accessor(3, type, "SCALAR", mesh.indices.size());
        placeMesh(*g, {{"attributes", {{"POSITION", p}, {"NORMAL", n}, {"TEXCOORD_0", t}}},
                       {"indices", i}});
        g->doc["extensionsUsed"] = {"KHR_mesh_quantization"};
        g->doc["extensionsRequired"] = {"KHR_mesh_quantization"};
    }
    out.compressed.doc["extensionsUsed"].push_back("EXT_meshopt_compression");
    out.compressed.doc["extensionsRequired"].push_back("EXT_meshopt_compression");
    return out;
}

} // namespace fl::test
