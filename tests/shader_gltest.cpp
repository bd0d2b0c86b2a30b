// Compile and link failures are fatal and name the file, the line and the driver's log; a
// program built again from the same sources reuses an idle one, as if it were new. Typed
// uniforms (gpu/Uniform.h) are checked when a program binds them, and every program the
// renderer, the overlays, the JFA kernels and the Delaunay steps build binds its table.

#include "GlTest.h"
#include "TestPaths.h"

#include "TestScenes.h"

#include <geometry_gl/GlDiscreteDelaunay.h>
#include <gpu/LiveObjects.h>
#include <gpu/Program.h>
#include <jfa/CpuKernel.h>
#include <jfa_gl/GlExactRepair.h>
#include <jfa_gl/GlJfa3d.h>
#include <jfa_gl/GlKernel.h>
#include <renderer/Renderer.h>
#include <renderer/overlays/Overlay.h>
#include <renderer/overlays/OverlayCanvas.h>
#include <renderer/passes/HudPass.h>
#include <renderer/passes/ShadowDiagnosticsPass.h>

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
        gl::Program p = gl::Program::build(lib, stages);
        first = p.id();
        constexpr gl::Uniform<int> count{"uCount"};
        constexpr gl::Uniform<float> scale{"uScale"};
        p.bindUniforms({&count, &scale});
        p.set(count, 3);
        p.set(scale, 2.5f);
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

// A compute shader with active uniforms of three kinds, one declared but unused (the compiler
// removes it), one declared only in a variant and one only in a comment.
gl::ShaderLibrary typedShaders() {
    const auto dir = outputDir("typed_uniforms");
    std::ofstream(dir / "typed.comp.glsl") << R"(#version 450 core
layout(local_size_x = 1) in;
uniform int uUsed;
uniform vec3 uOffset;
uniform float uWeights[4];
uniform vec2 uDeclaredUnused;
#ifdef VARIANT
uniform mat4 uOnlyInVariant;
#endif
// uniform float uInComment;
layout(std430, binding = 0) buffer Out { float o[]; };
void main() { o[0] = float(uUsed) + uOffset.y + uWeights[2]; }
)";
    return gl::ShaderLibrary(dir);
}

// bindUniforms' GlError for `u` on a fresh typed.comp.glsl program ("" if none).
std::string bindError(const gl::ShaderLibrary& lib, const gl::UniformBase& u) {
    gl::Program p = gl::Program::build(lib, {{GL_COMPUTE_SHADER, "typed.comp.glsl"}});
    try {
        p.bindUniforms({&u});
    } catch (const gl::GlError& e) {
        return e.what();
    }
    return {};
}

TEST_F(ShaderTest, TypedUniformsAreCheckedWhenBound) {
    const gl::ShaderLibrary lib = typedShaders();
    // A misspelt name, a name declared nowhere but in a comment, a type or an arrayness other
    // than the declaration's (active or removed): each fails at bind time, naming the
    // program's file and the uniform.
    constexpr gl::Uniform<int> misspelt{"uUsd"};
    constexpr gl::Uniform<float> onlyInAComment{"uInComment"};
    constexpr gl::Uniform<float> intAsFloat{"uUsed"};
    constexpr gl::Uniform<glm::vec4> vec3AsVec4{"uOffset"};
    constexpr gl::Uniform<float> arrayAsScalar{"uWeights"};
    constexpr gl::UniformArray<int> scalarAsArray{"uUsed"};
    constexpr gl::Uniform<float> removedVec2AsFloat{"uDeclaredUnused"};
    constexpr gl::Uniform<glm::mat3> variantMat4AsMat3{"uOnlyInVariant"};
    const struct {
        const gl::UniformBase* uniform;
        const char* expected; // in the message, after the file and the name
    } cases[] = {
        {&misspelt, "declared in none"},
        {&onlyInAComment, "declared in none"},
        {&intAsFloat, "set as float but the linked program's is int"},
        {&vec3AsVec4, "set as vec4 but the linked program's is vec3"},
        {&arrayAsScalar, "set as float but the linked program's is float[]"},
        {&scalarAsArray, "set as int[] but the linked program's is int"},
        {&removedVec2AsFloat, "set as float but declared vec2"},
        {&variantMat4AsMat3, "set as mat3 but declared mat4"},
    };
    for (const auto& c : cases) {
        const std::string msg = bindError(lib, *c.uniform);
        EXPECT_NE(msg.find(std::string("typed.comp.glsl: uniform ") + c.uniform->name() + ": "),
                  std::string::npos)
            << c.uniform->name() << ": " << msg;
        EXPECT_NE(msg.find(c.expected), std::string::npos) << c.uniform->name() << ": " << msg;
    }
}

TEST_F(ShaderTest, BoundUniformsSetTheirValuesAndInactiveOnesDoNothing) {
    const gl::ShaderLibrary lib = typedShaders();
    constexpr struct {
        gl::Uniform<int> used{"uUsed"};
        gl::Uniform<glm::vec3> offset{"uOffset"};
        gl::UniformArray<float> weights{"uWeights"};
        gl::Uniform<glm::vec2> declaredUnused{"uDeclaredUnused"};
        gl::Uniform<glm::mat4> onlyInVariant{"uOnlyInVariant"};
    } u;
    const std::vector<gl::StageSource> stages = {{GL_COMPUTE_SHADER, "typed.comp.glsl"}};
    GLuint first = 0;
    {
        gl::Program p = gl::Program::build(lib, stages);
        first = p.id();
        p.bindUniforms({&u.used, &u.offset, &u.weights, &u.declaredUnused, &u.onlyInVariant});
        EXPECT_EQ(p.location(u.declaredUnused), -1);
        EXPECT_EQ(p.location(u.onlyInVariant), -1);
        p.set(u.used, 3);
        p.set(u.offset, glm::vec3(1.0f, 2.0f, 3.0f));
        const std::array<float, 3> weights{0.5f, 1.5f, 2.5f};
        p.set(u.weights, weights);
        p.set(u.declaredUnused, glm::vec2(1.0f)); // removed by the compiler: nothing to set
        gl::throwIfErrors("setting typed uniforms");
        GLint used = 0;
        glGetUniformiv(p.id(), p.location(u.used), &used);
        EXPECT_EQ(used, 3);
        GLfloat third = 0.0f;
        glGetnUniformfv(p.id(), p.location("uWeights[2]"), sizeof(third), &third);
        EXPECT_EQ(third, 2.5f);
        // A uniform of the right name and type that this program never bound is refused.
        constexpr gl::Uniform<int> other{"uUsed"};
        EXPECT_THROW(p.set(other, 1), gl::GlError);
    }
    // The pooled program comes back to a new Program with nothing bound; bound again, its
    // locations are its own (the same GL program's).
    gl::Program again = gl::Program::build(lib, stages);
    EXPECT_EQ(again.id(), first) << "the idle program was not reused";
    EXPECT_THROW(again.set(u.used, 1), gl::GlError);
    again.bindUniforms({&u.used});
    EXPECT_EQ(again.location(u.used), glGetUniformLocation(again.id(), "uUsed"));
    EXPECT_NO_THROW(again.set(u.used, 1));
    // With the variant's define the uniform is declared but still unused: bound, inactive.
    gl::Program variant = gl::Program::build(lib, stages, {"VARIANT 1"});
    EXPECT_NO_THROW(variant.bindUniforms({&u.onlyInVariant}));
}

// Every program binds its uniform table when it is built, so building them all checks every
// table against its shaders: a Renderer per method of the table (each frame drawn too, so every
// set() finds its uniform bound, and the flooding methods' band programs get built), the
// overlays, the HUD, the aliasing diagnostics, the JFA kernels of both kinds with their band
// programs, the exact repair, the 3D flood and the Delaunay steps.
TEST_F(ShaderTest, EveryProgramBindsItsUniformTable) {
    const gl::ShaderLibrary& shaders = fl::test::testShaders();
    const Scene scene =
        groundAndBox(2.0f, {-0.5f, 0.5f, -0.5f}, {0.5f, 1.0f, 0.5f}, {0.3f, -1, 0.2f});
    const CameraView camera = makeCameraView(scene, {}, 1.0f);
    for (const MethodDescriptor& m : methodTable()) {
        SCOPED_TRACE(std::string(m.name));
        RenderSettings settings;
        settings.method = std::string(m.name);
        settings.shadow.size = 128;
        if (m.name == "reference") {
            settings.options.set("--reference-samples", 2);
            settings.options.set("--reference-map-size", 128);
        }
        if (m.name == "raytrace") settings.options.set("--raytrace-samples", 2);
        Renderer renderer(shaders, scene, settings);
        renderer.resize(32, 32);
        EXPECT_NO_THROW(renderer.render(camera));
    }
    EXPECT_NO_THROW(OverlayRenderer{shaders});
    EXPECT_NO_THROW(overlay::OverlayCanvas{shaders});
    EXPECT_NO_THROW(HudPass{shaders});
    EXPECT_NO_THROW(ShadowDiagnosticsPass{shaders});
    EXPECT_NO_THROW(jfa::GlExactRepair{shaders});
    EXPECT_NO_THROW(jfa::GlJfa3d{shaders});
    for (const jfa::GlKernelKind kind : {jfa::GlKernelKind::Fragment, jfa::GlKernelKind::Compute}) {
        EXPECT_NO_THROW(geom::GlDiscreteDelaunay(shaders, kind));
        jfa::GlFloodKernel<jfa::NearestSite> kernel(shaders, kind);
        kernel.setRegion(jfa::FloodRegion::Band);
        jfa::Grid seeds(16, 16, jfa::kEmptyCell);
        seeds.at(7, 5) = {7.0f, 5.0f, 0.0f, 0.0f}; // one site, id 0
        // Measuring a seed's reach builds the band's programs, the criterion's bound on each.
        const gl::Texture texture = jfa::uploadGrid(seeds);
        EXPECT_NO_THROW(kernel.maxSeedReach(texture, jfa::NearestSite{true}));
    }
}

TEST_F(ShaderTest, GlErrorsBecomeExceptions) {
    glBindTexture(GL_TEXTURE_2D, 0xdeadbeef); // not a texture name: GL_INVALID_OPERATION
    EXPECT_THROW(gl::throwIfErrors("deliberate"), gl::GlError);
    EXPECT_NO_THROW(gl::throwIfErrors("after"));
}

} // namespace
} // namespace fl::test
