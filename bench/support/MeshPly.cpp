// The PLY reader (ASCII and binary little-endian): the header's elements and properties, then
// each element's values in order. The vertex element gives x y z and, when all three are there,
// nx ny nz; the face element's list vertex_indices (or vertex_index) gives the polygons. Every
// other element and property is read past.

#include "MeshImport.h"
#include "MeshText.h"

#include <base/Text.h>

#include <array>
#include <bit>
#include <cmath>
#include <optional>

namespace fl::bench {

namespace {

using detail::LineReader;

enum class PlyType { I8, U8, I16, U16, I32, U32, F32, F64 };

std::optional<PlyType> plyType(std::string_view t) {
    static constexpr std::array<std::pair<std::string_view, PlyType>, 16> kNames = {{
        {"char", PlyType::I8},
        {"int8", PlyType::I8},
        {"uchar", PlyType::U8},
        {"uint8", PlyType::U8},
        {"short", PlyType::I16},
        {"int16", PlyType::I16},
        {"ushort", PlyType::U16},
        {"uint16", PlyType::U16},
        {"int", PlyType::I32},
        {"int32", PlyType::I32},
        {"uint", PlyType::U32},
        {"uint32", PlyType::U32},
        {"float", PlyType::F32},
        {"float32", PlyType::F32},
        {"double", PlyType::F64},
        {"float64", PlyType::F64},
    }};
    for (const auto& [name, type] : kNames)
        if (name == t) return type;
    return std::nullopt;
}

struct PlyProperty {
    std::string name;
    PlyType type = PlyType::F32;
    std::optional<PlyType> countType; // a list: its length's type
};

struct PlyElement {
    std::string name;
    std::size_t count = 0;
    std::vector<PlyProperty> properties;
    [[nodiscard]] int find(std::string_view n) const {
        for (std::size_t i = 0; i < properties.size(); ++i)
            if (properties[i].name == n) return static_cast<int>(i);
        return -1;
    }
};

struct PlyHeader {
    bool binary = false;
    std::vector<PlyElement> elements;
    std::size_t bodyStart = 0; // byte offset of the first value
    std::size_t bodyLine = 0;  // line number of the last header line
};

PlyType typeOrFail(std::string_view t, const MeshWhere& where) {
    const auto type = plyType(t);
    if (!type) where.fail(cat("unknown PLY type '", t, "'"));
    return *type;
}

PlyHeader readHeader(std::string_view text, const std::string& name) {
    PlyHeader h;
    LineReader lines(text);
    std::string_view line;
    std::vector<std::string_view> w;
    bool sawFormat = false;
    if (!lines.next(line) || line != "ply") MeshWhere{name, 1}.fail("not a PLY file (no 'ply')");
    while (lines.next(line)) {
        const MeshWhere where{name, lines.line()};
        detail::splitWords(line, w);
        if (w.empty() || w[0] == "comment" || w[0] == "obj_info") continue;
        if (w[0] == "end_header") {
            if (!sawFormat) where.fail("the header has no 'format' line");
            h.bodyStart = text.size() - lines.rest().size();
            h.bodyLine = lines.line();
            return h;
        }
        if (w[0] == "format") {
            if (w.size() < 2 || (w[1] != "ascii" && w[1] != "binary_little_endian"))
                where.fail(cat("PLY format '", w.size() > 1 ? w[1] : "", "' is not read (ascii ",
                               "or binary_little_endian)"));
            h.binary = w[1] != "ascii";
            sawFormat = true;
        } else if (w[0] == "element" && w.size() == 3) {
            const auto n = detail::integer(w[2], where, "element count", 0, INT64_MAX);
            h.elements.push_back({std::string(w[1]), static_cast<std::size_t>(n), {}});
        } else if (w[0] == "property" && !h.elements.empty() && w.size() >= 3) {
            const bool list = w[1] == "list";
            if (w.size() != (list ? 5u : 3u)) where.fail("a property line of the wrong length");
            PlyProperty p{std::string(w.back()), typeOrFail(w[list ? 3 : 1], where), {}};
            if (list) p.countType = typeOrFail(w[2], where);
            h.elements.back().properties.push_back(std::move(p));
        } else if (w[0] == "element" || w[0] == "property") {
            where.fail(cat("a malformed header line '", line, "'"));
        } // other lines are read past, as most readers do (Blender 2.4 wrote a bare comment)
    }
    MeshWhere{name, lines.line()}.fail("the header has no 'end_header'");
}

// The body's values one by one, from text words or little-endian bytes.
class PlyValues {
  public:
    PlyValues(std::span<const unsigned char> bytes, const PlyHeader& h, const std::string& name)
        : bytes_(bytes), at_(h.bodyStart), binary_(h.binary), name_(name),
          lines_({reinterpret_cast<const char*>(bytes.data()) + h.bodyStart,
                  bytes.size() - h.bodyStart}),
          lineBase_(h.bodyLine) {}

    double next(PlyType t, const std::string& what) {
        return binary_ ? nextBinary(t, what) : nextText(t, what);
    }

  private:
    static std::size_t sizeOf(PlyType t) {
        static constexpr std::array<std::size_t, 8> kSizes = {1, 1, 2, 2, 4, 4, 4, 8};
        return kSizes[static_cast<std::size_t>(t)];
    }
    double nextBinary(PlyType t, const std::string& what) {
        const std::size_t n = sizeOf(t);
        if (bytes_.size() - at_ < n) MeshWhere{name_}.fail(cat("the file ends in ", what));
        std::uint64_t u = 0;
        for (std::size_t i = 0; i < n; ++i) u |= std::uint64_t{bytes_[at_ + i]} << (8 * i);
        at_ += n;
        const auto sign = [&](int bits) {
            return static_cast<double>(static_cast<std::int64_t>(u << (64 - bits)) >> (64 - bits));
        };
        switch (t) {
        case PlyType::I8:
            return sign(8);
        case PlyType::I16:
            return sign(16);
        case PlyType::I32:
            return sign(32);
        case PlyType::F32:
            return std::bit_cast<float>(static_cast<std::uint32_t>(u));
        case PlyType::F64:
            return std::bit_cast<double>(u);
        default:
            return static_cast<double>(u);
        }
    }
    double nextText(PlyType, const std::string& what) {
        while (word_ == words_.size()) {
            std::string_view line;
            if (!lines_.next(line)) MeshWhere{name_}.fail(cat("the file ends in ", what));
            detail::splitWords(line, words_);
            word_ = 0;
        }
        return detail::number(words_[word_++], {name_, lineBase_ + lines_.line()}, what);
    }

    std::span<const unsigned char> bytes_;
    std::size_t at_;
    bool binary_;
    const std::string& name_;
    LineReader lines_;
    std::size_t lineBase_;
    std::vector<std::string_view> words_;
    std::size_t word_ = 0;
};

// One element's instances: vertices into mesh.positions (and normals), faces into indices.
void readElement(const PlyElement& e, PlyValues& values, ImportedMesh& out,
                 const std::string& name) {
    const bool vertex = e.name == "vertex", face = e.name == "face";
    const std::array<int, 6> at = {e.find("x"),  e.find("y"),  e.find("z"),
                                   e.find("nx"), e.find("ny"), e.find("nz")};
    if (vertex && (at[0] < 0 || at[1] < 0 || at[2] < 0))
        MeshWhere{name}.fail("the vertex element has no x, y and z");
    const bool normals = vertex && at[3] >= 0 && at[4] >= 0 && at[5] >= 0;
    const int list = face ? std::max(e.find("vertex_indices"), e.find("vertex_index")) : -1;
    std::vector<std::uint32_t> corners;
    std::array<double, 6> v{};
    if (e.properties.empty()) return; // nothing to read, however many it counts
    for (std::size_t i = 0; i < e.count; ++i) {
        const std::string what = cat(e.name, " ", i);
        for (std::size_t p = 0; p < e.properties.size(); ++p) {
            const PlyProperty& prop = e.properties[p];
            if (!prop.countType) {
                const double x = values.next(prop.type, what);
                for (std::size_t k = 0; k < 6; ++k)
                    if (vertex && at[k] == static_cast<int>(p)) v[k] = x;
                continue;
            }
            const double n = values.next(*prop.countType, what);
            if (!(n >= 0 && n <= 1e6 && n == std::floor(n)))
                MeshWhere{name}.fail(cat(what, ": a list of ", n, " values"));
            corners.clear();
            for (std::size_t k = 0; k < static_cast<std::size_t>(n); ++k) {
                const double index = values.next(prop.type, what);
                if (!(index >= 0 && index < 4294967295.0 && index == std::floor(index)))
                    MeshWhere{name}.fail(cat(what, ": vertex index ", index));
                corners.push_back(static_cast<std::uint32_t>(index));
            }
            if (static_cast<int>(p) == list) {
                detail::addFan(out.mesh, corners, MeshWhere{cat(name, ": ", what)});
                ++out.polygons;
            }
        }
        if (!vertex) continue;
        const MeshWhere where{cat(name, ": ", what)};
        out.mesh.positions.emplace_back(where.coordinate(v[0], "x"), where.coordinate(v[1], "y"),
                                        where.coordinate(v[2], "z"));
        if (normals)
            out.mesh.normals.emplace_back(where.coordinate(v[3], "nx"),
                                          where.coordinate(v[4], "ny"),
                                          where.coordinate(v[5], "nz"));
    }
    if (face && list < 0 && e.count > 0)
        MeshWhere{name}.fail("the face element has no list vertex_indices or vertex_index");
}

} // namespace

ImportedMesh readPly(std::span<const unsigned char> bytes, const std::string& name) {
    const PlyHeader h =
        readHeader({reinterpret_cast<const char*>(bytes.data()), bytes.size()}, name);
    ImportedMesh out{.format = h.binary ? "binary PLY" : "ASCII PLY"};
    PlyValues values(bytes, h, name);
    for (const PlyElement& e : h.elements) readElement(e, values, out, name);
    for (std::uint32_t i : out.mesh.indices)
        if (i >= out.mesh.positions.size())
            MeshWhere{name}.fail(cat("a face's vertex index ", i, " past the ",
                                     out.mesh.positions.size(), " vertices"));
    return out;
}

} // namespace fl::bench
