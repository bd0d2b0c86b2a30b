#include "GltfSniff.h"

#include <base/Text.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <string_view>

namespace fl::gltf {

namespace {

struct Signature {
    std::string_view bytes;
    std::string_view what;
};

// Formats people mistake for, or rename to, .glb/.gltf: images that a glTF file refers to, the
// archives it ships in, and the meshes it is converted from.
constexpr std::array<Signature, 12> kSignatures{{
    {"\x89PNG", "a PNG image"},
    {"\xFF\xD8\xFF", "a JPEG image"},
    {"GIF8", "a GIF image"},
    {"\xABKTX", "a KTX texture"},
    {"RIFF", "a RIFF file (WebP image or WAV sound)"},
    {"PK\x03\x04", "a ZIP archive (unpack it first)"},
    {"\x1F\x8B", "a gzip file (unpack it first)"},
    {"%PDF", "a PDF document"},
    {"ply", "a PLY mesh (convert it to glTF 2.0 first, e.g. assimp export IN.ply OUT.glb)"},
    {"solid", "an STL mesh (convert it to glTF 2.0 first, e.g. assimp export IN.stl OUT.glb)"},
    {"Kaydara FBX", "an FBX file (convert it to glTF 2.0 first, e.g. with FBX2glTF)"},
    {"<?xml", "an XML document (COLLADA? convert it to glTF 2.0 first)"},
}};

std::uint32_t le32(const std::vector<unsigned char>& b, std::size_t at) {
    std::uint32_t v = 0;
    for (std::size_t i = 0; i < 4; ++i) v |= std::uint32_t{b[at + i]} << (8 * i);
    return v;
}

bool startsWith(const std::vector<unsigned char>& b, std::size_t size, std::string_view s) {
    return size >= s.size() &&
           std::equal(s.begin(), s.end(), b.begin(),
                      [](char c, unsigned char u) { return static_cast<unsigned char>(c) == u; });
}

// "line L, column C" of byte offset `at` (0-based) in [begin, end).
std::string whereIs(const std::vector<unsigned char>& b, std::size_t begin, std::size_t at) {
    std::size_t line = 1, column = 1;
    for (std::size_t i = begin; i < at; ++i) {
        if (b[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
    return cat("line ", line, ", column ", column);
}

} // namespace

std::string sniffProblem(const std::vector<unsigned char>& bytes, std::size_t size) {
    if (size == 0) return "empty file (0 bytes); a glTF 2.0 file (.gltf or .glb) is needed";
    for (const Signature& s : kSignatures)
        if (startsWith(bytes, size, s.bytes))
            return cat("not a glTF file (it starts like ", s.what, ")");
    if (startsWith(bytes, size, "glTF")) {
        if (size < 12) return cat("truncated: a .glb header is 12 bytes, the file has ", size);
        if (const std::uint32_t version = le32(bytes, 4); version != 2)
            return cat("glTF binary version ", version,
                       " is not supported (its header says so); glTF 2.0 is needed");
        if (const std::uint32_t length = le32(bytes, 8); length > size)
            return cat("truncated: its .glb header says ", length, " bytes, the file has ", size);
        if (size < 20) return cat("truncated: the .glb has no JSON chunk (", size, " bytes)");
        if (const std::uint32_t json = le32(bytes, 12); json > size - 20)
            return cat("truncated: its JSON chunk of ", json, " bytes runs past the end of the ",
                       size, "-byte file");
        return {};
    }
    // Not a .glb: a .gltf is a JSON object, so its first byte past white space is '{'.
    const auto first =
        std::find_if(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(size),
                     [](unsigned char c) { return !std::isspace(c); });
    if (first == bytes.begin() + static_cast<std::ptrdiff_t>(size))
        return "only white space; a glTF 2.0 file (.gltf or .glb) is needed";
    if (*first == '{') return {};
    const bool text = std::all_of(bytes.begin(), bytes.begin() + std::min<std::size_t>(size, 64),
                                  [](unsigned char c) { return c >= 0x20 || std::isspace(c); });
    return text ? "not a glTF file (it is text that does not start with a JSON object '{'; an OBJ "
                  "mesh? convert it to glTF 2.0 first, e.g. assimp export IN.obj OUT.glb)"
                : "not a glTF file (it is binary, without the .glb header 'glTF')";
}

std::string jsonProblem(const std::vector<unsigned char>& bytes, std::size_t begin,
                        std::size_t end) {
    nlohmann::json doc;
    try {
        doc = nlohmann::json::parse(bytes.begin() + static_cast<std::ptrdiff_t>(begin),
                                    bytes.begin() + static_cast<std::ptrdiff_t>(end));
    } catch (const nlohmann::json::parse_error& e) {
        // e.byte: 1-based offset of the byte where the parse failed; at the end: cut short.
        const std::size_t at = begin + (e.byte > 0 ? e.byte - 1 : 0);
        if (at + 1 >= end)
            return cat("truncated: the JSON ends (after ", end - begin,
                       " bytes) before it is complete");
        return cat("not valid JSON at ", whereIs(bytes, begin, at), " (a glTF file is JSON)");
    }
    if (!doc.is_object()) return "the JSON is not an object; a glTF file is one JSON object";
    if (doc.contains("asset") && doc["asset"].is_object() && doc["asset"].contains("version") &&
        doc["asset"]["version"].is_string())
        if (std::string p = versionProblem(doc["asset"]["version"].get<std::string>()); !p.empty())
            return p;
    // glTF 1.0 keeps its meshes, nodes, ... as objects by name; 2.0 as arrays.
    for (const char* key : {"meshes", "nodes", "accessors", "buffers", "scenes"})
        if (doc.contains(key) && doc[key].is_object())
            return cat("glTF 1.0 is not supported (its \"", key,
                       "\" are an object by name, as in glTF 1.0); glTF 2.0 is needed");
    if (!doc.contains("asset") || !doc["asset"].is_object())
        return "no \"asset\" object, which every glTF 2.0 file has ({\"version\": \"2.0\"}); "
               "glTF 1.0 is not supported";
    const auto& asset = doc["asset"];
    if (!asset.contains("version") || !asset["version"].is_string())
        return "asset.version is missing; glTF 2.0 files say \"2.0\"";
    return {};
}

std::string versionProblem(const std::string& version) {
    if (version.rfind("2.", 0) == 0) return {};
    // Only printable characters of it: the message is one readable line.
    std::string shown;
    for (char c : version.substr(0, 16))
        shown += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
    return cat("glTF ", shown, " is not supported (asset.version ", shown, "); glTF 2.0 is needed");
}

} // namespace fl::gltf
