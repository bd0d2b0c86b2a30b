#include "ProgramPool.h"

#include <cstring>

namespace fl::gl {

namespace {

// How a uniform type is read and written: its scalar kind and shape (matrices: columns x rows).
enum class Scalar { Float, Int, Uint };
struct Shape {
    Scalar scalar;
    int columns; // 1 for scalars and vectors
    int rows;    // components of a vector
};

Shape shapeOf(GLenum type) {
    switch (type) {
    case GL_FLOAT:
        return {Scalar::Float, 1, 1};
    case GL_FLOAT_VEC2:
        return {Scalar::Float, 1, 2};
    case GL_FLOAT_VEC3:
        return {Scalar::Float, 1, 3};
    case GL_FLOAT_VEC4:
        return {Scalar::Float, 1, 4};
    case GL_FLOAT_MAT2:
        return {Scalar::Float, 2, 2};
    case GL_FLOAT_MAT3:
        return {Scalar::Float, 3, 3};
    case GL_FLOAT_MAT4:
        return {Scalar::Float, 4, 4};
    case GL_FLOAT_MAT2x3:
        return {Scalar::Float, 2, 3};
    case GL_FLOAT_MAT2x4:
        return {Scalar::Float, 2, 4};
    case GL_FLOAT_MAT3x2:
        return {Scalar::Float, 3, 2};
    case GL_FLOAT_MAT3x4:
        return {Scalar::Float, 3, 4};
    case GL_FLOAT_MAT4x2:
        return {Scalar::Float, 4, 2};
    case GL_FLOAT_MAT4x3:
        return {Scalar::Float, 4, 3};
    case GL_INT_VEC2:
    case GL_BOOL_VEC2:
        return {Scalar::Int, 1, 2};
    case GL_INT_VEC3:
    case GL_BOOL_VEC3:
        return {Scalar::Int, 1, 3};
    case GL_INT_VEC4:
    case GL_BOOL_VEC4:
        return {Scalar::Int, 1, 4};
    case GL_UNSIGNED_INT:
        return {Scalar::Uint, 1, 1};
    case GL_UNSIGNED_INT_VEC2:
        return {Scalar::Uint, 1, 2};
    case GL_UNSIGNED_INT_VEC3:
        return {Scalar::Uint, 1, 3};
    case GL_UNSIGNED_INT_VEC4:
        return {Scalar::Uint, 1, 4};
    // int, bool, samplers and images: one int. (Doubles are not used by our shaders; were one
    // added, setting it as an int is a GL error that throwIfErrors reports.)
    default:
        return {Scalar::Int, 1, 1};
    }
}

void setMatrix(GLuint p, GLint at, const Shape& s, const GLfloat* v) {
    using Setter = void (*)(GLuint, GLint, GLsizei, GLboolean, const GLfloat*);
    // [columns - 2][rows - 2]
    const Setter setters[3][3] = {
        {glProgramUniformMatrix2fv, glProgramUniformMatrix2x3fv, glProgramUniformMatrix2x4fv},
        {glProgramUniformMatrix3x2fv, glProgramUniformMatrix3fv, glProgramUniformMatrix3x4fv},
        {glProgramUniformMatrix4x2fv, glProgramUniformMatrix4x3fv, glProgramUniformMatrix4fv}};
    setters[s.columns - 2][s.rows - 2](p, at, 1, GL_FALSE, v);
}

// glProgramUniform{1,2,3,4}{f,i,ui}v for a vector of `width` components of type T.
template <typename T, typename Setter>
void setVector(Setter one, Setter two, Setter three, Setter four, GLuint p, GLint at, int width,
               const void* bits) {
    const Setter setters[4] = {one, two, three, four};
    setters[width - 1](p, at, 1, static_cast<const T*>(bits));
}

void setValue(GLuint p, GLint at, GLenum type, const void* bits) {
    const Shape s = shapeOf(type);
    if (s.columns > 1) return setMatrix(p, at, s, static_cast<const GLfloat*>(bits));
    switch (s.scalar) {
    case Scalar::Float:
        return setVector<GLfloat>(glProgramUniform1fv, glProgramUniform2fv, glProgramUniform3fv,
                                  glProgramUniform4fv, p, at, s.rows, bits);
    case Scalar::Int:
        return setVector<GLint>(glProgramUniform1iv, glProgramUniform2iv, glProgramUniform3iv,
                                glProgramUniform4iv, p, at, s.rows, bits);
    case Scalar::Uint:
        return setVector<GLuint>(glProgramUniform1uiv, glProgramUniform2uiv, glProgramUniform3uiv,
                                 glProgramUniform4uiv, p, at, s.rows, bits);
    }
}

} // namespace

ProgramPool::~ProgramPool() {
    for (const auto& [key, programs] : idle_)
        for (GLuint p : programs) glDeleteProgram(p);
}

GLuint ProgramPool::take(const std::string& key) {
    const auto it = idle_.find(key);
    if (it == idle_.end() || it->second.empty()) return 0;
    const GLuint p = it->second.back();
    it->second.pop_back();
    restore(p, linked_.at(p));
    return p;
}

void ProgramPool::remember(GLuint program) {
    linked_[program] = snapshot(program);
}

void ProgramPool::giveBack(const std::string& key, GLuint program) {
    idle_[key].push_back(program);
}

std::vector<ProgramPool::UniformValue> ProgramPool::snapshot(GLuint program) {
    std::vector<UniformValue> out;
    GLint count = 0;
    glGetProgramInterfaceiv(program, GL_UNIFORM, GL_ACTIVE_RESOURCES, &count);
    for (GLint r = 0; r < count; ++r) {
        const GLenum props[] = {GL_BLOCK_INDEX, GL_TYPE, GL_ARRAY_SIZE, GL_NAME_LENGTH};
        GLint v[4] = {};
        glGetProgramResourceiv(program, GL_UNIFORM, GLuint(r), 4, props, 4, nullptr, v);
        if (v[0] != -1) continue; // in a uniform block: a buffer's contents, not program state
        std::string name(std::size_t(v[3]), '\0');
        glGetProgramResourceName(program, GL_UNIFORM, GLuint(r), v[3], nullptr, name.data());
        name.resize(std::strlen(name.c_str()));
        // Arrays are named "a[0]": each element has its own location.
        const bool array = name.ends_with("[0]");
        const std::string base = array ? name.substr(0, name.size() - 3) : name;
        for (GLint e = 0; e < v[2]; ++e) {
            const std::string element = array ? base + "[" + std::to_string(e) + "]" : name;
            const GLint at = glGetProgramResourceLocation(program, GL_UNIFORM, element.c_str());
            if (at < 0) continue; // atomic counters and the like have no location
            UniformValue u{at, GLenum(v[1]), {}};
            const GLsizei bytes = sizeof(u.bits);
            switch (shapeOf(u.type).scalar) {
            case Scalar::Float:
                glGetnUniformfv(program, at, bytes, reinterpret_cast<GLfloat*>(u.bits.data()));
                break;
            case Scalar::Int:
                glGetnUniformiv(program, at, bytes, reinterpret_cast<GLint*>(u.bits.data()));
                break;
            case Scalar::Uint:
                glGetnUniformuiv(program, at, bytes, u.bits.data());
                break;
            }
            out.push_back(u);
        }
    }
    return out;
}

void ProgramPool::restore(GLuint program, const std::vector<UniformValue>& values) {
    for (const UniformValue& u : values) setValue(program, u.location, u.type, u.bits.data());
}

} // namespace fl::gl
