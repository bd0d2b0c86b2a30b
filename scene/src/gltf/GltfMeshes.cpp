// Triangle primitives -> fl::Mesh. Rejects what would make a mesh unusable (indices past the
// vertex count, non-finite positions, attribute counts that disagree) and repairs what is safe
// to repair: degenerate triangles are dropped, missing normals generated, broken normals and
// texcoords replaced, each with a warning.

#include "GltfInternal.h"

#include <base/Finite.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace fl::gltf {
namespace {

/// Normal used where geometry defines none (zero-area triangles, unreferenced vertices): any
/// unit vector is as good as another there, and it keeps every normal finite and unit length.
constexpr glm::vec3 kFallbackNormal{0.0f, 0.0f, 1.0f};

std::string_view modeName(int mode) {
    switch (mode) {
    case TINYGLTF_MODE_POINTS:
        return "POINTS";
    case TINYGLTF_MODE_LINE:
        return "LINES";
    case TINYGLTF_MODE_LINE_LOOP:
        return "LINE_LOOP";
    case TINYGLTF_MODE_LINE_STRIP:
        return "LINE_STRIP";
    default:
        return "unknown";
    }
}

/// Unnormalized face normal (twice the area) in double: float cross products of large but
/// finite coordinates overflow.
glm::dvec3 faceNormal(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::dvec3 da(a);
    return glm::cross(glm::dvec3(b) - da, glm::dvec3(c) - da);
}

/// Unit vector along n, or nullopt when n has no usable direction.
std::optional<glm::vec3> unit(const glm::dvec3& n) {
    const double len = glm::length(n);
    if (!std::isfinite(len) || len < 1e-30) return std::nullopt;
    return glm::vec3(n / len);
}

/// The primitive being converted, with the name used in messages.
struct Primitive {
    const tinygltf::Primitive& gltf;
    std::string element; // "meshes[0].primitives[1]"

    [[nodiscard]] int attribute(const char* name) const {
        const auto it = gltf.attributes.find(name);
        return it == gltf.attributes.end() ? -1 : it->second;
    }
    [[nodiscard]] std::string usage(std::string_view attr) const {
        return cat(element, ".attributes.", attr);
    }
};

std::vector<glm::vec3> readPositions(const Context& ctx, const Primitive& prim, int accessor) {
    const std::string usage = prim.usage("POSITION");
    std::vector<glm::vec3> positions = readPositionVec3(ctx, accessor, usage);
    for (std::size_t i = 0; i < positions.size(); ++i)
        if (!geom::allFinite(positions[i]))
            ctx.fail(elem("accessors", static_cast<std::size_t>(accessor)),
                     cat(usage, ": vertex ", i, " is not finite (", positions[i].x, ", ",
                         positions[i].y, ", ", positions[i].z, ")"));
    return positions;
}

/// The primitive's triangle list: its indices (or 0..n-1) checked against the vertex count,
/// converted from strips/fans, degenerate triangles dropped.
std::vector<std::uint32_t> readTriangles(const Context& ctx, const Primitive& prim,
                                         std::size_t vertexCount) {
    std::vector<std::uint32_t> indices;
    if (prim.gltf.indices >= 0) {
        indices = readIndices(ctx, prim.gltf.indices, prim.element + ".indices");
        for (std::uint32_t index : indices)
            if (index >= vertexCount)
                ctx.fail(prim.element, cat("index ", index, " past vertex count ", vertexCount));
    } else {
        indices.resize(vertexCount);
        std::iota(indices.begin(), indices.end(), 0u);
    }
    if (prim.gltf.mode == TINYGLTF_MODE_TRIANGLES && indices.size() % 3 != 0)
        ctx.warn(prim.element, cat(indices.size(), " indices is not a multiple of 3; the last ",
                                   indices.size() % 3, " dropped"));

    std::vector<std::uint32_t> list = triangleList(prim.gltf.mode, indices);
    std::vector<std::uint32_t> kept;
    kept.reserve(list.size());
    for (std::size_t t = 0; t + 2 < list.size(); t += 3) {
        const std::uint32_t a = list[t], b = list[t + 1], c = list[t + 2];
        if (a != b && b != c && a != c) kept.insert(kept.end(), {a, b, c});
    }
    if (const std::size_t dropped = (list.size() - kept.size()) / 3; dropped > 0)
        ctx.warn(prim.element, cat(dropped, " degenerate triangle(s) dropped"));
    return kept;
}

/// Same vertex count as POSITION, or the file is inconsistent (spec 3.7.2.1).
void checkCount(const Context& ctx, const Primitive& prim, std::string_view attr, std::size_t count,
                std::size_t vertexCount) {
    if (count != vertexCount)
        ctx.fail(prim.element,
                 cat(attr, " has ", count, " elements but POSITION has ", vertexCount));
}

/// Normalizes the file's normals; zero or non-finite ones become the area-weighted average of
/// the adjacent face normals.
void repairNormals(const Context& ctx, const Primitive& prim, Mesh& mesh) {
    std::vector<std::size_t> bad;
    for (std::size_t i = 0; i < mesh.normals.size(); ++i) {
        if (auto n = unit(glm::dvec3(mesh.normals[i])))
            mesh.normals[i] = *n;
        else
            bad.push_back(i);
    }
    if (bad.empty()) return;

    std::vector<glm::dvec3> smooth(mesh.positions.size(), glm::dvec3(0.0));
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
        const std::uint32_t* tri = &mesh.indices[t];
        const glm::dvec3 n =
            faceNormal(mesh.positions[tri[0]], mesh.positions[tri[1]], mesh.positions[tri[2]]);
        for (int k = 0; k < 3; ++k) smooth[tri[k]] += n;
    }
    for (std::size_t i : bad) mesh.normals[i] = unit(smooth[i]).value_or(kFallbackNormal);
    ctx.warn(prim.element, cat(bad.size(), " zero or non-finite normal(s) regenerated"));
}

/// `v` with one element per index: the per-vertex data of unshared triangle vertices.
template <class T>
void unshare(std::vector<T>& v, const std::vector<std::uint32_t>& indices) {
    if (v.empty()) return;
    std::vector<T> out;
    out.reserve(indices.size());
    for (std::uint32_t i : indices) out.push_back(v[i]);
    v = std::move(out);
}

/// Flat normals, which glTF requires when NORMAL is absent (spec 3.7.2.1): every triangle gets
/// its own three vertices, and every per-vertex array (skinning and morph deltas included)
/// follows.
void generateFlatNormals(Mesh& mesh) {
    std::vector<glm::vec3> normals;
    normals.reserve(mesh.indices.size());
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
        const std::uint32_t* tri = &mesh.indices[t];
        const glm::vec3 n =
            unit(faceNormal(mesh.positions[tri[0]], mesh.positions[tri[1]], mesh.positions[tri[2]]))
                .value_or(kFallbackNormal);
        normals.insert(normals.end(), {n, n, n});
    }
    unshare(mesh.positions, mesh.indices);
    unshare(mesh.texcoords, mesh.indices);
    unshare(mesh.colors, mesh.indices);
    unshare(mesh.joints, mesh.indices);
    unshare(mesh.weights, mesh.indices);
    for (Mesh::MorphTarget& target : mesh.targets) {
        unshare(target.positions, mesh.indices);
        unshare(target.normals, mesh.indices); // empty: no NORMAL, no NORMAL deltas (GltfSkins)
    }
    mesh.normals = std::move(normals);
    std::iota(mesh.indices.begin(), mesh.indices.end(), 0u);
}

/// The texture coordinates the base colour texture reads: its set (textureInfo.texCoord, or the
/// KHR_texture_transform override) and that extension's offset, rotation and scale.
struct UvMapping {
    int set = 0;
    glm::mat3 transform{1.0f};
};

/// The spec's matrix (KHR_texture_transform README): translation * rotation * scale, the
/// rotation counter-clockwise by `rotation` radians. Bad values are ignored with a warning.
UvMapping uvMapping(const Context& ctx, const Primitive& prim) {
    UvMapping m;
    if (prim.gltf.material < 0) return m;
    const auto& info = ctx.model()
                           .materials[static_cast<std::size_t>(prim.gltf.material)]
                           .pbrMetallicRoughness.baseColorTexture;
    if (info.index < 0) return m;
    m.set = info.texCoord;
    const auto ext = info.extensions.find("KHR_texture_transform");
    if (ext == info.extensions.end() || !ext->second.IsObject()) return m;
    const tinygltf::Value& t = ext->second;
    const std::string element =
        cat(elem("materials", static_cast<std::size_t>(prim.gltf.material)),
            ".pbrMetallicRoughness.baseColorTexture.extensions.KHR_texture_transform");
    auto number = [&](const tinygltf::Value& v, float& out) {
        if (!v.IsNumber() || !std::isfinite(v.GetNumberAsDouble()) ||
            std::abs(v.GetNumberAsDouble()) > 1e6)
            return false;
        out = static_cast<float>(v.GetNumberAsDouble());
        return true;
    };
    auto pair = [&](const char* key, glm::vec2 fallback) {
        if (!t.Has(key)) return fallback;
        const tinygltf::Value& v = t.Get(key);
        glm::vec2 out;
        if (v.IsArray() && v.ArrayLen() == 2 && number(v.Get(0), out.x) && number(v.Get(1), out.y))
            return out;
        ctx.warn(element, cat(key, " is not 2 finite numbers of at most 1e6; ignored"));
        return fallback;
    };
    const glm::vec2 offset = pair("offset", glm::vec2(0.0f)),
                    scale = pair("scale", glm::vec2(1.0f));
    float rotation = 0.0f;
    if (t.Has("rotation") && !number(t.Get("rotation"), rotation)) {
        ctx.warn(element, "rotation is not a finite number of at most 1e6; ignored");
        rotation = 0.0f;
    }
    if (t.Has("texCoord")) {
        const tinygltf::Value& v = t.Get("texCoord");
        if (v.IsInt() && v.GetNumberAsInt() >= 0)
            m.set = v.GetNumberAsInt();
        else
            ctx.warn(element, "texCoord is not a whole number >= 0; ignored");
    }
    const float c = std::cos(rotation), s = std::sin(rotation);
    const glm::mat3 translation(1, 0, 0, 0, 1, 0, offset.x, offset.y, 1);
    const glm::mat3 rotate(c, s, 0, -s, c, 0, 0, 0, 1);
    const glm::mat3 scaling(scale.x, 0, 0, 0, scale.y, 0, 0, 0, 1);
    m.transform = translation * rotate * scaling;
    return m;
}

void attachTexcoords(const Context& ctx, const Primitive& prim, Mesh& mesh) {
    const UvMapping mapping = uvMapping(ctx, prim);
    const std::string attribute = cat("TEXCOORD_", mapping.set);
    const int accessor = prim.attribute(attribute.c_str());
    if (accessor < 0) {
        if (mapping.set != 0)
            ctx.warn(prim.element, cat("its base colour texture reads ", attribute,
                                       ", which it does not have; drawn untextured"));
        return;
    }
    mesh.texcoords = readTexcoords(ctx, accessor, prim.usage(attribute));
    checkCount(ctx, prim, attribute, mesh.texcoords.size(), mesh.positions.size());
    std::size_t repaired = 0;
    for (glm::vec2& uv : mesh.texcoords) {
        uv = glm::vec2(mapping.transform * glm::vec3(uv, 1.0f));
        if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) {
            uv = glm::vec2(0.0f);
            ++repaired;
        }
    }
    if (repaired > 0)
        ctx.warn(prim.element, cat(repaired, " non-finite texcoord(s) set to (0, 0)"));
}

/// COLOR_0, which multiplies the base colour and its alpha (spec 3.9.2); values outside [0, 1] are
/// clamped and non-finite ones made white, with a warning.
void attachColors(const Context& ctx, const Primitive& prim, Mesh& mesh) {
    const int accessor = prim.attribute("COLOR_0");
    if (accessor < 0) return;
    mesh.colors = readColors(ctx, accessor, prim.usage("COLOR_0"));
    checkCount(ctx, prim, "COLOR_0", mesh.colors.size(), mesh.positions.size());
    std::size_t repaired = 0;
    for (glm::vec4& c : mesh.colors) {
        glm::vec4 fixed = c;
        for (int k = 0; k < 4; ++k)
            fixed[k] = std::isfinite(c[k]) ? std::clamp(c[k], 0.0f, 1.0f) : 1.0f;
        if (fixed != c) ++repaired;
        c = fixed;
    }
    if (repaired > 0)
        ctx.warn(prim.element,
                 cat(repaired, " COLOR_0 value(s) outside [0, 1] or not finite repaired"));
}

/// The fl::Mesh of one triangle primitive, or nullopt (with a warning) when it has nothing to
/// draw.
std::optional<Mesh> convertPrimitive(const Context& ctx, const Primitive& prim) {
    const int mode = prim.gltf.mode;
    if (mode >= TINYGLTF_MODE_POINTS && mode <= TINYGLTF_MODE_LINE_STRIP) {
        ctx.warn(prim.element,
                 cat(modeName(mode), " primitive skipped (only triangles are drawn)"));
        return std::nullopt;
    }
    if (mode < TINYGLTF_MODE_TRIANGLES || mode > TINYGLTF_MODE_TRIANGLE_FAN)
        ctx.fail(prim.element, cat("invalid mode ", mode));
    const int positionAccessor = prim.attribute("POSITION");
    if (positionAccessor < 0) {
        ctx.warn(prim.element, "no POSITION attribute; primitive skipped");
        return std::nullopt;
    }

    Mesh mesh;
    if (prim.gltf.material != -1)
        ctx.lookup(ctx.model().materials, prim.gltf.material, prim.element, "material",
                   "materials");
    mesh.material = prim.gltf.material;
    mesh.positions = readPositions(ctx, prim, positionAccessor);
    mesh.indices = readTriangles(ctx, prim, mesh.positions.size());
    if (mesh.indices.empty()) {
        ctx.warn(prim.element, "no triangles; primitive skipped");
        return std::nullopt;
    }
    attachTexcoords(ctx, prim, mesh);
    attachColors(ctx, prim, mesh);
    attachSkinning(ctx, prim.gltf, prim.element, mesh);
    attachMorphTargets(ctx, prim.gltf, prim.element, mesh);
    if (const int normals = prim.attribute("NORMAL"); normals >= 0) {
        mesh.normals = readNormalVec3(ctx, normals, prim.usage("NORMAL"));
        checkCount(ctx, prim, "NORMAL", mesh.normals.size(), mesh.positions.size());
        repairNormals(ctx, prim, mesh);
    } else {
        generateFlatNormals(mesh);
    }
    return mesh;
}

} // namespace

std::vector<std::uint32_t> triangleList(int mode, const std::vector<std::uint32_t>& indices) {
    std::vector<std::uint32_t> out;
    const std::size_t n = indices.size();
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        out.assign(indices.begin(), indices.begin() + static_cast<std::ptrdiff_t>(n - n % 3));
        return out;
    }
    if (n < 3) return out;
    out.reserve(3 * (n - 2));
    for (std::size_t i = 0; i + 2 < n; ++i) {
        if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) // {v_i, v_i+(1+i%2), v_i+(2-i%2)}
            out.insert(out.end(), {indices[i], indices[i + 1 + i % 2], indices[i + 2 - i % 2]});
        else // fan: {v_i+1, v_i+2, v_0}
            out.insert(out.end(), {indices[i + 1], indices[i + 2], indices[0]});
    }
    return out;
}

std::size_t morphTargetCount(const Context& ctx, int meshIndex) {
    const tinygltf::Mesh& mesh = ctx.model().meshes[static_cast<std::size_t>(meshIndex)];
    const std::size_t count = mesh.primitives.empty() ? 0 : mesh.primitives[0].targets.size();
    if (count > kMaxFileMorphTargets)
        ctx.fail(elem("meshes", static_cast<std::size_t>(meshIndex)),
                 cat("absurd morph target count ", count, " (limit ", kMaxFileMorphTargets, ")"));
    if (count > fl::kMaxMorphTargets)
        ctx.warn(elem("meshes", static_cast<std::size_t>(meshIndex)),
                 cat(count, " morph targets: the first ", fl::kMaxMorphTargets,
                     " are drawn (the vertex stage's limit), the rest ignored"));
    // One weight per target drives every primitive at once (spec 3.7.2.2).
    for (std::size_t p = 1; p < mesh.primitives.size(); ++p)
        if (mesh.primitives[p].targets.size() != count)
            ctx.fail(
                cat(elem("meshes", static_cast<std::size_t>(meshIndex)), elem(".primitives", p)),
                cat(mesh.primitives[p].targets.size(), " morph targets but primitives[0] has ",
                    count));
    return count;
}

void convertMesh(const Context& ctx, int meshIndex, std::vector<Mesh>& out) {
    const tinygltf::Mesh& mesh = ctx.model().meshes[static_cast<std::size_t>(meshIndex)];
    const std::string element = elem("meshes", static_cast<std::size_t>(meshIndex));
    std::vector<float> weights =
        defaultMorphWeights(ctx, meshIndex, morphTargetCount(ctx, meshIndex));
    if (weights.size() > fl::kMaxMorphTargets) weights.resize(fl::kMaxMorphTargets);
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
        const Primitive prim{mesh.primitives[p], element + elem(".primitives", p)};
        std::optional<Mesh> converted = convertPrimitive(ctx, prim);
        if (!converted) continue;
        converted->morphWeights = weights;
        converted->name = mesh.name.empty() ? element : mesh.name;
        if (mesh.primitives.size() > 1) converted->name += elem(".primitives", p);
        out.push_back(std::move(*converted));
    }
}

} // namespace fl::gltf
