// The default-scene generator (exact sizes, determinism, valid geometry, a plausible layout) and
// the GLB writer (file structure, determinism, I/O errors, round trip through loadGltf).

#include <scene/GltfLoader.h>
#include <scene/SceneGenerator.h>

#include "TestPaths.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>

namespace fl {
namespace {

std::vector<std::uint8_t> readFile(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::uint32_t u32At(const std::vector<std::uint8_t>& b, std::size_t at) {
    return static_cast<std::uint32_t>(b[at]) | static_cast<std::uint32_t>(b[at + 1]) << 8 |
           static_cast<std::uint32_t>(b[at + 2]) << 16 |
           static_cast<std::uint32_t>(b[at + 3]) << 24;
}

const Instance* findInstance(const Scene& s, const std::string& name) {
    for (const Instance& i : s.instances)
        if (i.nodeName == name) return &i;
    return nullptr;
}

glm::vec3 worldPos(const Instance& inst, const glm::vec3& p) {
    return glm::vec3(inst.world * glm::vec4(p, 1.0f));
}

/// Height of the terrain mesh under (x, z), found through a bucket grid of its triangles.
class TerrainSampler {
  public:
    explicit TerrainSampler(const Scene& s) {
        const Instance* inst = findInstance(s, "terrain");
        if (!inst) throw std::runtime_error("no terrain");
        const Mesh& m = s.meshes[static_cast<std::size_t>(inst->mesh)];
        for (const glm::vec3& p : m.positions) pts_.push_back(worldPos(*inst, p));
        idx_ = m.indices;
        lo_ = glm::vec2(1e9f);
        hi_ = glm::vec2(-1e9f);
        for (const glm::vec3& p : pts_) {
            lo_ = glm::min(lo_, glm::vec2(p.x, p.z));
            hi_ = glm::max(hi_, glm::vec2(p.x, p.z));
        }
        cells_.resize(kGrid * kGrid);
        for (std::size_t t = 0; t < idx_.size() / 3; ++t) {
            glm::vec2 a(1e9f), b(-1e9f);
            for (int k = 0; k < 3; ++k) {
                const glm::vec3& p = pts_[idx_[3 * t + static_cast<std::size_t>(k)]];
                a = glm::min(a, glm::vec2(p.x, p.z));
                b = glm::max(b, glm::vec2(p.x, p.z));
            }
            const glm::ivec2 ca = cell(a), cb = cell(b);
            for (int z = ca.y; z <= cb.y; ++z)
                for (int x = ca.x; x <= cb.x; ++x)
                    cells_[static_cast<std::size_t>(z * kGrid + x)].push_back(t);
        }
    }
    [[nodiscard]] std::optional<float> height(float x, float z) const {
        const glm::ivec2 c = cell({x, z});
        for (std::size_t t : cells_[static_cast<std::size_t>(c.y * kGrid + c.x)]) {
            const glm::vec3& a = pts_[idx_[3 * t]];
            const glm::vec3& b = pts_[idx_[3 * t + 1]];
            const glm::vec3& d = pts_[idx_[3 * t + 2]];
            const float det = (b.x - a.x) * (d.z - a.z) - (d.x - a.x) * (b.z - a.z);
            const float u = ((x - a.x) * (d.z - a.z) - (d.x - a.x) * (z - a.z)) / det;
            const float v = ((b.x - a.x) * (z - a.z) - (x - a.x) * (b.z - a.z)) / det;
            if (u >= -1e-5f && v >= -1e-5f && u + v <= 1.0f + 1e-5f)
                return a.y + u * (b.y - a.y) + v * (d.y - a.y);
        }
        return std::nullopt;
    }

  private:
    static constexpr int kGrid = 64;
    glm::ivec2 cell(glm::vec2 p) const {
        const glm::vec2 t = (p - lo_) / (hi_ - lo_) * static_cast<float>(kGrid);
        return glm::clamp(glm::ivec2(t), glm::ivec2(0), glm::ivec2(kGrid - 1));
    }
    std::vector<glm::vec3> pts_;
    std::vector<std::uint32_t> idx_;
    glm::vec2 lo_{}, hi_{};
    std::vector<std::vector<std::size_t>> cells_;
};

// ---- sizes ------------------------------------------------------------------------------------

TEST(SceneGenerator, ExactTriangleCountForThesisSizes) {
    ASSERT_EQ(thesisSceneSizes().size(), 5u);
    EXPECT_STREQ(thesisSceneSizes()[3].name, "fantasy");
    EXPECT_EQ(thesisSceneSizes()[4].triangles, 216440u);
    for (const NamedSize& size : thesisSceneSizes()) {
        const Scene s = generateScene({.triangles = size.triangles});
        EXPECT_EQ(s.triangleCount(), size.triangles) << size.name;
    }
}

TEST(SceneGenerator, ExactTriangleCountForAwkwardSizes) {
    for (std::size_t n : {kMinTriangles, std::size_t{601}, std::size_t{777}, std::size_t{1001},
                          std::size_t{2047}, std::size_t{12345}, std::size_t{33333},
                          std::size_t{149999}, std::size_t{150001}, std::size_t{333331}}) {
        EXPECT_EQ(generateScene({.triangles = n}).triangleCount(), n) << n;
    }
}

TEST(SceneGenerator, ExactTriangleCountForEverySmallSize) {
    // The small end is where the budget is tight and the terrain's remainder strips matter:
    // every size there, then a stride with odd steps (and a different seed each time).
    for (std::size_t n = kMinTriangles; n <= 1000; ++n)
        ASSERT_EQ(
            generateScene({.triangles = n, .seed = static_cast<std::uint32_t>(n)}).triangleCount(),
            n);
    for (std::size_t n = 1001; n <= 12000; n += 211)
        ASSERT_EQ(
            generateScene({.triangles = n, .seed = static_cast<std::uint32_t>(n)}).triangleCount(),
            n);
}

TEST(SceneGenerator, BelowMinimumThrows) {
    EXPECT_THROW(generateScene({.triangles = kMinTriangles - 1}), std::invalid_argument);
    EXPECT_THROW(generateScene({.triangles = 0}), std::invalid_argument);
}

// ---- determinism ------------------------------------------------------------------------------

void expectSameBits(const Scene& a, const Scene& b) {
    ASSERT_EQ(a.meshes.size(), b.meshes.size());
    for (std::size_t i = 0; i < a.meshes.size(); ++i) {
        const Mesh& x = a.meshes[i];
        const Mesh& y = b.meshes[i];
        EXPECT_EQ(x.name, y.name);
        ASSERT_EQ(x.positions.size(), y.positions.size());
        ASSERT_EQ(x.normals.size(), y.normals.size());
        EXPECT_EQ(0, std::memcmp(x.positions.data(), y.positions.data(),
                                 x.positions.size() * sizeof(glm::vec3)));
        EXPECT_EQ(0, std::memcmp(x.normals.data(), y.normals.data(),
                                 x.normals.size() * sizeof(glm::vec3)));
        EXPECT_EQ(x.indices, y.indices);
        EXPECT_EQ(x.material, y.material);
    }
    ASSERT_EQ(a.instances.size(), b.instances.size());
    for (std::size_t i = 0; i < a.instances.size(); ++i) {
        EXPECT_EQ(0, std::memcmp(&a.instances[i].world, &b.instances[i].world, sizeof(glm::mat4)));
        EXPECT_EQ(a.instances[i].objectId, b.instances[i].objectId);
    }
    ASSERT_EQ(a.materials.size(), b.materials.size());
    for (std::size_t i = 0; i < a.materials.size(); ++i)
        EXPECT_EQ(a.materials[i].baseColorFactor, b.materials[i].baseColorFactor);
    EXPECT_EQ(0, std::memcmp(&a.cameras.at(0).view, &b.cameras.at(0).view, sizeof(glm::mat4)));
    EXPECT_EQ(a.light->position, b.light->position);
}

TEST(SceneGenerator, SameParamsGiveIdenticalScenesAndFiles) {
    for (std::size_t n : {std::size_t{634}, std::size_t{6320}, std::size_t{216440}}) {
        const Scene a = generateScene({.triangles = n, .seed = 7});
        const Scene b = generateScene({.triangles = n, .seed = 7});
        expectSameBits(a, b);
        const auto dir = test::outputDir("scene_generator");
        writeGlb(a, dir / "a.glb");
        writeGlb(b, dir / "b.glb");
        const auto bytesA = readFile(dir / "a.glb");
        EXPECT_FALSE(bytesA.empty());
        EXPECT_EQ(bytesA, readFile(dir / "b.glb")) << n;
    }
}

TEST(SceneGenerator, SeedChangesTheScene) {
    const Scene a = generateScene({.triangles = 6320, .seed = 1});
    const Scene b = generateScene({.triangles = 6320, .seed = 2});
    EXPECT_EQ(b.triangleCount(), 6320u);
    EXPECT_NE(a.meshes[0].positions, b.meshes[0].positions); // the terrain's hills differ
}

// ---- geometry ---------------------------------------------------------------------------------

TEST(SceneGenerator, GeometryIsValidAndOutwardFacing) {
    for (std::size_t n : {kMinTriangles, std::size_t{6320}, std::size_t{216440}}) {
        const Scene s = generateScene({.triangles = n});
        for (const Mesh& m : s.meshes) {
            SCOPED_TRACE(m.name + " at " + std::to_string(n));
            ASSERT_EQ(m.normals.size(), m.positions.size());
            ASSERT_EQ(m.indices.size() % 3, 0u);
            ASSERT_GT(m.indices.size(), 0u);
            for (const glm::vec3& p : m.positions)
                ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
            for (const glm::vec3& nrm : m.normals) ASSERT_NEAR(glm::length(nrm), 1.0f, 1e-4f);
            std::size_t inwardFaces = 0;
            for (std::size_t i = 0; i < m.indices.size(); i += 3) {
                const std::uint32_t a = m.indices[i], b = m.indices[i + 1], c = m.indices[i + 2];
                ASSERT_LT(std::max({a, b, c}), m.positions.size());
                const glm::vec3 face =
                    glm::cross(m.positions[b] - m.positions[a], m.positions[c] - m.positions[a]);
                ASSERT_GT(glm::length(face), 1e-9f) << "degenerate triangle " << i / 3;
                // Counter-clockwise seen from outside: the winding agrees with the normals.
                if (glm::dot(face, m.normals[a] + m.normals[b] + m.normals[c]) <= 0.0f)
                    ++inwardFaces;
            }
            EXPECT_EQ(inwardFaces, 0u);
        }
    }
}

TEST(SceneGenerator, HasTheFantasyCastWithOwnMaterialsAndIds) {
    const Scene s = generateScene({.triangles = 101861});
    for (const char* name : {"terrain", "tree", "tree.crown", "pergola", "mushroom1", "mushroom2",
                             "mushroom3", "mushroom1.cap", "rock", "flower", "flower.bloom",
                             "character1", "character2", "character3", "character4"})
        EXPECT_NE(findInstance(s, name), nullptr) << name;
    EXPECT_EQ(findInstance(s, "tree2"), nullptr); // duplicates only in fantasy2-sized scenes
    std::map<std::uint32_t, int> ids;
    std::map<int, int> materials;
    for (const Instance& inst : s.instances) {
        ++ids[inst.objectId];
        ++materials[s.meshes[static_cast<std::size_t>(inst.mesh)].material];
    }
    EXPECT_EQ(ids.size(), s.instances.size());
    EXPECT_EQ(materials.size(), s.instances.size());
    EXPECT_EQ(s.materials.size(), s.meshes.size());

    // Every object gets a real share of the budget, not just the terrain.
    for (const Instance& inst : s.instances)
        EXPECT_GT(s.meshes[static_cast<std::size_t>(inst.mesh)].triangleCount(), 300u)
            << inst.nodeName;

    const Scene big = generateScene({.triangles = 216440});
    EXPECT_NE(findInstance(big, "tree2"), nullptr);
    EXPECT_NE(findInstance(big, "mushroom6"), nullptr);
    EXPECT_NE(findInstance(big, "character6"), nullptr);
}

TEST(SceneGenerator, ObjectsStandOnTheTerrain) {
    for (std::size_t n :
         {kMinTriangles, std::size_t{634}, std::size_t{6320}, std::size_t{216440}}) {
        const Scene s = generateScene({.triangles = n});
        const TerrainSampler ground(s);
        ASSERT_TRUE(s.bounds.valid());
        EXPECT_GT(s.bounds.extent().x, 18.0f);
        EXPECT_LT(s.bounds.extent().x, 30.0f);
        for (const Instance& inst : s.instances) {
            if (inst.nodeName == "terrain") continue;
            const bool grounded = inst.nodeName.find('.') == std::string::npos;
            float lowest = 1e9f; // smallest height of a vertex above the ground under it
            for (const glm::vec3& p : s.meshes[static_cast<std::size_t>(inst.mesh)].positions) {
                const glm::vec3 w = worldPos(inst, p);
                const std::optional<float> h = ground.height(w.x, w.z);
                ASSERT_TRUE(h) << inst.nodeName << " leaves the terrain";
                lowest = std::min(lowest, w.y - *h);
            }
            if (grounded) {
                // Touches the ground (no floating) and is not buried: the base reaches a few
                // centimetres below (slopes), a rock up to half a metre.
                EXPECT_LT(lowest, 0.02f) << inst.nodeName << " at " << n;
                EXPECT_GT(lowest, -0.6f) << inst.nodeName << " at " << n;
            } else {
                EXPECT_GT(lowest, 0.1f) << inst.nodeName << " at " << n; // crowns, caps, blooms
            }
        }
    }
}

TEST(SceneGenerator, LightAndCameraFrameTheScene) {
    const Scene s = generateScene({.triangles = 6320});
    ASSERT_TRUE(s.light);
    const Light& l = *s.light;
    EXPECT_TRUE(l.type == Light::Type::Spot || l.type == Light::Type::Point);
    EXPECT_NEAR(l.radius, 0.3f, 1e-6f);
    EXPECT_NEAR(glm::length(l.direction), 1.0f, 1e-5f);
    const float elevation = glm::degrees(std::asin(-l.direction.y));
    EXPECT_NEAR(elevation, 45.0f, 5.0f);
    const glm::vec3 toCentre = glm::normalize(s.bounds.center() - l.position);
    EXPECT_GT(glm::dot(toCentre, l.direction), std::cos(glm::radians(10.0f)));
    EXPECT_GT(l.position.y, s.bounds.max.y + 5.0f);

    ASSERT_EQ(s.cameras.size(), 1u);
    const Camera& cam = s.cameras[0];
    EXPECT_NEAR(cam.yfov, glm::radians(50.0f), 1e-6f);
    const glm::mat4 proj = glm::perspective(cam.yfov, 16.0f / 9.0f, cam.znear, cam.zfar);
    auto visible = [&](const glm::vec3& p) {
        const glm::vec4 clip = proj * cam.view * glm::vec4(p, 1.0f);
        return clip.w > 0.0f && std::abs(clip.x) < clip.w && std::abs(clip.y) < clip.w &&
               std::abs(clip.z) < clip.w;
    };
    EXPECT_TRUE(visible(s.bounds.center()));
    for (const char* name : {"pergola", "tree", "tree.crown", "mushroom1"}) {
        const Instance* inst = findInstance(s, name);
        ASSERT_NE(inst, nullptr);
        EXPECT_TRUE(visible(glm::vec3(inst->world[3]) + glm::vec3(0, 1, 0))) << name;
    }
    const glm::vec3 eye = glm::vec3(glm::inverse(cam.view)[3]);
    const std::optional<float> ground = TerrainSampler(s).height(eye.x, eye.z);
    ASSERT_TRUE(ground);
    EXPECT_NEAR(eye.y - *ground, 1.7f, 0.3f); // a person's eye height
}

TEST(SceneGenerator, LargestThesisSceneIsQuick) {
    const auto t0 = std::chrono::steady_clock::now();
    const Scene s = generateScene({.triangles = 216440});
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    RecordProperty("seconds", std::to_string(seconds));
    std::printf("generateScene(216440): %.3f s\n", seconds);
    EXPECT_EQ(s.triangleCount(), 216440u);
#if defined(NDEBUG) && !defined(__SANITIZE_ADDRESS__)
    EXPECT_LT(seconds, 2.0);
#endif
}

// ---- GLB --------------------------------------------------------------------------------------

/// A tiny hand-made scene with what the generator never produces: texcoords, a texture, a
/// double-sided material, a shared mesh, a point light and a camera aspect ratio.
Scene handMadeScene() {
    Scene s;
    Mesh quad;
    quad.name = "quad";
    quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    quad.normals.assign(4, glm::vec3(0, 0, 1));
    quad.texcoords = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    quad.indices = {0, 1, 2, 0, 2, 3};
    quad.material = 0;
    s.meshes.push_back(quad);
    Image img;
    img.name = "checker";
    img.width = 3;
    img.height = 2;
    for (int i = 0; i < 6; ++i)
        img.rgba.insert(img.rgba.end(), {static_cast<std::uint8_t>(40 * i), 200, 10, 255});
    s.images.push_back(img);
    s.materials.push_back(Material{"paper", {0.5f, 0.25f, 1.0f, 1.0f}, 0, true});
    for (int i = 0; i < 2; ++i) {
        Instance inst;
        inst.mesh = 0;
        inst.world = glm::translate(glm::mat4(1.0f), glm::vec3(2.0f * static_cast<float>(i), 0, 0));
        inst.objectId = static_cast<std::uint32_t>(i + 1);
        inst.nodeName = "quad" + std::to_string(i);
        s.instances.push_back(inst);
    }
    Camera cam;
    cam.name = "cam";
    cam.view = glm::lookAt(glm::vec3(1, 2, 5), glm::vec3(1, 0.5f, 0), glm::vec3(0, 1, 0));
    cam.aspectRatio = 1.5f;
    s.cameras.push_back(cam);
    Light light;
    light.type = Light::Type::Point;
    light.name = "bulb";
    light.position = {0, 3, 1};
    light.radius = 0.05f;
    s.light = light;
    s.computeBounds();
    return s;
}

TEST(GlbWriter, WritesAWellFormedGlb) {
    const Scene s = generateScene({.triangles = 6320});
    const auto file = test::outputDir("scene_generator") / "structure.glb";
    writeGlb(s, file);
    EXPECT_FALSE(std::filesystem::exists(file.string() + ".tmp"));
    const auto bytes = readFile(file);
    ASSERT_GE(bytes.size(), 28u);
    EXPECT_EQ(u32At(bytes, 0), 0x46546C67u);
    EXPECT_EQ(u32At(bytes, 4), 2u);
    EXPECT_EQ(u32At(bytes, 8), bytes.size());
    const std::uint32_t jsonLen = u32At(bytes, 12);
    EXPECT_EQ(jsonLen % 4, 0u);
    EXPECT_EQ(u32At(bytes, 16), 0x4E4F534Au);
    const std::size_t binAt = 20 + jsonLen;
    const std::uint32_t binLen = u32At(bytes, binAt);
    EXPECT_EQ(binLen % 4, 0u);
    EXPECT_EQ(u32At(bytes, binAt + 4), 0x004E4942u);
    EXPECT_EQ(binAt + 8 + binLen, bytes.size());

    const auto doc = nlohmann::json::parse(bytes.begin() + 20, bytes.begin() + 20 + jsonLen);
    EXPECT_EQ(doc["asset"]["version"], "2.0");
    EXPECT_EQ(doc["asset"]["generator"], "Floodlight");
    EXPECT_EQ(doc["buffers"][0]["byteLength"], binLen);
    // One node per instance, the characters' skeletons (Scene::nodes, written first), camera
    // and light.
    EXPECT_EQ(s.nodes.size(), 4u * 8u); // four characters: a root and seven joints each
    EXPECT_EQ(doc["nodes"].size(), s.nodes.size() + s.instances.size() + 2);
    EXPECT_EQ(doc["skins"].size(), 4u);
    EXPECT_EQ(doc["animations"].size(), 2u); // walk, wave
    EXPECT_EQ(doc["meshes"].size(), s.meshes.size());
    EXPECT_EQ(doc["materials"].size(), s.materials.size());
    EXPECT_EQ(doc["extensionsUsed"][0], "KHR_lights_punctual");
    const auto& light = doc["extensions"]["KHR_lights_punctual"]["lights"][0];
    EXPECT_EQ(light["type"], "spot");
    EXPECT_NEAR(light["extras"]["radius"].get<double>(), 0.3, 1e-6);
    for (const auto& view : doc["bufferViews"]) {
        EXPECT_EQ(view["byteOffset"].get<std::size_t>() % 4, 0u);
        EXPECT_LE(view["byteOffset"].get<std::size_t>() + view["byteLength"].get<std::size_t>(),
                  binLen);
    }
    // POSITION min/max are the exact extremes of the data.
    const auto& terrainPos =
        doc["accessors"]
           [doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"].get<std::size_t>()];
    glm::vec3 lo(1e9f), hi(-1e9f);
    for (const glm::vec3& p : s.meshes[0].positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(terrainPos["min"][static_cast<std::size_t>(k)].get<float>(), lo[k]);
        EXPECT_EQ(terrainPos["max"][static_cast<std::size_t>(k)].get<float>(), hi[k]);
    }
}

TEST(GlbWriter, EmbedsImagesAsPng) {
    const auto file = test::outputDir("scene_generator") / "handmade.glb";
    writeGlb(handMadeScene(), file);
    const auto bytes = readFile(file);
    const std::uint32_t jsonLen = u32At(bytes, 12);
    const auto doc = nlohmann::json::parse(bytes.begin() + 20, bytes.begin() + 20 + jsonLen);
    ASSERT_EQ(doc["images"].size(), 1u);
    EXPECT_EQ(doc["images"][0]["mimeType"], "image/png");
    const auto& view = doc["bufferViews"][doc["images"][0]["bufferView"].get<std::size_t>()];
    const std::size_t at = 20 + jsonLen + 8 + view["byteOffset"].get<std::size_t>();
    EXPECT_EQ(0, std::memcmp(&bytes[at], "\x89PNG", 4));
    EXPECT_EQ(doc["materials"][0]["doubleSided"], true);
    EXPECT_EQ(doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["index"], 0);
    EXPECT_EQ(doc["textures"][0]["source"], 0);
    EXPECT_EQ(doc["cameras"][0]["perspective"]["aspectRatio"].get<float>(), 1.5f);
    EXPECT_TRUE(doc["meshes"][0]["primitives"][0]["attributes"].contains("TEXCOORD_0"));
    EXPECT_EQ(doc["nodes"][0]["mesh"], 0);
    EXPECT_EQ(doc["nodes"][1]["mesh"], 0); // two nodes share the mesh
}

TEST(GlbWriter, ReportsIoErrorsWithPathAndReason) {
    const auto file = test::outputDir("scene_generator") / "no_such_dir" / "x.glb";
    try {
        writeGlb(handMadeScene(), file);
        FAIL() << "expected an exception";
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("no_such_dir"), std::string::npos) << what;
        EXPECT_NE(what.find(std::strerror(ENOENT)), std::string::npos) << what;
    }
}

TEST(GlbWriter, RejectsInvalidScenes) {
    Scene s = handMadeScene();
    s.meshes[0].indices.push_back(99);
    s.meshes[0].indices.push_back(0);
    s.meshes[0].indices.push_back(1);
    EXPECT_THROW(writeGlb(s, test::outputDir("scene_generator") / "bad.glb"),
                 std::invalid_argument);
}

// ---- round trip through the loader ------------------------------------------------------------

void expectRoundTrip(const Scene& s, const std::filesystem::path& file) {
    writeGlb(s, file);
    const Scene r = loadGltf(file);
    EXPECT_EQ(r.triangleCount(), s.triangleCount());
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(r.bounds.min[k], s.bounds.min[k], 1e-5f);
        EXPECT_NEAR(r.bounds.max[k], s.bounds.max[k], 1e-5f);
    }
    ASSERT_TRUE(r.light);
    EXPECT_EQ(r.light->type, s.light->type);
    EXPECT_NEAR(r.light->radius, s.light->radius, 1e-6f);
    for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(r.light->position[k], s.light->position[k], 1e-4f);
        if (s.light->type != Light::Type::Point) {
            EXPECT_NEAR(r.light->direction[k], s.light->direction[k], 1e-5f);
        }
    }
    ASSERT_EQ(r.cameras.size(), s.cameras.size());
    for (int c = 0; c < 4; ++c)
        for (int k = 0; k < 4; ++k)
            EXPECT_NEAR(r.cameras[0].view[c][k], s.cameras[0].view[c][k], 1e-4f);
    EXPECT_NEAR(r.cameras[0].yfov, s.cameras[0].yfov, 1e-6f);
    ASSERT_EQ(r.instances.size(), s.instances.size());
    for (std::size_t i = 0; i < s.instances.size(); ++i) {
        EXPECT_EQ(r.instances[i].nodeName, s.instances[i].nodeName);
        const Mesh& rm = r.meshes[static_cast<std::size_t>(r.instances[i].mesh)];
        const Mesh& sm = s.meshes[static_cast<std::size_t>(s.instances[i].mesh)];
        ASSERT_GE(rm.material, 0);
        EXPECT_EQ(r.materials[static_cast<std::size_t>(rm.material)].baseColorFactor,
                  s.materials[static_cast<std::size_t>(sm.material)].baseColorFactor)
            << s.instances[i].nodeName;
    }
}

TEST(GlbWriter, AlphaModesAndVertexColoursRoundTrip) {
    Scene s = handMadeScene();
    s.materials[0].alphaMode = AlphaMode::Mask;
    s.materials[0].alphaCutoff = 0.3f;
    s.materials.push_back(
        Material{"glass", glm::vec4(0.2f, 0.4f, 0.9f, 0.4f), -1, false, AlphaMode::Blend, 0.5f});
    s.meshes.push_back(s.meshes[0]);
    s.meshes[1].material = 1;
    s.meshes[1].colors = {{1, 0, 0, 1}, {0, 1, 0, 0.5f}, {0, 0, 1, 0.25f}, {1, 1, 1, 0}};
    s.instances[1].mesh = 1;
    const auto file = test::outputDir("scene_generator") / "roundtrip_alpha.glb";
    writeGlb(s, file);
    const Scene r = loadGltf(file);
    ASSERT_EQ(r.materials.size(), 2u);
    EXPECT_EQ(r.materials[0].alphaMode, AlphaMode::Mask);
    EXPECT_FLOAT_EQ(r.materials[0].alphaCutoff, 0.3f);
    EXPECT_EQ(r.materials[1].alphaMode, AlphaMode::Blend);
    ASSERT_EQ(r.meshes.size(), 2u);
    EXPECT_EQ(r.meshes[1].colors, s.meshes[1].colors);
    EXPECT_TRUE(r.meshes[0].colors.empty());
}

TEST(GlbWriter, GeneratedSceneRoundTripsThroughTheLoader) {
    expectRoundTrip(generateScene({.triangles = 6320}),
                    test::outputDir("scene_generator") / "roundtrip.glb");
}

TEST(GlbWriter, HandMadeSceneRoundTripsThroughTheLoader) {
    const Scene s = handMadeScene();
    const auto file = test::outputDir("scene_generator") / "roundtrip_handmade.glb";
    expectRoundTrip(s, file);
    const Scene r = loadGltf(file);
    ASSERT_EQ(r.images.size(), 1u);
    EXPECT_EQ(r.images[0].rgba, s.images[0].rgba);
    EXPECT_TRUE(r.materials.at(0).doubleSided);
    EXPECT_EQ(r.meshes.at(0).texcoords, s.meshes[0].texcoords);
    ASSERT_TRUE(r.cameras[0].aspectRatio);
    EXPECT_FLOAT_EQ(*r.cameras[0].aspectRatio, 1.5f);
}

} // namespace
} // namespace fl
