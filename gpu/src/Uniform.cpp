// Program::bindUniforms: typed uniforms checked against the linked program and, for those the
// compiler removed, against the declarations in the program's expanded sources.

#include <gpu/Program.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <map>
#include <string>
#include <string_view>

namespace fl::gl {

namespace {

// A declaration found in the sources: its GLSL type name and whether it is an array.
struct Declared {
    std::string type;
    bool array = false;
};

// `text` less its // and /* */ comments (each replaced by white space, so tokens stay apart).
std::string withoutComments(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '/' && i + 1 < text.size() && text[i + 1] == '/') {
            while (i < text.size() && text[i] != '\n') ++i;
            out += '\n';
        } else if (text[i] == '/' && i + 1 < text.size() && text[i + 1] == '*') {
            const size_t end = text.find("*/", i + 2);
            i = end == std::string_view::npos ? text.size() : end + 1;
            out += ' ';
        } else {
            out += text[i];
        }
    }
    return out;
}

bool identChar(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}

bool space(char c) {
    return std::isspace(static_cast<unsigned char>(c)) != 0;
}

// The identifier at or after `pos` (skipping white space); empty if something else comes first.
std::string_view nextIdentifier(std::string_view s, size_t& pos) {
    while (pos < s.size() && space(s[pos])) ++pos;
    const size_t start = pos;
    while (pos < s.size() && identChar(s[pos])) ++pos;
    return s.substr(start, pos - start);
}

// Every `uniform [qualifiers] <type> <name>` in `sources` (all stages, comments ignored), by
// name. Blocks (`uniform Name {`) are skipped. Declarations inside #if'd-out code count too: a
// variant that compiles them out is what leaves a declared uniform inactive. A declarator list
// (`uniform int a, b;`) records its first name only; none of our shaders has one, and a name it
// misses is reported as undeclared, loudly, not accepted.
std::map<std::string, Declared, std::less<>> declaredUniforms(std::string_view sources) {
    static constexpr std::string_view kQualifiers[] = {
        "readonly", "writeonly", "coherent", "volatile", "restrict", "highp", "mediump", "lowp"};
    const std::string text = withoutComments(sources);
    std::map<std::string, Declared, std::less<>> out;
    constexpr std::string_view kUniform = "uniform";
    for (size_t pos = text.find(kUniform); pos != std::string::npos;
         pos = text.find(kUniform, pos)) {
        const bool wordStart = pos == 0 || !identChar(text[pos - 1]);
        pos += kUniform.size();
        if (!wordStart || (pos < text.size() && identChar(text[pos]))) continue;
        size_t at = pos;
        std::string_view type = nextIdentifier(text, at);
        while (std::find(std::begin(kQualifiers), std::end(kQualifiers), type) !=
               std::end(kQualifiers))
            type = nextIdentifier(text, at);
        const std::string_view name = nextIdentifier(text, at);
        if (type.empty() || name.empty()) continue; // a block, or not a declaration
        while (at < text.size() && space(text[at])) ++at;
        out.emplace(std::string(name),
                    Declared{std::string(type), at < text.size() && text[at] == '['});
    }
    return out;
}

// A GL_TYPE as GLSL spells it, for messages (hex for types no table maps).
std::string glslName(GLenum type) {
    switch (type) {
    case GL_INT:
        return "int";
    case GL_UNSIGNED_INT:
        return "uint";
    case GL_BOOL:
        return "bool";
    case GL_FLOAT:
        return "float";
    case GL_INT_VEC2:
        return "ivec2";
    case GL_INT_VEC3:
        return "ivec3";
    case GL_INT_VEC4:
        return "ivec4";
    case GL_FLOAT_VEC2:
        return "vec2";
    case GL_FLOAT_VEC3:
        return "vec3";
    case GL_FLOAT_VEC4:
        return "vec4";
    case GL_FLOAT_MAT3:
        return "mat3";
    case GL_FLOAT_MAT4:
        return "mat4";
    default: {
        char hex[32];
        std::snprintf(hex, sizeof(hex), "GL type 0x%04X", type);
        return hex;
    }
    }
}

std::string described(const std::string& glsl, bool array) {
    return glsl + (array ? "[]" : "");
}

} // namespace

void Program::bindUniforms(std::initializer_list<const UniformBase*> uniforms) {
    std::map<std::string, Declared, std::less<>> declared; // parsed at the first inactive name
    bool parsed = false;
    for (const UniformBase* u : uniforms) {
        const std::string where = files_ + ": uniform " + u->name() + ": ";
        const std::string wanted = described(u->glsl(), u->array());
        GLint at = glGetUniformLocation(id(), u->name());
        if (at >= 0) {
            const GLuint index = glGetProgramResourceIndex(id(), GL_UNIFORM, u->name());
            const GLenum property = GL_TYPE;
            GLint type = 0;
            glGetProgramResourceiv(id(), GL_UNIFORM, index, 1, &property, 1, nullptr, &type);
            // An array's resource is named "name[0]"; a plain uniform's is the name alone.
            char name[256] = {};
            glGetProgramResourceName(id(), GL_UNIFORM, index, sizeof(name), nullptr, name);
            const bool array = std::string_view(name).ends_with("[0]");
            if (static_cast<GLenum>(type) != u->type() || array != u->array())
                throw GlError(where + "set as " + wanted + " but the linked program's is " +
                              described(glslName(static_cast<GLenum>(type)), array));
        } else {
            if (!parsed) declared = declaredUniforms(key_), parsed = true;
            const auto found = declared.find(std::string_view(u->name()));
            if (found == declared.end())
                throw GlError(where + "declared in none of the program's stages (misspelt?)");
            const std::string has = described(found->second.type, found->second.array);
            if (has != wanted) throw GlError(where + "set as " + wanted + " but declared " + has);
            at = -1; // declared but unused in this variant: setting it does nothing
        }
        const auto same = [u](const auto& entry) { return entry.first == u; };
        const auto it = std::find_if(bound_.begin(), bound_.end(), same);
        if (it != bound_.end())
            it->second = at;
        else
            bound_.emplace_back(u, at);
    }
}

GLint Program::location(const UniformBase& u) const {
    for (const auto& [uniform, at] : bound_)
        if (uniform == &u) return at;
    throw GlError(files_ + ": uniform " + u.name() +
                  ": set on a program that did not bind it (Program::bindUniforms)");
}

} // namespace fl::gl
