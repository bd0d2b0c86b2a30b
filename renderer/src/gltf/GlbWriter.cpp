// Binary glTF 2.0 output of a Scene: what loadGltf reads back to the same scene. The bytes depend
// only on the scene (sorted JSON keys, fixed layout), so the same scene gives the same file.

#include <renderer/scene/SceneGenerator.h>

#include <geometry/Framing.h>

#include <base/OutputFiles.h>

#include <nlohmann/json.hpp>
#include <stb_image_write.h>

#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>
#include <stdexcept>

namespace fl {

namespace {

using nlohmann::json;

constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;
constexpr int kUnsignedShort = 5123;
constexpr int kUnsignedInt = 5125;
constexpr int kFloat = 5126;

constexpr std::uint32_t kGlbMagic = 0x46546C67;  // "glTF"
constexpr std::uint32_t kChunkJson = 0x4E4F534A; // "JSON"
constexpr std::uint32_t kChunkBin = 0x004E4942;  // "BIN\0"

/// Little-endian byte sink, independent of the host's byte order.
struct Bytes {
    std::vector<std::uint8_t> data;
    void u32(std::uint32_t v) {
        for (int i = 0; i < 4; ++i) data.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
    }
    void u16(std::uint16_t v) {
        data.push_back(static_cast<std::uint8_t>(v));
        data.push_back(static_cast<std::uint8_t>(v >> 8));
    }
    void f32(float v) { u32(std::bit_cast<std::uint32_t>(v)); }
    void pad(std::uint8_t fill) {
        while (data.size() % 4 != 0) data.push_back(fill);
    }
};

json vecJson(const float* v, int n) {
    json a = json::array();
    for (int i = 0; i < n; ++i) a.push_back(static_cast<double>(v[i]));
    return a;
}

json matrixJson(const glm::mat4& m) {
    json a = json::array();
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) a.push_back(static_cast<double>(m[c][r])); // column-major
    return a;
}

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool finiteMatrix(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

[[noreturn]] void invalid(const std::string& what) {
    throw std::invalid_argument("writeGlb: " + what);
}

void validateMesh(const Scene& scene, std::size_t i) {
    const Mesh& m = scene.meshes[i];
    const std::string where = "meshes[" + std::to_string(i) + "] '" + m.name + "': ";
    if (m.positions.empty() || m.indices.empty()) invalid(where + "no triangles");
    if (m.indices.size() % 3 != 0) invalid(where + "index count not a multiple of 3");
    if (!m.normals.empty() && m.normals.size() != m.positions.size())
        invalid(where + "normal count differs from position count");
    if (!m.texcoords.empty() && m.texcoords.size() != m.positions.size())
        invalid(where + "texcoord count differs from position count");
    for (std::uint32_t idx : m.indices)
        if (idx >= m.positions.size())
            invalid(where + "index " + std::to_string(idx) + " past vertex count");
    for (const glm::vec3& p : m.positions)
        if (!finite(p)) invalid(where + "non-finite position");
    if (m.material >= static_cast<int>(scene.materials.size()))
        invalid(where + "material index out of range");
}

/// Rejects what would make an invalid file (or NaNs that JSON cannot hold), naming the element.
void validate(const Scene& scene) {
    for (std::size_t i = 0; i < scene.meshes.size(); ++i) validateMesh(scene, i);
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        const Instance& inst = scene.instances[i];
        if (inst.mesh < 0 || inst.mesh >= static_cast<int>(scene.meshes.size()))
            invalid("instances[" + std::to_string(i) + "]: mesh index out of range");
        if (!finiteMatrix(inst.world))
            invalid("instances[" + std::to_string(i) + "]: non-finite transform");
    }
    for (std::size_t i = 0; i < scene.cameras.size(); ++i) {
        const Camera& cam = scene.cameras[i];
        if (!finiteMatrix(cam.view) || !(cam.yfov > 0.0f) || !(cam.znear > 0.0f))
            invalid("cameras[" + std::to_string(i) + "]: invalid view or projection");
    }
    if (scene.light && (!finite(scene.light->position) || !finite(scene.light->direction) ||
                        glm::dot(scene.light->direction, scene.light->direction) == 0.0f))
        invalid("light: non-finite position or zero direction");
    for (std::size_t i = 0; i < scene.materials.size(); ++i)
        if (scene.materials[i].baseColorTexture >= static_cast<int>(scene.images.size()))
            invalid("materials[" + std::to_string(i) + "]: texture index out of range");
    for (std::size_t i = 0; i < scene.images.size(); ++i) {
        const Image& im = scene.images[i];
        const auto pixels =
            static_cast<std::size_t>(im.width) * static_cast<std::size_t>(im.height);
        if (im.width <= 0 || im.height <= 0 || im.rgba.size() != pixels * 4)
            invalid("images[" + std::to_string(i) + "]: size does not match its pixels");
    }
}

/// The glTF document and its binary buffer, built together.
class Document {
  public:
    json root = json::object();
    Bytes bin;

    /// Starts a buffer view at the next 4-byte boundary; finish it with endView.
    std::size_t beginView() {
        bin.pad(0);
        return bin.data.size();
    }
    int endView(std::size_t offset, std::optional<int> target) {
        json view = {
            {"buffer", 0}, {"byteOffset", offset}, {"byteLength", bin.data.size() - offset}};
        if (target) view["target"] = *target;
        return push("bufferViews", std::move(view));
    }
    int accessor(int view, int componentType, std::size_t count, const char* type) {
        return push("accessors", {{"bufferView", view},
                                  {"componentType", componentType},
                                  {"count", count},
                                  {"type", type}});
    }
    int push(const char* array, json value) {
        json& a = root[array];
        if (a.is_null()) a = json::array();
        a.push_back(std::move(value));
        return static_cast<int>(a.size() - 1);
    }

    int positions(const std::vector<glm::vec3>& v) {
        glm::vec3 lo = v.front();
        glm::vec3 hi = v.front();
        const std::size_t offset = beginView();
        for (const glm::vec3& p : v) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
            bin.f32(p.x), bin.f32(p.y), bin.f32(p.z);
        }
        const int a = accessor(endView(offset, kArrayBuffer), kFloat, v.size(), "VEC3");
        root["accessors"][static_cast<std::size_t>(a)]["min"] = vecJson(&lo.x, 3);
        root["accessors"][static_cast<std::size_t>(a)]["max"] = vecJson(&hi.x, 3);
        return a;
    }
    int vec3s(const std::vector<glm::vec3>& v) {
        const std::size_t offset = beginView();
        for (const glm::vec3& p : v) bin.f32(p.x), bin.f32(p.y), bin.f32(p.z);
        return accessor(endView(offset, kArrayBuffer), kFloat, v.size(), "VEC3");
    }
    int vec2s(const std::vector<glm::vec2>& v) {
        const std::size_t offset = beginView();
        for (const glm::vec2& p : v) bin.f32(p.x), bin.f32(p.y);
        return accessor(endView(offset, kArrayBuffer), kFloat, v.size(), "VEC2");
    }
    int vec4s(const std::vector<glm::vec4>& v) {
        const std::size_t offset = beginView();
        for (const glm::vec4& p : v) bin.f32(p.x), bin.f32(p.y), bin.f32(p.z), bin.f32(p.w);
        return accessor(endView(offset, kArrayBuffer), kFloat, v.size(), "VEC4");
    }
    /// u16 when every index fits below the primitive-restart value 65535, else u32.
    int indices(const std::vector<std::uint32_t>& idx, std::size_t vertexCount) {
        const bool small = vertexCount <= 65535;
        const std::size_t offset = beginView();
        for (std::uint32_t i : idx) small ? bin.u16(static_cast<std::uint16_t>(i)) : bin.u32(i);
        return accessor(endView(offset, kElementArrayBuffer), small ? kUnsignedShort : kUnsignedInt,
                        idx.size(), "SCALAR");
    }
    int png(const Image& image) {
        const std::size_t offset = beginView();
        auto sink = [](void* context, void* data, int size) {
            auto* out = static_cast<Bytes*>(context);
            const auto* p = static_cast<const std::uint8_t*>(data);
            out->data.insert(out->data.end(), p, p + size);
        };
        if (stbi_write_png_to_func(sink, &bin, image.width, image.height, 4, image.rgba.data(),
                                   image.width * 4) == 0)
            throw std::runtime_error("writeGlb: PNG encoding of image '" + image.name + "' failed");
        return endView(offset, std::nullopt);
    }
};

void writeMeshes(Document& doc, const Scene& scene) {
    for (const Mesh& m : scene.meshes) {
        json attributes = {{"POSITION", doc.positions(m.positions)}};
        if (!m.normals.empty()) attributes["NORMAL"] = doc.vec3s(m.normals);
        if (!m.texcoords.empty()) attributes["TEXCOORD_0"] = doc.vec2s(m.texcoords);
        if (!m.colors.empty()) attributes["COLOR_0"] = doc.vec4s(m.colors);
        json primitive = {{"attributes", std::move(attributes)},
                          {"indices", doc.indices(m.indices, m.positions.size())},
                          {"mode", 4}};
        if (m.material >= 0) primitive["material"] = m.material;
        doc.push("meshes", {{"name", m.name}, {"primitives", json::array({std::move(primitive)})}});
    }
}

void writeMaterials(Document& doc, const Scene& scene) {
    for (const Material& mat : scene.materials) {
        // Floodlight shades diffuse surfaces: say so explicitly (glTF's default is metallic 1).
        json pbr = {{"baseColorFactor", vecJson(&mat.baseColorFactor.x, 4)},
                    {"metallicFactor", 0.0},
                    {"roughnessFactor", 1.0}};
        if (mat.baseColorTexture >= 0) pbr["baseColorTexture"] = {{"index", mat.baseColorTexture}};
        json material = {{"name", mat.name}, {"pbrMetallicRoughness", std::move(pbr)}};
        if (mat.doubleSided) material["doubleSided"] = true;
        if (mat.alphaMode == AlphaMode::Mask) {
            material["alphaMode"] = "MASK";
            material["alphaCutoff"] = mat.alphaCutoff;
        } else if (mat.alphaMode == AlphaMode::Blend) {
            material["alphaMode"] = "BLEND";
        }
        doc.push("materials", std::move(material));
    }
    if (scene.images.empty()) return;
    doc.push("samplers",
             {{"magFilter", 9729}, {"minFilter", 9987}, {"wrapS", 10497}, {"wrapT", 10497}});
    for (std::size_t i = 0; i < scene.images.size(); ++i) {
        const Image& image = scene.images[i];
        doc.push("images",
                 {{"name", image.name}, {"mimeType", "image/png"}, {"bufferView", doc.png(image)}});
        doc.push("textures", {{"sampler", 0}, {"source", i}});
    }
}

json lightJson(const Light& light) {
    static constexpr const char* kTypes[] = {"directional", "point", "spot"};
    json j = {{"name", light.name},
              {"type", kTypes[static_cast<int>(light.type)]},
              {"color", vecJson(&light.color.x, 3)},
              {"intensity", static_cast<double>(light.intensity)},
              {"extras", {{"radius", static_cast<double>(light.radius)}}}};
    if (light.type == Light::Type::Spot)
        j["spot"] = {{"innerConeAngle", 0.0},
                     {"outerConeAngle", static_cast<double>(light.outerConeAngle)}};
    return j;
}

/// Node transform whose -Z axis is the light's direction, placed at its position.
glm::mat4 lightMatrix(const Light& light) {
    const glm::vec3 z = -glm::normalize(light.direction);
    const glm::vec3 x = glm::normalize(glm::cross(geom::stableUp(z), z));
    const glm::vec3 y = glm::cross(z, x);
    return glm::mat4(glm::vec4(x, 0.0f), glm::vec4(y, 0.0f), glm::vec4(z, 0.0f),
                     glm::vec4(light.position, 1.0f));
}

void writeNodes(Document& doc, const Scene& scene) {
    json roots = json::array();
    for (const Instance& inst : scene.instances)
        roots.push_back(doc.push(
            "nodes",
            {{"name", inst.nodeName}, {"mesh", inst.mesh}, {"matrix", matrixJson(inst.world)}}));
    for (std::size_t i = 0; i < scene.cameras.size(); ++i) {
        const Camera& cam = scene.cameras[i];
        json perspective = {{"yfov", static_cast<double>(cam.yfov)},
                            {"znear", static_cast<double>(cam.znear)}};
        if (cam.zfar > 0.0f) perspective["zfar"] = static_cast<double>(cam.zfar);
        if (cam.aspectRatio) perspective["aspectRatio"] = static_cast<double>(*cam.aspectRatio);
        doc.push("cameras",
                 {{"name", cam.name}, {"type", "perspective"}, {"perspective", perspective}});
        roots.push_back(doc.push(
            "nodes",
            {{"name", cam.name}, {"camera", i}, {"matrix", matrixJson(glm::inverse(cam.view))}}));
    }
    if (scene.light) {
        doc.root["extensionsUsed"] = json::array({"KHR_lights_punctual"});
        doc.root["extensions"]["KHR_lights_punctual"]["lights"] =
            json::array({lightJson(*scene.light)});
        roots.push_back(
            doc.push("nodes", {{"name", scene.light->name},
                               {"matrix", matrixJson(lightMatrix(*scene.light))},
                               {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}));
    }
    doc.root["scenes"] = json::array({{{"nodes", std::move(roots)}}});
    doc.root["scene"] = 0;
}

std::vector<std::uint8_t> glbBytes(const Scene& scene) {
    Document doc;
    doc.root["asset"] = {{"version", "2.0"}, {"generator", "Floodlight"}};
    writeMeshes(doc, scene);
    writeMaterials(doc, scene);
    writeNodes(doc, scene);
    doc.bin.pad(0);
    if (!doc.bin.data.empty())
        doc.root["buffers"] = json::array({{{"byteLength", doc.bin.data.size()}}});

    Bytes jsonChunk;
    {
        const std::string text = doc.root.dump(-1, ' ', false, json::error_handler_t::replace);
        jsonChunk.data.assign(text.begin(), text.end());
        jsonChunk.pad(' ');
    }
    const bool hasBin = !doc.bin.data.empty();
    const std::size_t total =
        12 + 8 + jsonChunk.data.size() + (hasBin ? 8 + doc.bin.data.size() : 0);
    if (total > 0xFFFFFFFFu)
        throw std::invalid_argument("writeGlb: scene exceeds the 4 GiB GLB limit");

    Bytes out;
    out.data.reserve(total);
    out.u32(kGlbMagic);
    out.u32(2);
    out.u32(static_cast<std::uint32_t>(total));
    out.u32(static_cast<std::uint32_t>(jsonChunk.data.size()));
    out.u32(kChunkJson);
    out.data.insert(out.data.end(), jsonChunk.data.begin(), jsonChunk.data.end());
    if (hasBin) {
        out.u32(static_cast<std::uint32_t>(doc.bin.data.size()));
        out.u32(kChunkBin);
        out.data.insert(out.data.end(), doc.bin.data.begin(), doc.bin.data.end());
    }
    return std::move(out.data);
}

} // namespace

void writeGlb(const Scene& scene, const std::filesystem::path& file) {
    validate(scene);
    const std::vector<std::uint8_t> bytes = glbBytes(scene);
    writeFileAtomically(file, {reinterpret_cast<const char*>(bytes.data()), bytes.size()});
}

} // namespace fl
