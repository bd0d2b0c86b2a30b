// Loads every glTF file of Debian's assimp-testmodels (real-world and deliberately broken
// files). Each must either load into a scene that keeps the Scene invariants or be rejected
// with a SceneError naming the file; a crash, hang or sanitizer report fails the sweep.

#include <scene/GltfLoader.h>

#include <base/Finite.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

const fs::path kModels = "/usr/share/assimp/models/glTF2";

std::vector<fs::path> gltfFiles(const fs::path& root) {
    std::vector<fs::path> files;
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
        std::string ext = entry.path().extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(),
                       [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        if (entry.is_regular_file() && (ext == ".gltf" || ext == ".glb"))
            files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    return files;
}

/// The invariants every pass relies on (see Scene.h).
void checkScene(const fl::Scene& scene) {
    ASSERT_FALSE(scene.instances.empty());
    EXPECT_TRUE(scene.bounds.valid());
    EXPECT_TRUE(fl::geom::allFinite(scene.bounds.min) && fl::geom::allFinite(scene.bounds.max));
    for (const fl::Mesh& mesh : scene.meshes) {
        SCOPED_TRACE(mesh.name);
        EXPECT_EQ(mesh.normals.size(), mesh.positions.size());
        EXPECT_TRUE(mesh.texcoords.empty() || mesh.texcoords.size() == mesh.positions.size());
        EXPECT_EQ(mesh.indices.size() % 3, 0u);
        EXPECT_FALSE(mesh.indices.empty());
        EXPECT_TRUE(std::all_of(mesh.indices.begin(), mesh.indices.end(),
                                [&](std::uint32_t i) { return i < mesh.positions.size(); }));
        EXPECT_TRUE(std::all_of(mesh.positions.begin(), mesh.positions.end(),
                                [](const glm::vec3& p) { return fl::geom::allFinite(p); }));
        EXPECT_TRUE(std::all_of(mesh.normals.begin(), mesh.normals.end(), [](const glm::vec3& n) {
            return fl::geom::allFinite(n) && std::abs(glm::length(n) - 1.0f) < 1e-3f;
        }));
        EXPECT_TRUE(mesh.material >= -1 &&
                    mesh.material < static_cast<int>(scene.materials.size()));
    }
    for (const fl::Instance& inst : scene.instances) {
        EXPECT_TRUE(inst.mesh >= 0 && inst.mesh < static_cast<int>(scene.meshes.size()));
        EXPECT_GE(inst.objectId, 1u);
    }
    for (const fl::Material& m : scene.materials)
        EXPECT_TRUE(m.baseColorTexture >= -1 &&
                    m.baseColorTexture < static_cast<int>(scene.images.size()));
    for (const fl::Image& image : scene.images)
        EXPECT_EQ(image.rgba.size(), static_cast<std::size_t>(image.width) * image.height * 4);
    for (const fl::Camera& c : scene.cameras)
        EXPECT_TRUE(std::isfinite(c.zfar) && c.zfar > c.znear);
    if (scene.light) {
        EXPECT_TRUE(fl::geom::allFinite(scene.light->position) &&
                    fl::geom::allFinite(scene.light->direction));
    }
}

TEST(GltfSweep, AssimpTestModels) {
    if (!fs::is_directory(kModels))
        GTEST_SKIP() << kModels << " absent (install assimp-testmodels)";
    const std::vector<fs::path> files = gltfFiles(kModels);
    ASSERT_FALSE(files.empty());
    int loaded = 0, rejected = 0;
    for (const fs::path& file : files) {
        const std::string rel = fs::relative(file, kModels).string();
        SCOPED_TRACE(rel);
        std::vector<std::string> warnings;
        fl::LoadOptions options;
        options.warn = [&warnings](const std::string& w) { warnings.push_back(w); };
        try {
            const fl::Scene scene = fl::loadGltf(file, options);
            ++loaded;
            std::printf("LOADED   %-70s %zu meshes, %zu triangles, %zu images, %zu cameras, "
                        "%s, %zu warnings\n",
                        rel.c_str(), scene.meshes.size(), scene.triangleCount(),
                        scene.images.size(), scene.cameras.size(),
                        scene.light ? "light" : "no light", warnings.size());
            for (const std::string& w : warnings)
                std::printf("           warning: %s\n", w.c_str());
            checkScene(scene);
        } catch (const fl::SceneError& e) {
            ++rejected;
            const std::string message = e.what();
            std::printf("REJECTED %-70s %s\n", rel.c_str(), message.c_str());
            EXPECT_NE(message.find(file.filename().string()), std::string::npos) << message;
            EXPECT_GT(message.size(), file.filename().string().size() + 2) << message;
        }
    }
    std::printf("%zu files: %d loaded, %d rejected\n", files.size(), loaded, rejected);
}

} // namespace
