// glTF 2.0 loading: reads the file, lets tinygltf parse it, then converts everything Floodlight
// uses while validating it (the steps live in the Gltf*.cpp files, see GltfInternal.h).
//
// Decisions worth knowing:
// - Rejected (SceneError "file: element: problem"): unreadable file or unknown extension,
//   tinygltf parse errors, unsupported required extensions, invalid indices into any array we
//   follow, byte ranges past their bufferView/buffer, wrong accessor types for an attribute,
//   indices past the vertex count, non-finite positions or transforms, world-space bounds
//   beyond kMaxWorldCoordinate (base/Numbers.h), node cycles and nodes with two parents,
//   missing image files, absurd counts, no triangles at all.
// - Repaired with a warning: degenerate triangles (dropped), zero/non-finite normals
//   (regenerated from the faces), non-finite texcoords (zeroed), points and lines (skipped),
//   undecodable images or missing texture indices (texture dropped), orthographic or invalid
//   cameras, and cameras or lights placed beyond kMaxWorldCoordinate (skipped), invalid light
//   parameters (defaults). Numbers are checked as the floats the renderer uses: a finite double
//   such as 1e300 is invalid.
// - Sparse accessors are supported. Missing normals become flat normals, as the spec requires.
// - KHR_mesh_quantization: integer positions, normals and texture coordinates in the forms the
//   extension lists (GltfAccessors.cpp), read as they are; the nodes' transforms scale them.
// - KHR_draco_mesh_compression and EXT_meshopt_compression: decoded (libdraco, libmeshoptimizer)
//   into ordinary buffers before the meshes are converted, so decoded data gets every check
//   above; corrupt or inconsistent compressed data is rejected (GltfCompressed.h).
// - Skins, morph targets and animations (GltfSkins.cpp, GltfAnimation.cpp) are read into the
//   scene's nodes, skins and animations with the same rules; the instances keep their rest pose.
//   Spec violations a renderer can live with are repaired with a warning: weights that do not
//   sum to 1, skinning data without a skin (drawn unskinned), channels with unknown paths or
//   no node (skipped), animated matrix nodes (turned into TRS). Data that would make skinning or
//   sampling meaningless is rejected: joint indices past the skin, non-finite or unordered
//   keys, output counts that do not match the keys.
// - The base colour texture's coordinate set (texCoord) and KHR_texture_transform are applied
//   to the mesh's texture coordinates at load (GltfMeshes.cpp).

#include <scene/GltfLoader.h>

#include "GltfCompressed.h"
#include "GltfInternal.h"
#include "GltfSniff.h"

#include <base/InputFile.h>
#include <base/Numbers.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <map>
#include <new>
#include <set>

namespace fl {
namespace gltf {

void Context::fail(std::string_view element, std::string_view problem) const {
    throw SceneError(cat(fileName_, ": ", element, ": ", problem));
}

void Context::warn(std::string_view element, std::string_view what) const {
    if (options_.warn) warnings_.emplace_back(element, what);
}

void Context::flushWarnings() const {
    // The same warning twice (a rule checked by two steps) is one.
    std::set<std::pair<std::string, std::string>> seen;
    std::erase_if(warnings_, [&](const auto& w) { return !seen.insert(w).second; });
    // Kinds in the order each first came, each its warnings' indices; a kind's key is the text
    // with its numbers blanked.
    std::vector<std::vector<std::size_t>> kinds;
    std::map<std::string, std::size_t> kindOf; // key -> index into kinds
    for (std::size_t i = 0; i < warnings_.size(); ++i) {
        std::string key;
        for (char c : warnings_[i].second)
            if (!std::isdigit(static_cast<unsigned char>(c)))
                key += c;
            else if (key.empty() || key.back() != '#')
                key += '#';
        const auto [at, added] = kindOf.emplace(key, kinds.size());
        if (added) kinds.emplace_back();
        kinds[at->second].push_back(i);
    }
    for (const std::vector<std::size_t>& members : kinds) {
        const auto& [element, what] = warnings_[members.front()];
        if (members.size() == 1) {
            options_.warn(cat(fileName_, ": ", element, ": ", what));
            continue;
        }
        // A count leading the text ("25 degenerate triangle(s) dropped") is summed.
        std::string text = what;
        if (!what.empty() && std::isdigit(static_cast<unsigned char>(what.front()))) {
            unsigned long long total = 0;
            for (std::size_t i : members) total += std::stoull(warnings_[i].second);
            text = cat(total, what.substr(what.find_first_not_of("0123456789")));
        }
        std::string where;
        constexpr std::size_t kNamed = 3;
        for (std::size_t n = 0; n < std::min(kNamed, members.size()); ++n)
            where += (n ? ", " : "") + warnings_[members[n]].first;
        if (members.size() > kNamed) where += cat(", and ", members.size() - kNamed, " more");
        options_.warn(
            cat(fileName_, ": ", text, " in ", members.size(), " elements (", where, ")"));
    }
    warnings_.clear();
}

void Context::charge(std::size_t values, std::string_view element) const {
    decodedValues_ += values; // cannot wrap: each call is at most 16 * kMaxAccessorCount
    if (decodedValues_ > kMaxDecodedValues)
        fail(element, cat("the file decodes to more than ", kMaxDecodedValues,
                          " accessor values (absurd size)"));
}

} // namespace gltf

namespace {

using gltf::cat;
using gltf::elem;

// tinygltf takes sizes as unsigned int; kSceneInputLimitMiB (1 GiB) is far beyond any scene we
// can render.
static_assert(kSceneInputLimitMiB <= 1024);
// tinygltf 2.7.0 lets a GLB's BIN chunk end up to 8 bytes past the data it was given; zero
// padding keeps such reads inside our allocation.
constexpr std::size_t kPadding = 16;

// tinygltf converts extras and extensions recursively; deeper nesting than any real file has
// would only serve to overflow the stack.
constexpr int kMaxJsonDepth = 128;

// Required extensions we implement. Everything else changes the meaning of the file (other
// compressions, other material models), so a file requiring it is refused.
constexpr std::array<std::string_view, 5> kSupportedRequired = {
    "EXT_meshopt_compression", "KHR_draco_mesh_compression", "KHR_lights_punctual",
    "KHR_mesh_quantization", "KHR_texture_transform"};

std::string lowercase(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

/// "NAME: PROBLEM (PATH)", the loader's form of a file problem.
SceneError fileError(const std::string& name, const std::filesystem::path& file,
                     const std::string& problem) {
    return SceneError(cat(name, ": ", problem, " (", file.string(), ")"));
}

/// The whole file plus kPadding zero bytes; throws SceneError when it cannot be used. The file
/// checks (regular file, size limit) are base/InputFile.h's, shared by every reader.
std::vector<unsigned char> readFile(const std::filesystem::path& file, const std::string& name,
                                    std::size_t& size) {
    // Checked before the extension so that a FIFO or a missing file is named as such.
    if (const std::string problem = inputFileProblem(file, kSceneInputLimitMiB); !problem.empty())
        throw fileError(name, file, problem);
    const std::string ext = lowercase(file.extension().string());
    if (ext != ".gltf" && ext != ".glb")
        throw SceneError(cat(name, ": unsupported file type '", ext, "' (expected .gltf or .glb)"));
    try {
        std::vector<unsigned char> bytes = readInputBytes(file, "", kSceneInputLimitMiB, kPadding);
        size = bytes.size() - kPadding;
        return bytes;
    } catch (const InputFileError& e) {
        throw fileError(name, file, e.problem());
    }
}

// tinygltf's file callbacks for external buffers and images: the same checks as the scene file
// (its defaults fopen() the path, which blocks on a FIFO and reads a directory as "not found").
// "Exists" is true for anything there, so that reading reports what is wrong with it.
bool externalFileExists(const std::string& path, void*) {
    std::error_code ec;
    return std::filesystem::exists(path, ec);
}

bool readExternalFile(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                      void*) {
    try {
        *out = readInputBytes(path, "", kSceneInputLimitMiB);
        return true;
    } catch (const InputFileError& e) {
        if (err) *err += e.problem();
        return false;
    }
}

std::string keepPath(const std::string& path, void*) {
    return path;
}

/// Non-empty lines of a tinygltf message, which joins its reports with newlines.
std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        if (end > start) out.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    return out;
}

/// The JSON text of the file: all of a .gltf, the first chunk of a .glb (whole file when the
/// header is broken; tinygltf reports that).
std::pair<std::size_t, std::size_t> jsonRange(const std::vector<unsigned char>& bytes,
                                              std::size_t size, bool binary) {
    if (!binary || size < 20) return {0, size};
    std::uint32_t length = 0;
    for (int i = 0; i < 4; ++i)
        length |= std::uint32_t{bytes[12 + static_cast<std::size_t>(i)]} << (8 * i);
    if (length > size - 20) return {0, size};
    return {20, 20 + length};
}

/// Deepest nesting of [ and { outside strings; a byte scan, cheaper than any parse.
int jsonDepth(const std::vector<unsigned char>& bytes, std::size_t begin, std::size_t end) {
    int depth = 0, deepest = 0;
    bool inString = false;
    for (std::size_t i = begin; i < end; ++i) {
        const unsigned char c = bytes[i];
        if (inString) {
            if (c == '\\')
                ++i; // skip the escaped character
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            deepest = std::max(deepest, ++depth);
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return deepest;
}

bool supportedRequired(const std::string& ext) {
    return std::find(kSupportedRequired.begin(), kSupportedRequired.end(), ext) !=
           kSupportedRequired.end();
}

/// The first unsupported entry of extensionsRequired, read straight from the JSON. Used when
/// tinygltf fails: a file needing e.g. Draco breaks tinygltf's own checks (accessors without
/// bufferViews), and the missing extension is the message that helps.
std::optional<std::string> unsupportedRequired(const std::vector<unsigned char>& bytes,
                                               std::size_t size, bool binary) {
    const auto [begin, end] = jsonRange(bytes, size, binary);
    const auto doc = nlohmann::json::parse(bytes.begin() + static_cast<std::ptrdiff_t>(begin),
                                           bytes.begin() + static_cast<std::ptrdiff_t>(end),
                                           nullptr, /*allow_exceptions=*/false);
    if (!doc.is_object() || !doc.contains("extensionsRequired") ||
        !doc["extensionsRequired"].is_array())
        return std::nullopt;
    for (const auto& ext : doc["extensionsRequired"])
        if (ext.is_string() && !supportedRequired(ext.get<std::string>()))
            return ext.get<std::string>();
    return std::nullopt;
}

/// `bytes` is the file followed by kPadding zero bytes, `size` the file's own; `baseDir` is
/// where its external files are (empty: it may have none).
tinygltf::Model parse(std::vector<unsigned char> bytes, std::size_t size,
                      const std::filesystem::path& baseDirectory, const std::string& name,
                      const LoadOptions& options) {
    if (const std::string problem = gltf::sniffProblem(bytes, size); !problem.empty())
        throw SceneError(cat(name, ": ", problem));
    tinygltf::TinyGLTF parser;
    parser.SetImageLoader(&gltf::keepEncodedImage, nullptr);
    parser.SetFsCallbacks(
        {&externalFileExists, &keepPath, &readExternalFile, &tinygltf::WriteWholeFile, nullptr});
    tinygltf::Model model;
    std::string err, warn;
    const std::string baseDir = baseDirectory.string();
    // Dispatch on the content, not the extension: a mislabelled file still loads.
    const bool binary = size >= 4 && std::equal(bytes.begin(), bytes.begin() + 4, "glTF");
    const auto [jsonBegin, jsonEnd] = jsonRange(bytes, size, binary);
    if (jsonDepth(bytes, jsonBegin, jsonEnd) > kMaxJsonDepth)
        throw SceneError(cat(name, ": JSON nested deeper than ", kMaxJsonDepth, " levels"));
    gltf::prepareCompressedJson(bytes, size, {jsonBegin, jsonEnd}, binary, kPadding);
    const auto length = static_cast<unsigned int>(size);
    const bool ok =
        binary ? parser.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), length, baseDir)
               : parser.LoadASCIIFromString(&model, &err, &warn,
                                            reinterpret_cast<const char*>(bytes.data()), length,
                                            baseDir);
    if (!ok) {
        if (auto ext = unsupportedRequired(bytes, size, binary))
            throw SceneError(
                cat(name, ": extensionsRequired: unsupported required extension ", *ext));
        if (const std::string problem = gltf::jsonProblem(bytes, jsonBegin, jsonEnd);
            !problem.empty())
            throw SceneError(cat(name, ": ", problem));
        std::string message;
        for (const std::string& line : lines(err)) message += (message.empty() ? "" : "; ") + line;
        throw SceneError(
            cat(name, ": ", message.empty() ? "tinygltf could not parse it" : message));
    }
    if (const std::string problem = gltf::versionProblem(model.asset.version); !problem.empty())
        throw SceneError(cat(name, ": ", problem));
    // tinygltf 2.7 reports a skin without inverseBindMatrices, which the spec allows (identity
    // matrices, 3.7.3.2), as a missing required property: not a problem worth a warning.
    constexpr std::string_view kOptionalMatrices =
        "'inverseBindMatrices' property is missing in Skin.";
    if (options.warn)
        for (const std::string& line : lines(warn + err))
            if (line != kOptionalMatrices) options.warn(cat(name, ": ", line));
    return model;
}

void checkRequiredExtensions(const gltf::Context& ctx) {
    for (const std::string& ext : ctx.model().extensionsRequired)
        if (!supportedRequired(ext))
            ctx.fail("extensionsRequired", cat("unsupported required extension ", ext));
}

bool finite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

/// One Instance per triangle primitive of every placed node with a mesh; each glTF mesh is
/// converted once, however many nodes use it.
void placeInstances(const gltf::Context& ctx, const std::vector<gltf::PlacedNode>& placed,
                    Scene& scene) {
    std::map<int, std::pair<std::size_t, std::size_t>> converted; // mesh -> [first, end)
    std::uint32_t nextId = 1;                                     // 0 means "no object"
    for (const gltf::PlacedNode& p : placed) {
        const tinygltf::Node& node = ctx.model().nodes[static_cast<std::size_t>(p.node)];
        if (node.mesh == -1) continue;
        const std::string element = elem("nodes", static_cast<std::size_t>(p.node));
        ctx.lookup(ctx.model().meshes, node.mesh, element, "mesh", "meshes");
        auto it = converted.find(node.mesh);
        if (it == converted.end()) {
            const std::size_t first = scene.meshes.size();
            gltf::convertMesh(ctx, node.mesh, scene.meshes);
            it = converted.emplace(node.mesh, std::pair{first, scene.meshes.size()}).first;
        }
        const auto [first, end] = it->second;
        if (first == end) continue;
        if (!finite(p.world)) ctx.fail(element, "world transform is not finite");
        const std::uint32_t id = nextId++;
        for (std::size_t m = first; m < end; ++m)
            scene.instances.push_back({static_cast<int>(m), p.world, id,
                                       node.name.empty() ? element : node.name, p.node});
    }
}

/// Within the world's limit on every side (gltf::inWorld; NaN is outside), so that the sizes
/// and distances derived from the bounds (radius, far planes, light frusta) stay finite.
bool inWorld(const geom::Aabb& box) {
    return gltf::inWorld(box.min) && gltf::inWorld(box.max);
}

/// `model` is the one `ctx` reads: decoding compressed meshes adds buffers to it.
Scene convert(const gltf::Context& ctx, tinygltf::Model& model, const std::filesystem::path& file) {
    checkRequiredExtensions(ctx);
    Scene scene;
    scene.source = file.string();
    const std::vector<gltf::PlacedNode> placed = gltf::placeSceneNodes(ctx);
    gltf::decodeCompressed(ctx, model, placed);
    placeInstances(ctx, placed, scene);
    if (scene.instances.empty()) ctx.fail("scene", "no triangle primitives");
    gltf::convertRigging(ctx, placed, scene);
    scene.computeBounds();
    if (!scene.bounds.valid() || !inWorld(scene.bounds))
        ctx.fail("scene", cat("world-space bounds are not finite or reach beyond ",
                              kMaxWorldCoordinate, " (positions or transforms too large)"));
    // Nothing to draw, to cast a shadow or to stand a ground under: a point or a line has no
    // size to place a light, a camera or a ground from.
    if (!restHasArea(scene))
        ctx.fail("scene", "every triangle has zero area where its node places it (its vertices "
                          "lie in one point or on one line, or a node scale is 0)");

    std::vector<bool> used(ctx.model().materials.size(), false);
    for (const Mesh& mesh : scene.meshes)
        if (mesh.material >= 0) used[static_cast<std::size_t>(mesh.material)] = true;
    scene.materials = gltf::convertMaterials(ctx, used, scene.images);
    scene.cameras = gltf::convertCameras(ctx, placed, scene.bounds);
    scene.light = gltf::convertLight(ctx, placed, scene.bounds);
    return scene;
}

} // namespace

namespace {

// Both entry points: parse, convert, and one clear error naming the file whatever fails.
Scene load(std::vector<unsigned char> bytes, std::size_t size, const std::filesystem::path& file,
           const std::string& name, const LoadOptions& options) {
    try {
        tinygltf::Model model = parse(std::move(bytes), size, file.parent_path(), name, options);
        const gltf::Context ctx(name, file.parent_path(), model, options);
        // The warnings come out summed once the file is read, or before its error.
        struct Flush {
            const gltf::Context& ctx;
            ~Flush() {
                try {
                    ctx.flushWarnings();
                } catch (...) { // a failing printer must not end the program from a destructor
                }
            }
        } flush{ctx};
        return convert(ctx, model, file);
    } catch (const SceneError&) {
        throw;
    } catch (const std::bad_alloc&) {
        throw SceneError(cat(name, ": out of memory while loading"));
    } catch (const std::exception& e) {
        // Nothing here should throw anything else; if tinygltf or the standard library does,
        // the caller still gets one clear error naming the file.
        throw SceneError(cat(name, ": ", e.what()));
    }
}

} // namespace

Scene loadGltf(const std::filesystem::path& file, const LoadOptions& options) {
    const std::string name =
        file.has_filename() ? file.filename().string() : file.string(); // names every message
    std::size_t size = 0;
    std::vector<unsigned char> bytes = readFile(file, name, size);
    return load(std::move(bytes), size, file, name, options);
}

Scene loadGlbBytes(std::span<const unsigned char> glb, const std::string& name,
                   const LoadOptions& options) {
    std::vector<unsigned char> bytes(glb.begin(), glb.end());
    bytes.resize(glb.size() + kPadding, 0);
    // A name, not a path: no folder, so no external file can be read.
    return load(std::move(bytes), glb.size(), std::filesystem::path(name), name, options);
}

} // namespace fl
