// Shader sources: embedding, --shader-dir override, #include expansion and error-line mapping.

#include "TestPaths.h"

#include <gpu/Program.h>
#include <gpu/ShaderLibrary.h>

#include <gtest/gtest.h>

#include <fstream>

namespace fl::test {
namespace {

using gl::ShaderLibrary;

void writeFile(const std::filesystem::path& p, const std::string& text) {
    std::ofstream(p) << text;
}

TEST(ShaderLibrary, EveryShaderFileIsEmbeddedVerbatim) {
    const std::filesystem::path dir = std::filesystem::path(FLOODLIGHT_SOURCE_DIR) / "shaders";
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        if (entry.path().extension() != ".glsl") continue;
        ++files;
        std::ifstream in(entry.path(), std::ios::binary);
        const std::string disk((std::istreambuf_iterator<char>(in)), {});
        const ShaderLibrary embedded;
        EXPECT_EQ(embedded.read(entry.path().filename().string()), disk) << entry.path();
    }
    EXPECT_GE(files, 5);
    EXPECT_EQ(static_cast<size_t>(files), gl::embeddedShaders().size());
}

TEST(ShaderLibrary, DirectoryOverridesEmbedded) {
    const auto dir = outputDir("shaderdir");
    writeFile(dir / "x.glsl", "#version 450 core\nvoid main() {}\n");
    const ShaderLibrary lib(dir);
    EXPECT_EQ(lib.read("x.glsl"), "#version 450 core\nvoid main() {}\n");
    EXPECT_THROW((void)lib.read("surfaces.frag.glsl"), std::runtime_error); // embedded, not here
}

TEST(ShaderLibrary, MissingDirectoryIsAnError) {
    EXPECT_THROW(ShaderLibrary(std::filesystem::path("/nonexistent/shaders")), std::runtime_error);
}

TEST(ShaderLibrary, IncludesExpandWithLineDirectives) {
    const auto dir = outputDir("shaderinclude");
    writeFile(dir / "main.glsl",
              "#version 450 core\n// a\n#include \"lib.glsl\"\nvoid main() {}\n");
    writeFile(dir / "lib.glsl", "float f() { return 1.0; }\n");
    const ShaderLibrary lib(dir);
    std::vector<std::string> files;
    const std::string out = lib.expand("main.glsl", files);
    EXPECT_EQ(files, (std::vector<std::string>{"main.glsl", "lib.glsl"}));
    EXPECT_EQ(out, "#version 450 core\n#line 2 0\n// a\n#line 1 1\nfloat f() { return 1.0; }\n"
                   "#line 4 0\nvoid main() {}\n");
}

TEST(ShaderLibrary, IncludeCycleIsAnError) {
    const auto dir = outputDir("shadercycle");
    writeFile(dir / "a.glsl", "#version 450 core\n#include \"b.glsl\"\n");
    writeFile(dir / "b.glsl", "#include \"a.glsl\"\n");
    const ShaderLibrary lib(dir);
    std::vector<std::string> files;
    EXPECT_THROW((void)lib.expand("a.glsl", files), std::runtime_error);
}

TEST(ShaderLibrary, InfoLogNamesFileAndLine) {
    const std::vector<std::string> files{"main.glsl", "lib.glsl"};
    EXPECT_EQ(gl::mapInfoLog("1:7(12): error: `x' undeclared\n", files),
              "lib.glsl:7:12: error: `x' undeclared\n");
    EXPECT_EQ(gl::mapInfoLog("0(3) : error C1008: undefined variable\n", files),
              "main.glsl:3: error C1008: undefined variable\n");
    // NVIDIA's warnings and a line with no message after the reference.
    EXPECT_EQ(gl::mapInfoLog("1(2) : warning C7050: unused\n0(4)\n", files),
              "lib.glsl:2: warning C7050: unused\nmain.glsl:4:\n");
    EXPECT_EQ(gl::mapInfoLog("plain line\n", files), "plain line\n");
}

} // namespace
} // namespace fl::test
