#include <gpu/LiveObjects.h>
#include <gpu/Program.h>

#include "ProgramPool.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstring>
#include <sstream>

namespace fl::gl {

namespace {

const char* stageName(GLenum stage) {
    switch (stage) {
    case GL_VERTEX_SHADER:
        return "vertex";
    case GL_FRAGMENT_SHADER:
        return "fragment";
    case GL_COMPUTE_SHADER:
        return "compute";
    case GL_GEOMETRY_SHADER:
        return "geometry";
    default:
        return "shader";
    }
}

// Inserts `defines` right after the #version line, then restores line numbering with #line.
std::string withDefines(const std::string& source, const std::vector<std::string>& defines) {
    if (defines.empty()) return source;
    const size_t eol = source.find('\n');
    if (eol == std::string::npos) return source;
    std::string out = source.substr(0, eol + 1);
    // ShaderLibrary::expand already put "#line 2 0" after #version, so numbering survives.
    for (const std::string& d : defines) out += "#define " + d + "\n";
    out += source.substr(eol + 1);
    return out;
}

std::string infoLog(GLuint object, bool isProgram) {
    GLint length = 0;
    if (isProgram)
        glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
    else
        glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<size_t>(std::max(length, 1)), '\0');
    if (isProgram)
        glGetProgramInfoLog(object, length, nullptr, log.data());
    else
        glGetShaderInfoLog(object, length, nullptr, log.data());
    log.resize(std::strlen(log.c_str()));
    return log;
}

// One stage's source as the driver sees it, and the files its #line numbers refer to.
struct ExpandedStage {
    const StageSource* stage;
    std::string source;
    std::vector<std::string> files;
};

Shader compile(const ExpandedStage& s) {
    Shader shader(glCreateShader(s.stage->stage));
    noteCreated(ObjectKind::Shader, shader.id());
    const char* text = s.source.c_str();
    glShaderSource(shader.id(), 1, &text, nullptr);
    glCompileShader(shader.id());
    GLint ok = 0;
    glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
    if (!ok) {
        throw GlError(s.stage->file + ": " + stageName(s.stage->stage) +
                      " shader failed to compile:\n" +
                      mapInfoLog(infoLog(shader.id(), false), s.files));
    }
    return shader;
}

} // namespace

namespace {

// Reads decimal digits at s[pos]; false if there are none.
bool readNumber(const std::string& s, size_t& pos, size_t& value) {
    const size_t start = pos;
    value = 0;
    while (pos < s.size() && s[pos] >= '0' && s[pos] <= '9')
        value = value * 10 + size_t(s[pos++] - '0');
    return pos > start;
}

} // namespace

std::string mapInfoLog(const std::string& log, const std::vector<std::string>& files) {
    // Mesa: "0:12(5): error: ..."; NVIDIA: "0(12) : error ...". Both start with the
    // source-string number our #line directives assigned to a file. Both become
    // "file:line:..." (Mesa "file:12:5: error: ...", NVIDIA "file:12: error ...").
    std::istringstream in(log);
    std::ostringstream out;
    std::string line;
    while (std::getline(in, line)) {
        size_t pos = 0, source = 0, lineNo = 0, column = 0;
        const bool hasSource = readNumber(line, pos, source);
        const bool mesa = hasSource && pos < line.size() && line[pos] == ':' &&
                          readNumber(line, ++pos, lineNo) && pos < line.size() &&
                          line[pos] == '(' && readNumber(line, ++pos, column) &&
                          pos < line.size() && line[pos] == ')';
        size_t npos = 0;
        const bool nvidia = !mesa && readNumber(line, npos, source) && npos < line.size() &&
                            line[npos] == '(' && readNumber(line, ++npos, lineNo) &&
                            npos < line.size() && line[npos] == ')';
        const std::string file =
            source < files.size() ? files[source] : "source " + std::to_string(source);
        if (mesa)
            out << file << ":" << lineNo << ":" << column << line.substr(pos + 1) << "\n";
        else if (nvidia) {
            // "0(12) : error C1008: ..." -> "file:12: error C1008: ...", Mesa's shape less the
            // column (NVIDIA gives none), so that one pattern finds a line on either driver.
            std::size_t rest = npos + 1;
            while (rest < line.size() && line[rest] == ' ') ++rest;
            if (rest < line.size() && line[rest] == ':') ++rest;
            while (rest < line.size() && line[rest] == ' ') ++rest;
            out << file << ":" << lineNo << ":" << (rest < line.size() ? " " : "")
                << line.substr(rest) << "\n";
        } else if (!line.empty())
            out << line << "\n";
    }
    return out.str();
}

Program Program::build(const ShaderLibrary& library, const std::vector<StageSource>& stages,
                       const std::vector<std::string>& defines) {
    std::vector<ExpandedStage> expanded;
    std::string key, names;
    for (const StageSource& s : stages) {
        ExpandedStage e{&s, {}, {}};
        e.source = withDefines(library.expand(s.file, e.files), defines);
        key += std::to_string(s.stage) + '\n' + e.source + '\0';
        names += (names.empty() ? "" : " + ") + s.file;
        expanded.push_back(std::move(e));
    }
    const std::shared_ptr<ProgramPool>& pool = library.programPool();
    Program p;
    if (const GLuint reused = pool->take(key)) {
        p.handle_ = ProgramHandle(reused);
        p.pool_ = pool;
        p.key_ = std::move(key);
        p.files_ = std::move(names);
        return p;
    }
    std::vector<Shader> shaders;
    for (const ExpandedStage& e : expanded) shaders.push_back(compile(e));
    p.handle_ = ProgramHandle(glCreateProgram());
    noteCreated(ObjectKind::Program, p.id());
    for (const Shader& s : shaders) glAttachShader(p.id(), s.id());
    glLinkProgram(p.id());
    for (const Shader& s : shaders) glDetachShader(p.id(), s.id());
    GLint ok = 0;
    glGetProgramiv(p.id(), GL_LINK_STATUS, &ok);
    if (!ok) throw GlError(names + ": program failed to link:\n" + infoLog(p.id(), true));
    pool->remember(p.id());
    p.pool_ = pool; // from here on the program goes back to the pool rather than being deleted
    p.key_ = std::move(key);
    p.files_ = std::move(names);
    return p;
}

Program& Program::operator=(Program&& o) noexcept {
    if (this != &o) {
        giveBack();
        handle_ = std::move(o.handle_);
        pool_ = std::move(o.pool_);
        key_ = std::move(o.key_);
        files_ = std::move(o.files_);
        bound_ = std::move(o.bound_);
    }
    return *this;
}

Program::~Program() {
    giveBack();
}

void Program::giveBack() {
    if (!handle_) return;
    if (const std::shared_ptr<ProgramPool> pool = pool_.lock())
        pool->giveBack(key_, handle_.release());
    else
        handle_.reset();
}

GLint Program::location(const char* name) const {
    return glGetUniformLocation(id(), name);
}

// bind() and the uniform checks are in Uniform.cpp.

void Program::upload(GLint at, int v) const {
    if (at >= 0) glProgramUniform1i(id(), at, v);
}
void Program::upload(GLint at, float v) const {
    if (at >= 0) glProgramUniform1f(id(), at, v);
}
void Program::upload(GLint at, const glm::ivec2& v) const {
    if (at >= 0) glProgramUniform2iv(id(), at, 1, glm::value_ptr(v));
}
void Program::upload(GLint at, const glm::ivec3& v) const {
    if (at >= 0) glProgramUniform3iv(id(), at, 1, glm::value_ptr(v));
}
void Program::upload(GLint at, const glm::ivec4& v) const {
    if (at >= 0) glProgramUniform4iv(id(), at, 1, glm::value_ptr(v));
}
void Program::upload(GLint at, const glm::vec2& v) const {
    if (at >= 0) glProgramUniform2fv(id(), at, 1, glm::value_ptr(v));
}
void Program::upload(GLint at, const glm::vec3& v) const {
    if (at >= 0) glProgramUniform3fv(id(), at, 1, glm::value_ptr(v));
}
void Program::upload(GLint at, const glm::vec4& v) const {
    if (at >= 0) glProgramUniform4fv(id(), at, 1, glm::value_ptr(v));
}
void Program::upload(GLint at, const glm::mat3& v) const {
    if (at >= 0) glProgramUniformMatrix3fv(id(), at, 1, GL_FALSE, glm::value_ptr(v));
}
void Program::upload(GLint at, const glm::mat4& v) const {
    if (at >= 0) glProgramUniformMatrix4fv(id(), at, 1, GL_FALSE, glm::value_ptr(v));
}
void Program::upload(GLint at, std::span<const glm::vec2> v) const {
    if (at >= 0 && !v.empty())
        glProgramUniform2fv(id(), at, static_cast<GLsizei>(v.size()), glm::value_ptr(v[0]));
}
void Program::upload(GLint at, std::span<const float> v) const {
    if (at >= 0 && !v.empty())
        glProgramUniform1fv(id(), at, static_cast<GLsizei>(v.size()), v.data());
}

void drawFullscreenTriangle(const Program& program, const VertexArray& emptyVao) {
    glUseProgram(program.id());
    glBindVertexArray(emptyVao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glUseProgram(0);
}

void drawMarkedThenRefined(const std::function<void(const Program&)>& draw, const Program& mark,
                           const Program* refine) {
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    draw(mark);
    if (refine) {
        glDepthFunc(GL_GREATER);
        glDepthMask(GL_FALSE);
        draw(*refine);
    }
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
}

} // namespace fl::gl
