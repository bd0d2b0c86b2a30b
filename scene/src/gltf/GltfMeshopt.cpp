// EXT_meshopt_compression: a bufferView whose bytes are meshoptimizer's vertex or index codec
// output, stored in another buffer (extensions.EXT_meshopt_compression.{buffer, byteOffset,
// byteLength}). It is decoded with libmeshoptimizer into a new buffer, and the bufferView then
// reads that, so the accessors over it are read and checked as usual.
//
// meshoptimizer checks its preconditions (strides, counts) only with assert(), which Debian's
// build compiles out: everything it assumes is validated here first, with the spec's rules.

#include "GltfCompressed.h"

#include <meshoptimizer.h>

#include <array>
#include <cmath>
#include <optional>
#include <string_view>

namespace fl::gltf {
namespace {

constexpr const char* kMeshoptExtension = "EXT_meshopt_compression";

enum class Mode { Attributes, Triangles, Indices };
enum class Filter { None, Octahedral, Quaternion, Exponential };

/// ext[key] as a whole number in [0, max] (`fallback` when absent and not required), or fail.
std::uint64_t wholeNumber(const Context& ctx, const tinygltf::Value& ext, const char* key,
                          const std::string& element, std::uint64_t max,
                          std::optional<std::uint64_t> fallback = std::nullopt) {
    if (!ext.Has(key)) {
        if (!fallback) ctx.fail(element, cat("required ", key, " is missing"));
        return *fallback;
    }
    const tinygltf::Value& v = ext.Get(key);
    const double d = v.IsNumber() ? v.GetNumberAsDouble() : -1.0;
    if (!(d >= 0.0 && d <= static_cast<double>(max) && d == std::floor(d)))
        ctx.fail(element, cat(key, " is not a whole number in 0..", max));
    return static_cast<std::uint64_t>(d);
}

/// ext[key] as one of `names` (its index), `fallback` when absent, or fail.
template <std::size_t N>
std::size_t choice(const Context& ctx, const tinygltf::Value& ext, const char* key,
                   const std::string& element, const std::array<std::string_view, N>& names,
                   std::optional<std::size_t> fallback) {
    if (!ext.Has(key)) {
        if (!fallback) ctx.fail(element, cat("required ", key, " is missing"));
        return *fallback;
    }
    const tinygltf::Value& v = ext.Get(key);
    if (v.IsString())
        for (std::size_t i = 0; i < N; ++i)
            if (v.Get<std::string>() == names[i]) return i;
    std::string allowed;
    for (std::string_view n : names) allowed += cat(allowed.empty() ? "" : ", ", n);
    ctx.fail(element, cat(key, " is not one of ", allowed));
}

/// The spec's constraints on byteStride and count for the mode and filter; "" when they hold.
std::string strideProblem(Mode mode, Filter filter, std::uint64_t stride, std::uint64_t count) {
    switch (mode) {
    case Mode::Attributes:
        if (stride == 0 || stride > 256 || stride % 4 != 0)
            return cat("ATTRIBUTES needs a byteStride divisible by 4 in 4..256, got ", stride);
        break;
    case Mode::Triangles:
        if (count % 3 != 0) return cat("TRIANGLES needs a count divisible by 3, got ", count);
        [[fallthrough]];
    case Mode::Indices:
        if (stride != 2 && stride != 4)
            return cat(mode == Mode::Triangles ? "TRIANGLES" : "INDICES",
                       " needs byteStride 2 or 4, got ", stride);
        if (filter != Filter::None) return "filters apply only to ATTRIBUTES";
        break;
    }
    if (filter == Filter::Octahedral && stride != 4 && stride != 8)
        return cat("OCTAHEDRAL needs byteStride 4 or 8, got ", stride);
    if (filter == Filter::Quaternion && stride != 8)
        return cat("QUATERNION needs byteStride 8, got ", stride);
    return {};
}

} // namespace

bool isMeshoptFallback(const tinygltf::Buffer& buffer) {
    const auto ext = buffer.extensions.find(kMeshoptExtension);
    if (ext == buffer.extensions.end() || !ext->second.IsObject() || !ext->second.Has("fallback"))
        return false;
    const tinygltf::Value& fallback = ext->second.Get("fallback");
    return fallback.IsBool() && fallback.Get<bool>();
}

namespace {

// The extension's fields, checked against each other, the view and the source buffer.
struct MeshoptSource {
    const tinygltf::Buffer* buffer = nullptr;
    std::uint64_t bufferIndex = 0, offset = 0, length = 0, stride = 0, count = 0;
    Mode mode = Mode::Attributes;
    Filter filter = Filter::None;
};

MeshoptSource readMeshoptSource(const Context& ctx, const tinygltf::Model& model,
                                const tinygltf::BufferView& view, const tinygltf::Value& ext,
                                const std::string& extElement) {
    if (!ext.IsObject()) ctx.fail(extElement, "is not an object");
    MeshoptSource m;
    m.bufferIndex = wholeNumber(ctx, ext, "buffer", extElement, 1u << 30);
    m.buffer = &ctx.lookup(model.buffers, static_cast<int>(m.bufferIndex), extElement, "buffer",
                           "buffers");
    if (isMeshoptFallback(*m.buffer))
        ctx.fail(extElement, cat("reads buffers[", m.bufferIndex, "], a fallback buffer"));
    m.offset = wholeNumber(ctx, ext, "byteOffset", extElement, 1ull << 40, 0);
    m.length = wholeNumber(ctx, ext, "byteLength", extElement, 1ull << 40);
    m.stride = wholeNumber(ctx, ext, "byteStride", extElement, 1u << 30);
    m.count = wholeNumber(ctx, ext, "count", extElement, std::uint64_t{1} << 40);
    m.mode = static_cast<Mode>(choice(
        ctx, ext, "mode", extElement,
        std::array<std::string_view, 3>{"ATTRIBUTES", "TRIANGLES", "INDICES"}, std::nullopt));
    m.filter = static_cast<Filter>(choice(
        ctx, ext, "filter", extElement,
        std::array<std::string_view, 4>{"NONE", "OCTAHEDRAL", "QUATERNION", "EXPONENTIAL"}, 0));

    // Sizes first, all bounded before any multiplication: count by the accessor limit, stride
    // by 256 (strideProblem), so count * stride cannot overflow.
    if (m.count == 0 || m.count > kMaxAccessorCount)
        ctx.fail(extElement, cat("count ", m.count, " outside 1..", kMaxAccessorCount));
    if (const std::string problem = strideProblem(m.mode, m.filter, m.stride, m.count);
        !problem.empty())
        ctx.fail(extElement, problem);
    const std::uint64_t decodedSize = m.count * m.stride;
    if (decodedSize != view.byteLength)
        ctx.fail(extElement, cat("count ", m.count, " * byteStride ", m.stride, " = ", decodedSize,
                                 " bytes, but the bufferView's byteLength is ", view.byteLength));
    if (view.byteStride != 0 && view.byteStride != m.stride)
        ctx.fail(extElement,
                 cat("byteStride ", m.stride, " differs from the bufferView's ", view.byteStride));
    const std::size_t size = m.buffer->data.size();
    if (m.offset > size || m.length > size - m.offset)
        ctx.fail(extElement,
                 cat("byteOffset ", m.offset, " + byteLength ", m.length,
                     " past the end of buffers[", m.bufferIndex, "] (byteLength ", size, ")"));
    return m;
}

// The decoded bytes of a checked source: meshoptimizer's decoder for the mode, then the filter.
std::vector<unsigned char> decodeMeshopt(const Context& ctx, const MeshoptSource& m,
                                         const std::string& extElement) {
    std::vector<unsigned char> decoded(m.count * m.stride);
    const unsigned char* data = m.buffer->data.data() + m.offset;
    int rc = 0;
    switch (m.mode) {
    case Mode::Attributes:
        rc = meshopt_decodeVertexBuffer(decoded.data(), m.count, m.stride, data, m.length);
        break;
    case Mode::Triangles:
        rc = meshopt_decodeIndexBuffer(decoded.data(), m.count, m.stride, data, m.length);
        break;
    case Mode::Indices:
        rc = meshopt_decodeIndexSequence(decoded.data(), m.count, m.stride, data, m.length);
        break;
    }
    if (rc != 0)
        ctx.fail(extElement, cat("compressed data is corrupt (meshoptimizer error ", rc, ")"));
    switch (m.filter) {
    case Filter::None:
        break;
    case Filter::Octahedral:
        meshopt_decodeFilterOct(decoded.data(), m.count, m.stride);
        break;
    case Filter::Quaternion:
        meshopt_decodeFilterQuat(decoded.data(), m.count, m.stride);
        break;
    case Filter::Exponential:
        meshopt_decodeFilterExp(decoded.data(), m.count, m.stride);
        break;
    }
    return decoded;
}

} // namespace

void decodeMeshoptView(const Context& ctx, tinygltf::Model& model, int index) {
    const std::string element = elem("bufferViews", static_cast<std::size_t>(index));
    tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(index)];
    const auto it = view.extensions.find(kMeshoptExtension);
    if (it == view.extensions.end()) {
        // Only compressed views may use a fallback buffer (spec), whose data is never loaded
        // (prepareCompressedJson replaced it with a placeholder).
        if (Context::inRange(model.buffers, view.buffer) &&
            isMeshoptFallback(model.buffers[static_cast<std::size_t>(view.buffer)]))
            ctx.fail(element, cat("uses buffers[", view.buffer,
                                  "], an EXT_meshopt_compression fallback buffer, but is not "
                                  "compressed itself"));
        return;
    }
    const std::string extElement = element + ".extensions.EXT_meshopt_compression";
    const MeshoptSource source = readMeshoptSource(ctx, model, view, it->second, extElement);
    ctx.charge((source.count * source.stride + 3) / 4, extElement);
    std::vector<unsigned char> decoded = decodeMeshopt(ctx, source, extElement);

    // The view now reads the decoded bytes; without the extension it is an ordinary view.
    tinygltf::Buffer buffer;
    buffer.data = std::move(decoded);
    view.buffer = static_cast<int>(model.buffers.size());
    view.byteOffset = 0;
    model.buffers.push_back(std::move(buffer));
    view.extensions.erase(it);
}

} // namespace fl::gltf
