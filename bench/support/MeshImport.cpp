// OBJ and STL readers, the shared text helpers (MeshText.h), and a mesh file to a scene.

#include "MeshImport.h"
#include "MeshText.h"

#include <base/InputFile.h>
#include <base/Numbers.h>
#include <base/Text.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <charconv>
#include <cstring>
#include <unordered_map>

namespace fl::bench {

void MeshWhere::fail(const std::string& problem) const {
    std::string shown = problem; // the file's own words, made printable (a binary file's bytes)
    for (char& c : shown)
        if (!std::isprint(static_cast<unsigned char>(c))) c = '?';
    throw MeshFileError(line ? cat(name, ":", line, ": ", shown) : cat(name, ": ", shown));
}

float MeshWhere::coordinate(double v, std::string_view what) const {
    const std::string problem = numberProblem(v, -kMaxWorldCoordinate, kMaxWorldCoordinate, false);
    if (!problem.empty()) fail(cat(what, " ", problem));
    return static_cast<float>(v);
}

namespace detail {

bool LineReader::next(std::string_view& line) {
    if (done_) return false;
    const std::size_t end = rest_.find('\n');
    line = rest_.substr(0, end);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    rest_ = end == std::string_view::npos ? std::string_view{} : rest_.substr(end + 1);
    done_ = end == std::string_view::npos;
    ++line_;
    return true;
}

void splitWords(std::string_view line, std::vector<std::string_view>& out) {
    out.clear();
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
        if (i > start) out.push_back(line.substr(start, i - start));
    }
}

double number(std::string_view word, const MeshWhere& where, std::string_view what) {
    double v = 0.0;
    const std::string_view digits = word.starts_with('+') ? word.substr(1) : word;
    if (!parseNumber(digits, v)) where.fail(cat(what, ": '", word, "' is not a number"));
    return v;
}

std::int64_t integer(std::string_view word, const MeshWhere& where, std::string_view what,
                     std::int64_t lo, std::int64_t hi) {
    std::int64_t v = 0;
    const char* end = word.data() + word.size();
    const auto r = std::from_chars(word.data(), end, v);
    if (r.ec != std::errc() || r.ptr != end || v < lo || v > hi)
        where.fail(cat(what, ": '", word, "' is not an integer in [", lo, ", ", hi, "]"));
    return v;
}

void addFan(Mesh& mesh, std::span<const std::uint32_t> corners, const MeshWhere& where) {
    if (corners.size() < 3) where.fail(cat("a face of ", corners.size(), " vertices (needs 3)"));
    for (std::size_t k = 1; k + 1 < corners.size(); ++k)
        mesh.indices.insert(mesh.indices.end(), {corners[0], corners[k], corners[k + 1]});
}

} // namespace detail

namespace {

using detail::LineReader;
using detail::splitWords;

glm::vec3 vec3Of(std::span<const std::string_view> w, const MeshWhere& where,
                 std::string_view what) {
    glm::vec3 v;
    for (int k = 0; k < 3; ++k)
        v[k] = where.coordinate(detail::number(w[static_cast<std::size_t>(k)], where, what),
                                cat(what, " ", "xyz"[k]));
    return v;
}

// One OBJ face corner "v", "v/t", "v//n" or "v/t/n" as 0-based indices (-1: absent); negative
// indices count back from the last element read.
std::array<std::int64_t, 3> objCorner(std::string_view word, const std::array<std::size_t, 3>& have,
                                      const MeshWhere& where) {
    static constexpr std::array<std::string_view, 3> kWhat = {"vertex", "texcoord", "normal"};
    std::array<std::int64_t, 3> out{-1, -1, -1};
    for (std::size_t k = 0; k < 3 && !word.empty(); ++k) {
        const std::size_t slash = word.find('/');
        const std::string_view part = word.substr(0, slash);
        word = slash == std::string_view::npos ? std::string_view{} : word.substr(slash + 1);
        if (part.empty() && k != 0) continue;
        const auto n = static_cast<std::int64_t>(have[k]);
        const std::int64_t i = detail::integer(part, where, cat("face ", kWhat[k], " index"),
                                               -(INT64_C(1) << 53), INT64_C(1) << 53);
        if (i == 0) where.fail(cat("face ", kWhat[k], " index 0 (OBJ counts from 1)"));
        if (i > n || i < -n)
            where.fail(cat("face ", kWhat[k], " index ", i, " past the ", n, " read so far"));
        out[k] = i > 0 ? i - 1 : n + i;
    }
    return out;
}

struct CornerHash {
    std::size_t operator()(const std::array<std::int64_t, 3>& c) const {
        return std::hash<std::int64_t>{}(c[0] * 1000003 ^ c[1] * 7919 ^ c[2]);
    }
};

} // namespace

ImportedMesh readObj(std::string_view text, const std::string& name) {
    ImportedMesh out{.format = "OBJ"};
    std::vector<glm::vec3> v, vn;
    std::vector<glm::vec2> vt;
    std::unordered_map<std::array<std::int64_t, 3>, std::uint32_t, CornerHash> vertexOf;
    std::vector<std::array<std::int64_t, 3>> corners; // the mesh's vertices as (v, vt, vn)
    std::vector<std::string_view> w;
    std::vector<std::uint32_t> face;
    LineReader lines(text);
    std::string_view line;
    while (lines.next(line)) {
        const MeshWhere where{name, lines.line()};
        splitWords(line.substr(0, line.find('#')), w);
        if (w.empty()) continue;
        const std::span<const std::string_view> args(w.begin() + 1, w.end());
        const auto need = [&](std::size_t n) {
            if (args.size() < n) where.fail(cat("'", w[0], "' needs ", n, " numbers"));
        };
        if (w[0] == "v") {
            need(3);
            v.push_back(vec3Of(args, where, "vertex"));
        } else if (w[0] == "vn") {
            need(3);
            vn.push_back(vec3Of(args, where, "normal"));
        } else if (w[0] == "vt") {
            need(1);
            const double s = detail::number(args[0], where, "texcoord u");
            const double t = args.size() > 1 ? detail::number(args[1], where, "texcoord v") : 0.0;
            vt.emplace_back(where.coordinate(s, "texcoord u"), 1.0f - where.coordinate(t, "v"));
        } else if (w[0] == "f") {
            face.clear();
            for (std::string_view c : args) {
                const auto key = objCorner(c, {v.size(), vt.size(), vn.size()}, where);
                const auto [it, added] =
                    vertexOf.try_emplace(key, static_cast<std::uint32_t>(corners.size()));
                if (added) corners.push_back(key);
                face.push_back(it->second);
            }
            detail::addFan(out.mesh, face, MeshWhere{name, lines.line()});
            ++out.polygons;
        } // groups, objects, materials, smoothing groups, lines and points: not used
    }
    const bool allNormals =
        std::all_of(corners.begin(), corners.end(), [](const auto& c) { return c[2] >= 0; });
    const bool allTexcoords =
        std::all_of(corners.begin(), corners.end(), [](const auto& c) { return c[1] >= 0; });
    for (const auto& c : corners) {
        out.mesh.positions.push_back(v[static_cast<std::size_t>(c[0])]);
        if (allNormals) out.mesh.normals.push_back(vn[static_cast<std::size_t>(c[2])]);
        if (allTexcoords) out.mesh.texcoords.push_back(vt[static_cast<std::size_t>(c[1])]);
    }
    return out;
}

namespace {

constexpr std::size_t kStlHeader = 84, kStlTriangle = 50;

std::uint32_t u32At(std::span<const unsigned char> b, std::size_t at) {
    std::uint32_t u = 0;
    for (std::size_t i = 0; i < 4; ++i) u |= static_cast<std::uint32_t>(b[at + i]) << (8 * i);
    return u;
}
float f32At(std::span<const unsigned char> b, std::size_t at) {
    return std::bit_cast<float>(u32At(b, at));
}

ImportedMesh readBinaryStl(std::span<const unsigned char> bytes, const std::string& name) {
    ImportedMesh out{.format = "binary STL"};
    const std::size_t n = u32At(bytes, 80);
    if (bytes.size() != kStlHeader + kStlTriangle * n)
        MeshWhere{name}.fail(cat("binary STL of ", n, " triangles should be ",
                                 kStlHeader + kStlTriangle * n, " bytes, the file has ",
                                 bytes.size()));
    for (std::size_t t = 0; t < n; ++t) {
        const MeshWhere where{cat(name, ": triangle ", t)};
        for (std::size_t k = 0; k < 3; ++k) {
            glm::vec3 p;
            for (std::size_t a = 0; a < 3; ++a)
                p[static_cast<int>(a)] = where.coordinate(
                    f32At(bytes, kStlHeader + kStlTriangle * t + 12 * (k + 1) + 4 * a),
                    cat("vertex ", k, " ", "xyz"[a]));
            out.mesh.indices.push_back(static_cast<std::uint32_t>(out.mesh.positions.size()));
            out.mesh.positions.push_back(p);
        }
    }
    out.polygons = n;
    return out;
}

ImportedMesh readAsciiStl(std::string_view text, const std::string& name) {
    ImportedMesh out{.format = "ASCII STL"};
    std::vector<std::string_view> w;
    std::vector<std::uint32_t> loop;
    bool inLoop = false;
    LineReader lines(text);
    std::string_view line;
    while (lines.next(line)) {
        const MeshWhere where{name, lines.line()};
        splitWords(line, w);
        if (w.empty()) continue;
        if (w[0] == "vertex") {
            if (!inLoop) where.fail("'vertex' outside an 'outer loop'");
            if (w.size() < 4) where.fail("'vertex' needs 3 numbers");
            loop.push_back(static_cast<std::uint32_t>(out.mesh.positions.size()));
            out.mesh.positions.push_back(vec3Of({w.begin() + 1, w.end()}, where, "vertex"));
        } else if (w[0] == "outer") {
            inLoop = true;
            loop.clear();
        } else if (w[0] == "endloop") {
            if (!inLoop) where.fail("'endloop' without 'outer loop'");
            detail::addFan(out.mesh, loop, where);
            inLoop = false;
            ++out.polygons;
        } else if (w[0] != "solid" && w[0] != "endsolid" && w[0] != "facet" && w[0] != "endfacet") {
            where.fail(cat("unexpected '", w[0], "' in an ASCII STL"));
        }
    }
    if (inLoop) MeshWhere{name, lines.line()}.fail("the file ends inside a facet's loop");
    return out;
}

} // namespace

ImportedMesh readStl(std::span<const unsigned char> bytes, const std::string& name) {
    const std::string_view text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    const std::size_t first = text.find_first_not_of(" \t\r\n");
    const bool solid = first != std::string_view::npos && text.substr(first, 5) == "solid";
    // A binary file may start with "solid" too: its size decides.
    if (bytes.size() >= kStlHeader) {
        const std::size_t n = u32At(bytes, 80);
        if (!solid || bytes.size() == kStlHeader + kStlTriangle * n)
            return readBinaryStl(bytes, name);
    }
    if (!solid)
        MeshWhere{name}.fail(cat("neither an ASCII STL (starts with 'solid') nor a binary one (",
                                 bytes.size(), " bytes, the header alone is 84)"));
    return readAsciiStl(text, name);
}

ImportedMesh readMeshFile(const std::filesystem::path& path, std::size_t* dropped,
                          float creaseDegrees) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext != ".obj" && ext != ".stl" && ext != ".ply")
        MeshWhere{path.string()}.fail("not a mesh file this reads (.obj, .stl or .ply)");
    const std::vector<unsigned char> bytes = readInputBytes(path, "", kSceneInputLimitMiB);
    const std::string name = path.string();
    ImportedMesh m =
        ext == ".obj"   ? readObj({reinterpret_cast<const char*>(bytes.data()), bytes.size()}, name)
        : ext == ".stl" ? readStl(bytes, name)
                        : readPly(bytes, name);
    if (m.mesh.indices.empty()) MeshWhere{name}.fail(m.format + " file with no faces");
    m.normalsComputed = m.mesh.normals.empty();
    const std::size_t zeroArea =
        m.normalsComputed ? computeCreaseNormals(m.mesh, creaseDegrees) : 0;
    if (dropped) *dropped = zeroArea;
    if (m.mesh.indices.empty())
        MeshWhere{name}.fail(cat("every one of its ", m.polygons, " faces has zero area"));
    return m;
}

Scene meshScene(Mesh mesh, const std::string& source) {
    if (mesh.indices.empty()) MeshWhere{source}.fail("no triangles");
    Scene s;
    s.source = source;
    s.materials.push_back({.name = "default", .baseColorFactor = glm::vec4(0.8f, 0.8f, 0.8f, 1)});
    mesh.material = 0;
    if (mesh.name.empty()) mesh.name = std::filesystem::path(source).stem().string();
    s.instances.push_back({.mesh = 0, .nodeName = mesh.name});
    s.meshes.push_back(std::move(mesh));
    s.computeBounds();
    return s;
}

} // namespace fl::bench
