// Accessor, bufferView and buffer validation and decoding. tinygltf checks none of the byte
// ranges, so every read here is preceded by an overflow-safe range check, and element bytes are
// copied with memcpy (glTF data need not be aligned for our types).

#include "GltfInternal.h"

#include <algorithm>
#include <cstring>
#include <limits>

namespace fl::gltf {
namespace {

std::string_view componentTypeName(int componentType) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
        return "BYTE";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return "UNSIGNED_BYTE";
    case TINYGLTF_COMPONENT_TYPE_SHORT:
        return "SHORT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return "UNSIGNED_SHORT";
    case TINYGLTF_COMPONENT_TYPE_INT:
        return "INT";
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        return "UNSIGNED_INT";
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return "FLOAT";
    case TINYGLTF_COMPONENT_TYPE_DOUBLE:
        return "DOUBLE";
    default:
        return "invalid component type";
    }
}

std::string_view typeName(int type) {
    switch (type) {
    case TINYGLTF_TYPE_SCALAR:
        return "SCALAR";
    case TINYGLTF_TYPE_VEC2:
        return "VEC2";
    case TINYGLTF_TYPE_VEC3:
        return "VEC3";
    case TINYGLTF_TYPE_VEC4:
        return "VEC4";
    case TINYGLTF_TYPE_MAT2:
        return "MAT2";
    case TINYGLTF_TYPE_MAT3:
        return "MAT3";
    case TINYGLTF_TYPE_MAT4:
        return "MAT4";
    default:
        return "invalid type";
    }
}

/// Bytes per component of the component types glTF 2.0 allows in accessors; 0 for the others
/// (tinygltf also lets INT and DOUBLE through).
std::size_t componentSize(int componentType) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return 4;
    default:
        return 0;
    }
}

/// a + b and a * b that report overflow instead of wrapping.
bool addOk(std::uint64_t a, std::uint64_t b, std::uint64_t& out) {
    return !__builtin_add_overflow(a, b, &out);
}
bool mulOk(std::uint64_t a, std::uint64_t b, std::uint64_t& out) {
    return !__builtin_mul_overflow(a, b, &out);
}

/// What a validated accessor reads from: `count` elements of `components` components each,
/// element i at data + i * stride (data == nullptr: no bufferView, all zeros).
struct AccessorView {
    std::string element; // "accessors[3]"
    const tinygltf::Accessor* accessor = nullptr;
    const std::uint8_t* data = nullptr;
    std::size_t stride = 0;
    std::size_t count = 0;
    std::size_t components = 0;
};

/// One component as a float; normalized integers map to [0, 1] / [-1, 1] (spec 3.11).
float readComponent(const std::uint8_t* p, int componentType, bool normalized) {
    auto load = [p]<class T>(T) {
        T v;
        std::memcpy(&v, p, sizeof v);
        return v;
    };
    auto norm = [normalized](auto v, float maxValue) {
        const float f = static_cast<float>(v);
        return normalized ? std::max(f / maxValue, -1.0f) : f;
    };
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
        return norm(load(std::int8_t{}), 127.0f);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return norm(load(std::uint8_t{}), 255.0f);
    case TINYGLTF_COMPONENT_TYPE_SHORT:
        return norm(load(std::int16_t{}), 32767.0f);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return norm(load(std::uint16_t{}), 65535.0f);
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return load(float{});
    default:
        return 0.0f; // unreachable: componentSize() rejected the type
    }
}

/// Integer component (indices); exact for u32 unlike the float path.
std::uint32_t readIndexComponent(const std::uint8_t* p, int componentType) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return *p;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        std::uint16_t v;
        std::memcpy(&v, p, sizeof v);
        return v;
    }
    default: {
        std::uint32_t v;
        std::memcpy(&v, p, sizeof v);
        return v;
    }
    }
}

/// Checks that `offset + stride * (count - 1) + elementSize` bytes fit in a bufferView.
void checkRange(const Context& ctx, const std::string& element, std::uint64_t offset,
                std::uint64_t stride, std::uint64_t count, std::uint64_t elementSize, int viewIndex,
                std::size_t viewLength) {
    if (count == 0) return;
    std::uint64_t span = 0, end = 0;
    const bool ok = mulOk(stride, count - 1, span) && addOk(span, elementSize, span) &&
                    addOk(offset, span, end);
    if (!ok || end > viewLength)
        ctx.fail(element, cat("byteOffset ", offset, " + stride ", stride, " * (count ", count,
                              " - 1) + element size ", elementSize, " = ",
                              ok ? std::to_string(end) : std::string("overflow"),
                              " bytes, past the end of bufferViews[", viewIndex, "] (byteLength ",
                              viewLength, ")"));
}

/// Overwrites the elements a sparse accessor names (spec 3.6.2.3). `write(i, p)` stores
/// element i from the bytes at p.
template <class Write>
void applySparse(const Context& ctx, const AccessorView& view, std::size_t elementSize,
                 Write write) {
    const auto& sparse = view.accessor->sparse;
    const std::string element = view.element + ".sparse";
    if (sparse.count < 1 || static_cast<std::size_t>(sparse.count) > view.count)
        ctx.fail(element, cat("count ", sparse.count, " outside 1..", view.count));
    const auto count = static_cast<std::size_t>(sparse.count);
    const int indexType = sparse.indices.componentType;
    const std::size_t indexSize = componentSize(indexType);
    if (indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        ctx.fail(element + ".indices",
                 cat("componentType ", indexType, " is not UNSIGNED_BYTE/SHORT/INT"));
    if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0)
        ctx.fail(element, "negative byteOffset");

    const ByteSpan indices = bufferViewBytes(ctx, sparse.indices.bufferView, element + ".indices");
    const ByteSpan values = bufferViewBytes(ctx, sparse.values.bufferView, element + ".values");
    // Sparse data is tightly packed: the views' byteStride does not apply.
    checkRange(ctx, element + ".indices", static_cast<std::uint64_t>(sparse.indices.byteOffset),
               indexSize, count, indexSize, sparse.indices.bufferView, indices.size);
    checkRange(ctx, element + ".values", static_cast<std::uint64_t>(sparse.values.byteOffset),
               elementSize, count, elementSize, sparse.values.bufferView, values.size);

    const std::uint8_t* ip = indices.data + sparse.indices.byteOffset;
    const std::uint8_t* vp = values.data + sparse.values.byteOffset;
    for (std::size_t k = 0; k < count; ++k) {
        const std::uint32_t target = readIndexComponent(ip + k * indexSize, indexType);
        if (target >= view.count)
            ctx.fail(element + ".indices",
                     cat("index ", target, " past accessor count ", view.count));
        write(target, vp + k * elementSize);
    }
}

/// Validates accessors[index] for `usage`: allowed type and component types, the bufferView
/// and buffer it reads, and the byte range of all its elements.
AccessorView viewAccessor(const Context& ctx, int index, std::string_view usage, int type,
                          std::initializer_list<int> componentTypes) {
    const auto& model = ctx.model();
    AccessorView view;
    view.accessor = &ctx.lookup(model.accessors, index, usage, "accessor", "accessors");
    const tinygltf::Accessor& acc = *view.accessor;
    view.element = elem("accessors", static_cast<std::size_t>(index));

    const bool typeOk = acc.type == type;
    const bool componentOk = std::find(componentTypes.begin(), componentTypes.end(),
                                       acc.componentType) != componentTypes.end();
    if (!typeOk || !componentOk) {
        std::string allowed;
        for (int c : componentTypes)
            allowed += cat(allowed.empty() ? "" : "/", componentTypeName(c));
        ctx.fail(view.element, cat(usage, " needs ", typeName(type), ' ', allowed, ", got ",
                                   typeName(acc.type), ' ', componentTypeName(acc.componentType)));
    }
    if (acc.count > kMaxAccessorCount)
        ctx.fail(view.element, cat("absurd count ", acc.count, " (limit ", kMaxAccessorCount, ")"));

    view.count = acc.count;
    view.components = static_cast<std::size_t>(
        tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(acc.type)));
    ctx.charge(view.count * view.components, view.element);
    const std::size_t elementSize = view.components * componentSize(acc.componentType);
    view.stride = elementSize;
    if (acc.bufferView < 0) return view; // zeros (plus sparse substitutions), spec 3.6.2.2

    const ByteSpan bytes = bufferViewBytes(ctx, acc.bufferView, view.element);
    const tinygltf::BufferView& bv = model.bufferViews[static_cast<std::size_t>(acc.bufferView)];
    if (bv.byteStride != 0) {
        if (bv.byteStride < elementSize || bv.byteStride % componentSize(acc.componentType) != 0)
            ctx.fail(elem("bufferViews", static_cast<std::size_t>(acc.bufferView)),
                     cat("byteStride ", bv.byteStride, " does not fit ", view.element,
                         " (element size ", elementSize, ")"));
        view.stride = bv.byteStride;
    }
    checkRange(ctx, view.element, acc.byteOffset, view.stride, view.count, elementSize,
               acc.bufferView, bytes.size);
    if (view.count > 0) view.data = bytes.data + acc.byteOffset;
    return view;
}

/// All components of the accessor as floats, sparse substitutions applied.
std::vector<float> readFloats(const Context& ctx, const AccessorView& view) {
    const tinygltf::Accessor& acc = *view.accessor;
    const std::size_t size = componentSize(acc.componentType);
    std::vector<float> out(view.count * view.components, 0.0f);
    auto readElement = [&](std::size_t i, const std::uint8_t* p) {
        for (std::size_t c = 0; c < view.components; ++c)
            out[i * view.components + c] =
                readComponent(p + c * size, acc.componentType, acc.normalized);
    };
    if (view.data)
        for (std::size_t i = 0; i < view.count; ++i) readElement(i, view.data + i * view.stride);
    if (acc.sparse.isSparse) applySparse(ctx, view, view.components * size, readElement);
    return out;
}

} // namespace

ByteSpan bufferViewBytes(const Context& ctx, int index, std::string_view usage) {
    const auto& model = ctx.model();
    const auto& bv = ctx.lookup(model.bufferViews, index, usage, "bufferView", "bufferViews");
    const std::string element = elem("bufferViews", static_cast<std::size_t>(index));
    const auto& buffer = ctx.lookup(model.buffers, bv.buffer, element, "buffer", "buffers");
    std::uint64_t end = 0;
    if (!addOk(bv.byteOffset, bv.byteLength, end) || end > buffer.data.size())
        ctx.fail(element, cat("byteOffset ", bv.byteOffset, " + byteLength ", bv.byteLength,
                              " past the end of buffers[", bv.buffer, "] (byteLength ",
                              buffer.data.size(), ")"));
    return {buffer.data.data() + bv.byteOffset, bv.byteLength};
}

bool usesExtension(const Context& ctx, std::string_view name) {
    const auto& used = ctx.model().extensionsUsed;
    return std::find(used.begin(), used.end(), name) != used.end();
}

namespace {

constexpr int kByte = TINYGLTF_COMPONENT_TYPE_BYTE, kUByte = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
              kShort = TINYGLTF_COMPONENT_TYPE_SHORT,
              kUShort = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
              kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;

/// Fails unless an integer accessor is normalized where `usage` needs it to be.
void requireNormalized(const Context& ctx, const AccessorView& view, std::string_view usage,
                       std::string_view why) {
    const tinygltf::Accessor& acc = *view.accessor;
    if (acc.componentType != kFloat && !acc.normalized)
        ctx.fail(view.element,
                 cat(usage, " with component type ", componentTypeName(acc.componentType),
                     " must be normalized (", why, ")"));
}

std::vector<glm::vec3> vec3s(const Context& ctx, const AccessorView& view) {
    const std::vector<float> f = readFloats(ctx, view);
    std::vector<glm::vec3> out(view.count);
    for (std::size_t i = 0; i < view.count; ++i) out[i] = {f[3 * i], f[3 * i + 1], f[3 * i + 2]};
    return out;
}

} // namespace

std::vector<glm::vec3> readPositionVec3(const Context& ctx, int index, std::string_view usage) {
    // KHR_mesh_quantization: integer positions, scaled back to the model by the node's
    // transform (the extension's whole point), so they are read as they are.
    const bool quantized = usesExtension(ctx, "KHR_mesh_quantization");
    return vec3s(ctx, quantized ? viewAccessor(ctx, index, usage, TINYGLTF_TYPE_VEC3,
                                               {kFloat, kByte, kUByte, kShort, kUShort})
                                : viewAccessor(ctx, index, usage, TINYGLTF_TYPE_VEC3, {kFloat}));
}

std::vector<glm::vec3> readNormalVec3(const Context& ctx, int index, std::string_view usage) {
    if (!usesExtension(ctx, "KHR_mesh_quantization"))
        return vec3s(ctx, viewAccessor(ctx, index, usage, TINYGLTF_TYPE_VEC3, {kFloat}));
    const AccessorView view =
        viewAccessor(ctx, index, usage, TINYGLTF_TYPE_VEC3, {kFloat, kByte, kShort});
    requireNormalized(ctx, view, usage, "KHR_mesh_quantization");
    return vec3s(ctx, view);
}

std::vector<glm::vec2> readTexcoords(const Context& ctx, int index, std::string_view usage) {
    const bool quantized = usesExtension(ctx, "KHR_mesh_quantization");
    const AccessorView view =
        quantized ? viewAccessor(ctx, index, usage, TINYGLTF_TYPE_VEC2,
                                 {kFloat, kByte, kUByte, kShort, kUShort})
                  : viewAccessor(ctx, index, usage, TINYGLTF_TYPE_VEC2, {kFloat, kUByte, kUShort});
    // Integer texcoords are only meaningful normalized in the core spec (3.7.2.1); unnormalized
    // ones belong to KHR_mesh_quantization, where KHR_texture_transform scales them (applied by
    // GltfMeshes.cpp, attachTexcoords).
    if (!quantized)
        requireNormalized(ctx, view, usage, "core glTF; KHR_mesh_quantization allows it");

    const std::vector<float> f = readFloats(ctx, view);
    std::vector<glm::vec2> out(view.count);
    for (std::size_t i = 0; i < view.count; ++i) out[i] = {f[2 * i], f[2 * i + 1]};
    return out;
}

std::vector<glm::vec4> readColors(const Context& ctx, int index, std::string_view usage) {
    const auto& acc = ctx.lookup(ctx.model().accessors, index, usage, "accessor", "accessors");
    const int type = acc.type == TINYGLTF_TYPE_VEC3 ? TINYGLTF_TYPE_VEC3 : TINYGLTF_TYPE_VEC4;
    const AccessorView view = viewAccessor(ctx, index, usage, type, {kFloat, kUByte, kUShort});
    requireNormalized(ctx, view, usage, "core glTF, 3.7.2.1");
    const std::vector<float> f = readFloats(ctx, view);
    std::vector<glm::vec4> out(view.count, glm::vec4(1.0f));
    for (std::size_t i = 0; i < view.count; ++i)
        for (std::size_t c = 0; c < view.components; ++c)
            out[i][static_cast<int>(c)] = f[i * view.components + c];
    return out;
}

std::vector<glm::vec3> readTargetPositionVec3(const Context& ctx, int index,
                                              std::string_view usage) {
    // KHR_mesh_quantization lets position deltas be signed integers, normalized or not.
    const bool quantized = usesExtension(ctx, "KHR_mesh_quantization");
    return vec3s(ctx, quantized ? viewAccessor(ctx, index, usage, TINYGLTF_TYPE_VEC3,
                                               {kFloat, kByte, kShort})
                                : viewAccessor(ctx, index, usage, TINYGLTF_TYPE_VEC3, {kFloat}));
}

std::vector<glm::uvec4> readJoints(const Context& ctx, int index, std::string_view usage) {
    const AccessorView view =
        viewAccessor(ctx, index, usage, TINYGLTF_TYPE_VEC4, {kUByte, kUShort});
    const int type = view.accessor->componentType;
    const std::size_t size = componentSize(type);
    std::vector<glm::uvec4> out(view.count, glm::uvec4(0));
    // Read as integers: joint indices are indices even if a file marks them normalized.
    auto readElement = [&](std::size_t i, const std::uint8_t* p) {
        for (int c = 0; c < 4; ++c)
            out[i][c] = readIndexComponent(p + static_cast<std::size_t>(c) * size, type);
    };
    if (view.data)
        for (std::size_t i = 0; i < view.count; ++i) readElement(i, view.data + i * view.stride);
    if (view.accessor->sparse.isSparse) applySparse(ctx, view, 4 * size, readElement);
    return out;
}

std::vector<glm::vec4> readWeights(const Context& ctx, int index, std::string_view usage) {
    const AccessorView view =
        viewAccessor(ctx, index, usage, TINYGLTF_TYPE_VEC4, {kFloat, kUByte, kUShort});
    requireNormalized(ctx, view, usage, "core glTF, 3.7.3.3");
    const std::vector<float> f = readFloats(ctx, view);
    std::vector<glm::vec4> out(view.count);
    for (std::size_t i = 0; i < view.count; ++i)
        out[i] = {f[4 * i], f[4 * i + 1], f[4 * i + 2], f[4 * i + 3]};
    return out;
}

std::vector<glm::mat4> readMat4(const Context& ctx, int index, std::string_view usage) {
    const std::vector<float> f =
        readFloats(ctx, viewAccessor(ctx, index, usage, TINYGLTF_TYPE_MAT4, {kFloat}));
    std::vector<glm::mat4> out(f.size() / 16);
    for (std::size_t i = 0; i < out.size(); ++i)
        std::memcpy(&out[i][0][0], &f[16 * i], 16 * sizeof(float)); // both column-major
    return out;
}

std::vector<float> readAnimationFloats(const Context& ctx, int index, std::string_view usage,
                                       int type, bool normalizedIntegers) {
    if (!normalizedIntegers)
        return readFloats(ctx, viewAccessor(ctx, index, usage, type, {kFloat}));
    const AccessorView view =
        viewAccessor(ctx, index, usage, type, {kFloat, kByte, kUByte, kShort, kUShort});
    requireNormalized(ctx, view, usage, "core glTF, 3.11");
    return readFloats(ctx, view);
}

std::vector<std::uint32_t> readIndices(const Context& ctx, int index, std::string_view usage) {
    const AccessorView view =
        viewAccessor(ctx, index, usage, TINYGLTF_TYPE_SCALAR,
                     {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                      TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT});
    const int type = view.accessor->componentType;
    std::vector<std::uint32_t> out(view.count, 0);
    auto readElement = [&](std::size_t i, const std::uint8_t* p) {
        out[i] = readIndexComponent(p, type);
    };
    if (view.data)
        for (std::size_t i = 0; i < view.count; ++i) readElement(i, view.data + i * view.stride);
    if (view.accessor->sparse.isSparse) applySparse(ctx, view, componentSize(type), readElement);
    return out;
}

} // namespace fl::gltf
