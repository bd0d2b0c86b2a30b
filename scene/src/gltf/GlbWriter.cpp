// Binary glTF 2.0 output of a Scene: what loadGltf reads back to the same scene. The bytes depend
// only on the scene (sorted JSON keys, fixed layout), so the same scene gives the same file.
// Animation data (Scene::nodes, skins, animations, skinning and morph targets) is written when
// the scene has it; a scene without nodes is written as before, one root node per instance.

#include <scene/SceneGenerator.h>

#include <base/Finite.h>
#include <base/Framing.h>
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
        if (!geom::allFinite(p)) invalid(where + "non-finite position");
    if (m.material >= static_cast<int>(scene.materials.size()))
        invalid(where + "material index out of range");
}

template <class T>
bool inRange(const std::vector<T>& v, int i) {
    return i >= 0 && static_cast<std::size_t>(i) < v.size();
}

/// Skinning and morph data: per-vertex arrays of the right size (the loader's promises).
void validateRigging(const Mesh& m, const std::string& where) {
    if (m.joints.size() != m.weights.size() ||
        (!m.joints.empty() && m.joints.size() != m.positions.size()))
        invalid(where + "joint or weight count differs from position count");
    for (const glm::uvec4& j : m.joints)
        if (glm::any(glm::greaterThan(j, glm::uvec4(65535))))
            invalid(where + "joint index above 65535");
    if (m.morphWeights.size() != m.targets.size())
        invalid(where + "morph weight count differs from target count");
    for (const Mesh::MorphTarget& t : m.targets)
        if ((!t.positions.empty() && t.positions.size() != m.positions.size()) ||
            (!t.normals.empty() && t.normals.size() != m.positions.size()))
            invalid(where + "morph target size differs from position count");
}

/// Nodes, skins and animations index what exists.
void validateAnimation(const Scene& scene) {
    for (std::size_t i = 0; i < scene.nodes.size(); ++i) {
        const int parent = scene.nodes[i].parent;
        if (parent != -1 && (!inRange(scene.nodes, parent) || parent == static_cast<int>(i)))
            invalid("nodes[" + std::to_string(i) + "]: parent out of range");
    }
    for (std::size_t i = 0; i < scene.skins.size(); ++i) {
        const Skin& skin = scene.skins[i];
        if (skin.joints.empty() || skin.inverseBind.size() != skin.joints.size())
            invalid("skins[" + std::to_string(i) + "]: no joints or inverse bind count differs");
        for (int j : skin.joints)
            if (!inRange(scene.nodes, j))
                invalid("skins[" + std::to_string(i) + "]: joint out of range");
    }
    for (std::size_t i = 0; i < scene.animations.size(); ++i) {
        const Animation& a = scene.animations[i];
        const std::string where = "animations[" + std::to_string(i) + "]: ";
        for (const Animation::Channel& c : a.channels)
            if (!inRange(scene.nodes, c.node) || !inRange(a.samplers, c.sampler))
                invalid(where + "channel node or sampler out of range");
        for (const Animation::Sampler& s : a.samplers) {
            const std::size_t perKey =
                s.interpolation == Animation::Interpolation::CubicSpline ? 3 : 1;
            if (s.times.empty() || s.width <= 0 ||
                s.values.size() != s.times.size() * perKey * static_cast<std::size_t>(s.width))
                invalid(where + "sampler values do not match its times");
        }
    }
}

/// Rejects what would make an invalid file (or NaNs that JSON cannot hold), naming the element.
void validate(const Scene& scene) {
    for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
        validateMesh(scene, i);
        validateRigging(scene.meshes[i], "meshes[" + std::to_string(i) + "]: ");
    }
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        const Instance& inst = scene.instances[i];
        if (inst.mesh < 0 || inst.mesh >= static_cast<int>(scene.meshes.size()))
            invalid("instances[" + std::to_string(i) + "]: mesh index out of range");
        if (!geom::allFinite(inst.world))
            invalid("instances[" + std::to_string(i) + "]: non-finite transform");
        if ((inst.node != -1 && !inRange(scene.nodes, inst.node)) ||
            (inst.skin != -1 && !inRange(scene.skins, inst.skin)))
            invalid("instances[" + std::to_string(i) + "]: node or skin index out of range");
    }
    validateAnimation(scene);
    for (std::size_t i = 0; i < scene.cameras.size(); ++i) {
        const Camera& cam = scene.cameras[i];
        if (!geom::allFinite(cam.view) || !(cam.yfov > 0.0f) || !(cam.znear > 0.0f))
            invalid("cameras[" + std::to_string(i) + "]: invalid view or projection");
    }
    if (scene.light &&
        (!geom::allFinite(scene.light->position) || !geom::allFinite(scene.light->direction) ||
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
    /// `values` as one FLOAT accessor of `type` (`components` floats per element).
    int floats(const std::vector<float>& values, const char* type, std::size_t components) {
        const std::size_t offset = beginView();
        for (float v : values) bin.f32(v);
        return accessor(endView(offset, std::nullopt), kFloat, values.size() / components, type);
    }
    int mat4s(const std::vector<glm::mat4>& v) {
        const std::size_t offset = beginView();
        for (const glm::mat4& m : v)
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r) bin.f32(m[c][r]); // column-major
        return accessor(endView(offset, std::nullopt), kFloat, v.size(), "MAT4");
    }
    /// JOINTS_0 as UNSIGNED_SHORT (indices above 65535 cannot be written; validate() refuses).
    int joints(const std::vector<glm::uvec4>& v) {
        const std::size_t offset = beginView();
        for (const glm::uvec4& j : v)
            for (int k = 0; k < 4; ++k) bin.u16(static_cast<std::uint16_t>(j[k]));
        return accessor(endView(offset, kArrayBuffer), kUnsignedShort, v.size(), "VEC4");
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

/// One glTF mesh per Mesh (meshes[i] is scene.meshes[i]); returns each one's primitive, which
/// writeAnimatedNodes combines for nodes that place several.
std::vector<json> writeMeshes(Document& doc, const Scene& scene) {
    std::vector<json> primitives;
    for (const Mesh& m : scene.meshes) {
        json attributes = {{"POSITION", doc.positions(m.positions)}};
        if (!m.normals.empty()) attributes["NORMAL"] = doc.vec3s(m.normals);
        if (!m.texcoords.empty()) attributes["TEXCOORD_0"] = doc.vec2s(m.texcoords);
        if (!m.colors.empty()) attributes["COLOR_0"] = doc.vec4s(m.colors);
        if (!m.joints.empty()) {
            attributes["JOINTS_0"] = doc.joints(m.joints);
            attributes["WEIGHTS_0"] = doc.vec4s(m.weights);
        }
        json primitive = {{"attributes", std::move(attributes)},
                          {"indices", doc.indices(m.indices, m.positions.size())},
                          {"mode", 4}};
        if (m.material >= 0) primitive["material"] = m.material;
        for (const Mesh::MorphTarget& t : m.targets) {
            json target = json::object();
            if (!t.positions.empty()) target["POSITION"] = doc.vec3s(t.positions);
            if (!t.normals.empty()) target["NORMAL"] = doc.vec3s(t.normals);
            primitive["targets"].push_back(std::move(target));
        }
        json mesh = {{"name", m.name}, {"primitives", json::array({primitive})}};
        if (!m.morphWeights.empty()) mesh["weights"] = m.morphWeights;
        doc.push("meshes", std::move(mesh));
        primitives.push_back(std::move(primitive));
    }
    return primitives;
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

/// Scene::nodes as nodes[0..n) (so that skins and channels keep their indices) with the meshes
/// their instances place: a node placing one Mesh gets its glTF mesh, a node placing several (a
/// multi-primitive mesh of the source file) a new glTF mesh holding their primitives. Appends the
/// root nodes to `roots`.
void writeNodeTree(Document& doc, const Scene& scene, const std::vector<json>& primitives,
                   json& roots) {
    std::vector<std::vector<const Instance*>> placed(scene.nodes.size());
    for (const Instance& inst : scene.instances)
        if (inst.node >= 0) placed[static_cast<std::size_t>(inst.node)].push_back(&inst);
    std::vector<json> children(scene.nodes.size(), json::array());
    for (std::size_t i = 0; i < scene.nodes.size(); ++i) {
        const int parent = scene.nodes[i].parent;
        (parent >= 0 ? children[static_cast<std::size_t>(parent)] : roots).push_back(i);
    }
    for (std::size_t i = 0; i < scene.nodes.size(); ++i) {
        const Node& n = scene.nodes[i];
        json node = {{"name", n.name}};
        if (n.matrix) {
            node["matrix"] = matrixJson(*n.matrix);
        } else {
            const glm::vec4 q(n.rotation.x, n.rotation.y, n.rotation.z, n.rotation.w);
            node["translation"] = vecJson(&n.translation.x, 3);
            node["rotation"] = vecJson(&q.x, 4); // glTF order x, y, z, w
            node["scale"] = vecJson(&n.scale.x, 3);
        }
        if (!children[i].empty()) node["children"] = std::move(children[i]);
        if (!n.weights.empty()) node["weights"] = n.weights;
        const std::vector<const Instance*>& insts = placed[i];
        if (insts.size() == 1) {
            node["mesh"] = insts[0]->mesh;
        } else if (insts.size() > 1) {
            json mesh = {{"name", n.name}, {"primitives", json::array()}};
            for (const Instance* inst : insts)
                mesh["primitives"].push_back(primitives[static_cast<std::size_t>(inst->mesh)]);
            const Mesh& first = scene.meshes[static_cast<std::size_t>(insts[0]->mesh)];
            if (!first.morphWeights.empty()) mesh["weights"] = first.morphWeights;
            node["mesh"] = doc.push("meshes", std::move(mesh));
        }
        for (const Instance* inst : insts)
            if (inst->skin >= 0) node["skin"] = inst->skin;
        doc.push("nodes", std::move(node));
    }
}

void writeSkins(Document& doc, const Scene& scene) {
    for (const Skin& skin : scene.skins)
        doc.push("skins", {{"name", skin.name},
                           {"joints", skin.joints},
                           {"inverseBindMatrices", doc.mat4s(skin.inverseBind)}});
}

void writeAnimations(Document& doc, const Scene& scene) {
    for (const Animation& a : scene.animations) {
        // A sampler's output type follows the channel that reads it: VEC3 for translation and
        // scale, VEC4 for rotation, SCALAR for weights (and for a sampler no channel reads).
        std::vector<Animation::Path> paths(a.samplers.size(), Animation::Path::Weights);
        for (auto it = a.channels.rbegin(); it != a.channels.rend(); ++it)
            paths[static_cast<std::size_t>(it->sampler)] = it->path;
        json samplers = json::array(), channels = json::array();
        for (std::size_t i = 0; i < a.samplers.size(); ++i) {
            const Animation::Sampler& sm = a.samplers[i];
            const Animation::Path path = paths[i];
            const char* type = path == Animation::Path::Rotation  ? "VEC4"
                               : path == Animation::Path::Weights ? "SCALAR"
                                                                  : "VEC3";
            const std::size_t components = path == Animation::Path::Rotation  ? 4
                                           : path == Animation::Path::Weights ? 1
                                                                              : 3;
            samplers.push_back(
                {{"input", doc.floats(sm.times, "SCALAR", 1)},
                 {"output", doc.floats(sm.values, type, components)},
                 {"interpolation",
                  std::string(Animation::kInterpolationNames[static_cast<std::size_t>(
                      sm.interpolation)])}});
        }
        for (const Animation::Channel& c : a.channels)
            channels.push_back(
                {{"sampler", c.sampler},
                 {"target",
                  {{"node", c.node},
                   {"path",
                    std::string(Animation::kPathNames[static_cast<std::size_t>(c.path)])}}}});
        doc.push("animations", {{"name", a.name},
                                {"samplers", std::move(samplers)},
                                {"channels", std::move(channels)}});
    }
}

void writeNodes(Document& doc, const Scene& scene, const std::vector<json>& primitives) {
    json roots = json::array();
    writeNodeTree(doc, scene, primitives, roots);
    writeSkins(doc, scene);
    writeAnimations(doc, scene);
    for (const Instance& inst : scene.instances) {
        if (inst.node >= 0) continue;
        json node = {
            {"name", inst.nodeName}, {"mesh", inst.mesh}, {"matrix", matrixJson(inst.world)}};
        if (inst.skin >= 0) node["skin"] = inst.skin;
        roots.push_back(doc.push("nodes", std::move(node)));
    }
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
    const std::vector<json> primitives = writeMeshes(doc, scene);
    writeMaterials(doc, scene);
    writeNodes(doc, scene, primitives);
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
