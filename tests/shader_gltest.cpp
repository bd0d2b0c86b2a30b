// Compile and link failures are fatal and name the file, the line and the driver's log.

#include "GlTest.h"
#include "TestPaths.h"

#include <gpu/Program.h>

#include <fstream>

namespace fl::test {
namespace {

class ShaderTest : public GlTest {};

TEST_F(ShaderTest, EveryEmbeddedProgramCompiles) {
    const gl::ShaderLibrary lib;
    EXPECT_NO_THROW(gl::Program::build(lib, {{GL_VERTEX_SHADER, "forward.vert.glsl"},
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

TEST_F(ShaderTest, GlErrorsBecomeExceptions) {
    glBindTexture(GL_TEXTURE_2D, 0xdeadbeef); // not a texture name: GL_INVALID_OPERATION
    EXPECT_THROW(gl::throwIfErrors("deliberate"), gl::GlError);
    EXPECT_NO_THROW(gl::throwIfErrors("after"));
}

} // namespace
} // namespace fl::test
