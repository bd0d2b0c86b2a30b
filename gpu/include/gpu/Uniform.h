#pragma once
// Typed uniforms. A pass declares the uniforms it sets once, as a table of gl::Uniform<T> (a name
// and the C++ type that stands for one GLSL type), and binds the table to its program right after
// building it (Program::bindUniforms). Binding checks every entry against the linked program and
// caches its location; Program::set then takes a bound Uniform<T> and a T only. A misspelt name, a
// type other than the shader's, or a uniform set on a program that never bound it throws GlError
// naming the program's files and the uniform, where setting by name did nothing, silently.
//
// A table is an object with static storage (usually a constexpr struct in the pass's .cpp, or an
// inline constexpr one in a header when several passes share it): a program caches locations by
// the Uniform's address, so the object bound must be the object set.

#include <epoxy/gl.h>
#include <glm/glm.hpp>

namespace fl::gl {

/// The GLSL type a C++ uniform type stands for: `gl` as glGetProgramResourceiv's GL_TYPE reads,
/// `glsl` as a declaration spells it. Only the types some pass sets are defined.
template <class T>
struct UniformType;

#define FL_UNIFORM_TYPE(CppType, GlType, GlslName)                                                 \
    template <>                                                                                    \
    struct UniformType<CppType> {                                                                  \
        static constexpr GLenum gl = GlType;                                                       \
        static constexpr const char* glsl = GlslName;                                              \
    }
FL_UNIFORM_TYPE(int, GL_INT, "int");
FL_UNIFORM_TYPE(float, GL_FLOAT, "float");
FL_UNIFORM_TYPE(glm::ivec2, GL_INT_VEC2, "ivec2");
FL_UNIFORM_TYPE(glm::ivec3, GL_INT_VEC3, "ivec3");
FL_UNIFORM_TYPE(glm::ivec4, GL_INT_VEC4, "ivec4");
FL_UNIFORM_TYPE(glm::vec2, GL_FLOAT_VEC2, "vec2");
FL_UNIFORM_TYPE(glm::vec3, GL_FLOAT_VEC3, "vec3");
FL_UNIFORM_TYPE(glm::vec4, GL_FLOAT_VEC4, "vec4");
FL_UNIFORM_TYPE(glm::mat3, GL_FLOAT_MAT3, "mat3");
FL_UNIFORM_TYPE(glm::mat4, GL_FLOAT_MAT4, "mat4");
#undef FL_UNIFORM_TYPE

/// What Program::bindUniforms checks for any uniform: its name, its GLSL type and whether it is an
/// array.
class UniformBase {
  public:
    constexpr UniformBase(const char* name, GLenum type, const char* glsl, bool array)
        : name_(name), type_(type), glsl_(glsl), array_(array) {}
    UniformBase(const UniformBase&) = delete; // a copy would be another, unbound, uniform
    UniformBase& operator=(const UniformBase&) = delete;

    [[nodiscard]] constexpr const char* name() const { return name_; }
    [[nodiscard]] constexpr GLenum type() const { return type_; }
    [[nodiscard]] constexpr const char* glsl() const { return glsl_; }
    [[nodiscard]] constexpr bool array() const { return array_; }

  private:
    const char* name_;
    GLenum type_;
    const char* glsl_;
    bool array_;
};

/// One uniform `uniform <glsl> name;` whose C++ type is T.
template <class T>
class Uniform : public UniformBase {
  public:
    explicit constexpr Uniform(const char* name)
        : UniformBase(name, UniformType<T>::gl, UniformType<T>::glsl, false) {}
};

/// A uniform array `uniform <glsl> name[N];` of elements T, set from a span of at most N.
template <class T>
class UniformArray : public UniformBase {
  public:
    explicit constexpr UniformArray(const char* name)
        : UniformBase(name, UniformType<T>::gl, UniformType<T>::glsl, true) {}
};

} // namespace fl::gl
