// The one binding layout (shaders/bindings.glsl, gpu/Bindings.h): every binding a shader declares
// names an entry of the layout of the right kind, the C++ constants name the same entries, and no
// C++ bind call takes a number for its binding point. Reads the source tree; no GL needed.

#include "SourceFolders.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

const fs::path kRoot = fs::path(FLOODLIGHT_TEST_DATA) / "..";

std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
}

// FL_<KIND>_<ROLE> -> its kind (TEX, IMG, SSBO, ATOMIC) and number, from bindings.glsl.
struct Entry {
    std::string kind;
    int number = 0;
};
using Layout = std::map<std::string, Entry>;

// Parses the layout file; anything but comments, the guard and `#define FL_<KIND>_<ROLE> <n>`
// lines is reported in `errors`.
Layout parseLayout(const std::string& text, std::vector<std::string>& errors) {
    static const std::regex define(
        R"(#define (FL_(TEX|IMG|SSBO|ATOMIC)_[A-Z0-9_]+) (\d+)\s*(//.*)?)");
    static const std::regex other(
        R"(\s*(//.*)?|#ifndef FL_BINDINGS_GLSL|#define FL_BINDINGS_GLSL|#endif)");
    Layout layout;
    std::istringstream in(text);
    std::string line;
    int lineNo = 0;
    while (std::getline(in, line)) {
        ++lineNo;
        std::smatch m;
        if (std::regex_match(line, m, define)) {
            if (!layout.emplace(m[1], Entry{m[2], std::stoi(m[3])}).second)
                errors.push_back("bindings.glsl:" + std::to_string(lineNo) + ": " + m[1].str() +
                                 " defined twice");
        } else if (!std::regex_match(line, other)) {
            errors.push_back("bindings.glsl:" + std::to_string(lineNo) +
                             ": not a layout line: " + line);
        }
    }
    return layout;
}

// The layout kind a declaration needs: samplers take texture units, images image units, blocks
// storage bindings, atomic counters counter bindings.
std::string kindOf(const std::string& declaration) {
    if (declaration.find("atomic_uint") != std::string::npos) return "ATOMIC";
    if (declaration.find("buffer ") != std::string::npos) return "SSBO";
    if (std::regex_search(declaration, std::regex(R"(\b[iu]?image[123A-Z])"))) return "IMG";
    if (std::regex_search(declaration, std::regex(R"(\b[iu]?sampler[123A-Z])"))) return "TEX";
    return "?";
}

// Every `binding = X` in one shader: X must be a layout name of the declaration's kind, and a
// shader that uses one includes bindings.glsl itself.
void checkShader(const fs::path& path, const Layout& layout, std::vector<std::string>& errors) {
    static const std::regex binding(R"(binding\s*=\s*([A-Za-z0-9_]+))");
    const std::string text = readText(path);
    const std::string name = path.filename().string();
    std::istringstream in(text);
    std::string line;
    int lineNo = 0;
    bool uses = false;
    while (std::getline(in, line)) {
        ++lineNo;
        const std::string code = line.substr(0, line.find("//"));
        std::smatch m;
        if (!std::regex_search(code, m, binding)) continue;
        uses = true;
        const std::string where = name + ":" + std::to_string(lineNo) + ": ";
        const std::string value = m[1];
        const auto it = layout.find(value);
        if (std::isdigit(static_cast<unsigned char>(value[0])) != 0)
            errors.push_back(where + "binding = " + value + " is a number, not a layout name");
        else if (it == layout.end())
            errors.push_back(where + value + " is not in bindings.glsl");
        else if (it->second.kind != kindOf(code))
            errors.push_back(where + value + " is a " + it->second.kind + " binding on a " +
                             kindOf(code) + " declaration");
    }
    if (uses && text.find("#include \"bindings.glsl\"") == std::string::npos)
        errors.push_back(name + ": uses the layout without #include \"bindings.glsl\"");
}

// The layout names `file` and the files it includes declare, every #ifdef branch at once (a
// superset of what any one build of it declares).
void declaredNames(const fs::path& dir, const std::string& file, std::set<std::string>& visited,
                   std::set<std::string>& names) {
    if (!visited.insert(file).second) return;
    static const std::regex include(R"re(^\s*#include\s+"([^"]+)")re");
    static const std::regex binding(R"(binding\s*=\s*(FL_[A-Z0-9_]+))");
    std::istringstream in(readText(dir / file));
    std::string line;
    while (std::getline(in, line)) {
        const std::string code = line.substr(0, line.find("//"));
        std::smatch m;
        if (std::regex_search(code, m, include))
            declaredNames(dir, m[1], visited, names);
        else if (std::regex_search(code, m, binding))
            names.insert(m[1]);
    }
}

// Roles share a number only where no shader declares both: per compilation unit (a file with a
// #version line) and its includes, no two names of one kind carry the same number. (Units that
// are linked into one program, e.g. a vertex and a fragment shader, are checked apart.)
void checkSharing(const fs::path& dir, const std::string& file, const Layout& layout,
                  std::vector<std::string>& errors) {
    if (readText(dir / file).rfind("#version", 0) != 0) return;
    std::set<std::string> visited, names;
    declaredNames(dir, file, visited, names);
    std::map<std::pair<std::string, int>, std::string> owner;
    for (const std::string& name : names) {
        const auto it = layout.find(name);
        if (it == layout.end()) continue; // reported by checkShader
        const auto [at, fresh] = owner.emplace(std::pair{it->second.kind, it->second.number}, name);
        if (!fresh)
            errors.push_back(file + ": " + at->second + " and " + name + " share " +
                             it->second.kind + " " + std::to_string(it->second.number));
    }
}

std::vector<std::string> shaderErrors(const fs::path& shaderDir) {
    std::vector<std::string> errors;
    const Layout layout = parseLayout(readText(shaderDir / "bindings.glsl"), errors);
    if (layout.empty()) errors.push_back("bindings.glsl: no entries");
    for (const auto& entry : fs::directory_iterator(shaderDir)) {
        const fs::path& p = entry.path();
        if (p.extension() != ".glsl" || p.filename() == "bindings.glsl") continue;
        checkShader(p, layout, errors);
        checkSharing(shaderDir, p.filename().string(), layout, errors);
    }
    return errors;
}

// The arguments of the call whose '(' is at `open`, split at top-level commas.
std::vector<std::string> callArguments(const std::string& text, std::size_t open) {
    std::vector<std::string> args(1);
    int depth = 0;
    for (std::size_t i = open + 1; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '(' || c == '{' || c == '[') ++depth;
        if (c == ')' || c == '}' || c == ']') {
            if (depth == 0) break;
            --depth;
        }
        if (c == ',' && depth == 0)
            args.emplace_back();
        else
            args.back() += c;
    }
    return args;
}

// Whether a C++ argument is a number (possibly cast): `2`, `3u`, `GLuint(4)`,
// `static_cast<GLuint>(5)`.
bool isNumber(const std::string& arg) {
    static const std::regex number(
        R"(\s*(static_cast<\w+>\s*\(|GLuint\s*\(|\(\s*GLuint\s*\))?\s*\d+[uU]?\s*\)?\s*)");
    return std::regex_match(arg, number);
}

// Bind calls in one C++ file whose binding point is a number literal.
void checkSource(const fs::path& path, std::vector<std::string>& errors) {
    // Binding point argument: the first, but the second for the indexed buffer targets.
    static const std::regex call(
        R"(\b(glBindTextureUnit|glBindSampler|glBindImageTexture|glBindBufferBase|glBindBufferRange)\s*\()");
    std::string text = readText(path);
    // Comments may quote calls.
    text = std::regex_replace(text, std::regex(R"(//[^\n]*)"), "");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), call);
         it != std::sregex_iterator(); ++it) {
        const std::string fn = (*it)[1];
        const auto open = static_cast<std::size_t>(it->position(0) + it->length(0) - 1);
        const std::vector<std::string> args = callArguments(text, open);
        const std::size_t at = fn.rfind("glBindBuffer", 0) == 0 ? 1 : 0;
        if (args.size() > at && isNumber(args[at])) {
            const auto line = 1 + std::count(text.begin(), text.begin() + it->position(0), '\n');
            const std::string arg = std::regex_replace(args[at], std::regex(R"(^\s+|\s+$)"), "");
            errors.push_back(fs::relative(path, kRoot).string() + ":" + std::to_string(line) +
                             ": " + fn + " with binding point " + arg +
                             " (use a gl::bind constant through gl::BindScope)");
        }
    }
}

std::vector<std::string> sourceErrors(const std::vector<fs::path>& roots) {
    std::vector<std::string> errors;
    for (const fs::path& root : roots) {
        for (const auto& entry : fs::recursive_directory_iterator(root)) {
            const std::string ext = entry.path().extension().string();
            if (ext == ".cpp" || ext == ".h") checkSource(entry.path(), errors);
        }
    }
    return errors;
}

std::string joined(const std::vector<std::string>& lines) {
    std::string out;
    for (const std::string& l : lines) out += l + "\n";
    return out;
}

TEST(BindingLayout, EveryShaderBindingNamesALayoutEntryOfItsKind) {
    const std::vector<std::string> errors = shaderErrors(kRoot / "shaders");
    EXPECT_TRUE(errors.empty()) << joined(errors);
}

TEST(BindingLayout, CppConstantsNameExactlyTheLayoutEntries) {
    std::vector<std::string> errors;
    const Layout layout = parseLayout(readText(kRoot / "shaders/bindings.glsl"), errors);
    const std::map<std::string, std::string> types{{"TEX", "TextureUnit"},
                                                   {"IMG", "ImageUnit"},
                                                   {"SSBO", "StorageBinding"},
                                                   {"ATOMIC", "CounterBinding"}};
    const std::string header = readText(kRoot / "gpu/include/gpu/Bindings.h");
    static const std::regex constant(R"(inline constexpr (\w+) \w+\{(FL_\w+)\};)");
    std::map<std::string, int> seen;
    for (auto it = std::sregex_iterator(header.begin(), header.end(), constant);
         it != std::sregex_iterator(); ++it) {
        const std::string name = (*it)[2];
        ++seen[name];
        const auto entry = layout.find(name);
        if (entry == layout.end())
            errors.push_back("Bindings.h: " + name + " is not in bindings.glsl");
        else if (types.at(entry->second.kind) != (*it)[1])
            errors.push_back("Bindings.h: " + name + " should be a " +
                             types.at(entry->second.kind));
    }
    for (const auto& [name, kind] : layout)
        if (seen[name] != 1)
            errors.push_back("Bindings.h: " + name + " has " + std::to_string(seen[name]) +
                             " constants, not one");
    EXPECT_TRUE(errors.empty()) << joined(errors);
}

TEST(BindingLayout, NoCppBindCallTakesANumber) {
    std::vector<fs::path> roots;
    for (const std::string_view dir : fl::test::kLibraryFolders) roots.push_back(kRoot / dir);
    const std::vector<std::string> errors = sourceErrors(roots);
    EXPECT_TRUE(errors.empty()) << joined(errors);
}

// The checks themselves: each rejects what it is there to reject.
TEST(BindingLayout, ChecksRejectLiteralsAndUnknownNames) {
    const fs::path dir = fs::path(FLOODLIGHT_TEST_OUTPUT) / "binding_layout";
    fs::create_directories(dir);
    const auto write = [&](const std::string& name, const std::string& text) {
        std::ofstream(dir / name, std::ios::binary) << text;
    };
    write("bindings.glsl",
          "// layout\n#define FL_TEX_A 0\n#define FL_SSBO_B 1\n#define FL_TEX_D 0\n");
    write("ok.glsl",
          "#include \"bindings.glsl\"\nlayout(binding = FL_TEX_A) uniform sampler2D u;\n");
    write("literal.glsl", "#include \"bindings.glsl\"\nlayout(binding = 3) uniform sampler2D u;\n");
    write("unknown.glsl", "#include \"bindings.glsl\"\nlayout(std430, binding = FL_SSBO_C) "
                          "buffer X { uint x[]; };\n");
    write("kind.glsl", "#include \"bindings.glsl\"\nlayout(binding = FL_SSBO_B) uniform "
                       "sampler2D u;\n");
    write("lib.glsl",
          "#include \"bindings.glsl\"\nlayout(binding = FL_TEX_D) uniform sampler2D d;\n");
    write("shared.glsl", "#version 450 core\n#include \"lib.glsl\"\n#include \"bindings.glsl\"\n"
                         "layout(binding = FL_TEX_A) uniform sampler2D a;\n");
    const std::string shaders = joined(shaderErrors(dir));
    EXPECT_EQ(std::count(shaders.begin(), shaders.end(), '\n'), 4) << shaders;
    EXPECT_NE(shaders.find("shared.glsl: FL_TEX_A and FL_TEX_D share TEX 0"), std::string::npos);
    EXPECT_NE(shaders.find("literal.glsl:2: binding = 3 is a number"), std::string::npos);
    EXPECT_NE(shaders.find("unknown.glsl:2: FL_SSBO_C is not in"), std::string::npos);
    EXPECT_NE(shaders.find("kind.glsl:2: FL_SSBO_B is a SSBO binding on a TEX"), std::string::npos);

    const fs::path src = dir / "src";
    fs::create_directories(src);
    std::ofstream(src / "a.cpp", std::ios::binary)
        << "glBindTextureUnit(2, t);\nglBindBufferBase(GL_SHADER_STORAGE_BUFFER,\n 7u, b);\n"
           "glBindImageTexture(static_cast<GLuint>(1), t, 0, GL_FALSE, 0, a, f);\n"
           "glBindTextureUnit(unit.index, t); // glBindTextureUnit(3, t)\n"
           "glBindBufferRange(GL_ATOMIC_COUNTER_BUFFER, b.index, id, 0, 4);\n";
    const std::string cpp = joined(sourceErrors({src}));
    EXPECT_EQ(std::count(cpp.begin(), cpp.end(), '\n'), 3) << cpp;
}

} // namespace
