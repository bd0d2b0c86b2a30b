// Compile and link failures are fatal and name the file, the line and the driver's log; a
// program built again from the same sources reuses an idle one, as if it were new.

#include "GlTest.h"
#include "TestPaths.h"

#include <gpu/LiveObjects.h>
#include <gpu/Program.h>

#include <fstream>
#include <optional>

namespace fl::test {
namespace {

class ShaderTest : public GlTest {};

TEST_F(ShaderTest, EveryEmbeddedProgramCompiles) {
    const gl::ShaderLibrary lib;
    EXPECT_NO_THROW(gl::Program::build(lib, {{GL_VERTEX_SHADER, "forward.vert.glsl"},
                                             {GL_GEOMETRY_SHADER, "surfaces.geom.glsl"},
                                             {GL_FRAGMENT_SHADER, "surfaces.frag.glsl"}}));
    EXPECT_NO_THROW(gl::Program::build(lib, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                             {GL_FRAGMENT_SHADER, "shading.frag.glsl"}}));
    EXPECT_NO_THROW(gl::Program::build(lib, {{GL_VERTEX_SHADER, "shadow_depth.vert.glsl"},
                                             {GL_FRAGMENT_SHADER, "shadow_depth.frag.glsl"}}));
    EXPECT_NO_THROW(gl::Program::build(lib, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                             {GL_FRAGMENT_SHADER, "present.frag.glsl"}}));
}

TEST_F(ShaderTest, CompileErrorNamesIncludedFileAndLine) {
    const auto dir = outputDir("badshader");
    std::ofstream(dir / "bad.frag.glsl")
        << "#version 450 core\nout vec4 o;\n#include \"broken.glsl\"\nvoid main() { o = f(); }\n";
    std::ofstream(dir / "broken.glsl") << "vec4 f() {\n  return undeclaredThing;\n}\n";
    const gl::ShaderLibrary lib(dir);
    try {
        gl::Program::build(lib, {{GL_FRAGMENT_SHADER, "bad.frag.glsl"}});
        FAIL() << "a broken shader compiled";
    } catch (const gl::GlError& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("bad.frag.glsl: fragment shader failed to compile"), std::string::npos)
            << msg;
        EXPECT_NE(msg.find("broken.glsl:2:"), std::string::npos) << msg;
        EXPECT_NE(msg.find("undeclaredThing"), std::string::npos) << msg;
    }
}

TEST_F(ShaderTest, LinkErrorIsFatal) {
    const auto dir = outputDir("badlink");
    std::ofstream(dir / "v.glsl") << "#version 450 core\nvoid main() { gl_Position = vec4(0); }\n";
    std::ofstream(dir / "f.glsl")
        << "#version 450 core\nvec4 missing();\nout vec4 o;\nvoid main() { o = missing(); }\n";
    const gl::ShaderLibrary lib(dir);
    try {
        gl::Program::build(lib, {{GL_VERTEX_SHADER, "v.glsl"}, {GL_FRAGMENT_SHADER, "f.glsl"}});
        FAIL() << "a program with an undefined function linked";
    } catch (const gl::GlError& e) {
        EXPECT_NE(std::string(e.what()).find("v.glsl + f.glsl: program failed to link"),
                  std::string::npos)
            << e.what();
    }
}

// A compute shader with uniforms of several kinds, one with a GLSL initialiser, and an array.
gl::ShaderLibrary poolShaders() {
    const auto dir = outputDir("program_pool");
    std::ofstream(dir / "u.comp.glsl") << R"(#version 450 core
layout(local_size_x = 1) in;
uniform int uCount = 7;
uniform float uScale;
uniform vec3 uOffsets[3];
uniform mat3 uBasis;
uniform uvec2 uMask = uvec2(5u, 9u);
layout(std430, binding = 0) buffer Out { float o[]; };
void main() { o[0] = float(uCount) * uScale + uOffsets[2].y + uBasis[1][2] + float(uMask.y); }
)";
    return gl::ShaderLibrary(dir);
}

int intUniform(const gl::Program& p, const char* name) {
    GLint v = 0;
    glGetUniformiv(p.id(), p.location(name), &v);
    return v;
}
float floatUniform(const gl::Program& p, const char* name) {
    GLfloat v[9] = {};
    glGetnUniformfv(p.id(), p.location(name), sizeof(v), v);
    return v[0] + v[5]; // a scalar, or a mat3's [0][0] + [1][2]
}

TEST_F(ShaderTest, AReusedProgramStartsWithItsJustLinkedUniforms) {
    const gl::ShaderLibrary lib = poolShaders();
    const std::vector<gl::StageSource> stages = {{GL_COMPUTE_SHADER, "u.comp.glsl"}};
    GLuint first = 0;
    {
        const gl::Program p = gl::Program::build(lib, stages);
        first = p.id();
        p.set("uCount", 3);
        p.set("uScale", 2.5f);
        glProgramUniform3f(p.id(), p.location("uOffsets[2]"), 1.0f, 4.0f, 1.0f);
        glProgramUniformMatrix3fv(p.id(), p.location("uBasis"), 1, GL_FALSE,
                                  std::array<float, 9>{1, 1, 1, 1, 1, 6, 1, 1, 1}.data());
        glProgramUniform2ui(p.id(), p.location("uMask"), 1u, 2u);
    }
    const gl::Program again = gl::Program::build(lib, stages);
    EXPECT_EQ(again.id(), first) << "the idle program was not reused";
    EXPECT_EQ(intUniform(again, "uCount"), 7); // its initialiser, not the 3 set before
    EXPECT_EQ(floatUniform(again, "uScale"), 0.0f);
    GLfloat offset[3] = {9, 9, 9};
    glGetnUniformfv(again.id(), again.location("uOffsets[2]"), sizeof(offset), offset);
    EXPECT_EQ(offset[1], 0.0f);
    EXPECT_EQ(floatUniform(again, "uBasis"), 0.0f);
    GLuint mask[2] = {};
    glGetnUniformuiv(again.id(), again.location("uMask"), sizeof(mask), mask);
    EXPECT_EQ(mask[0], 5u);
    EXPECT_EQ(mask[1], 9u);
}

TEST_F(ShaderTest, LiveProgramsAreNeverSharedAndDefinesMakeAnotherProgram) {
    const gl::ShaderLibrary lib = poolShaders();
    const std::vector<gl::StageSource> stages = {{GL_COMPUTE_SHADER, "u.comp.glsl"}};
    const gl::Program a = gl::Program::build(lib, stages);
    const gl::Program b = gl::Program::build(lib, stages);
    EXPECT_NE(a.id(), b.id());
    GLuint defined = 0;
    {
        const gl::Program c = gl::Program::build(lib, stages, {"SOMETHING 1"});
        defined = c.id();
    }
    // The idle program made with the define is not lent for the sources without it.
    const gl::Program d = gl::Program::build(lib, stages);
    EXPECT_NE(d.id(), defined);
    EXPECT_NE(d.id(), a.id());
    EXPECT_NE(d.id(), b.id());
}

TEST_F(ShaderTest, IdleProgramsGoWithTheLibraryAndItsCopies) {
    const gl::ObjectCounts before = gl::countLiveObjects();
    const auto programs = static_cast<std::size_t>(gl::ObjectKind::Program);
    std::optional<gl::Program> outlives;
    {
        std::optional<gl::ShaderLibrary> lib(poolShaders());
        const gl::ShaderLibrary copy = *lib; // as a Renderer keeps one
        { const gl::Program p = gl::Program::build(*lib, {{GL_COMPUTE_SHADER, "u.comp.glsl"}}); }
        lib.reset();
        // The copy shares the pool: the idle program is still there to be lent.
        outlives = gl::Program::build(copy, {{GL_COMPUTE_SHADER, "u.comp.glsl"}});
        EXPECT_EQ(gl::countLiveObjects().live[programs], before.live[programs] + 1);
    }
    // Its pool is gone: the program is deleted, not kept.
    outlives.reset();
    EXPECT_EQ(gl::countLiveObjects().live, before.live);
}

TEST_F(ShaderTest, GlErrorsBecomeExceptions) {
    glBindTexture(GL_TEXTURE_2D, 0xdeadbeef); // not a texture name: GL_INVALID_OPERATION
    EXPECT_THROW(gl::throwIfErrors("deliberate"), gl::GlError);
    EXPECT_NO_THROW(gl::throwIfErrors("after"));
}

} // namespace
} // namespace fl::test
