// The default scene: layout after the thesis' fantasy scene, a triangle budget shared among the
// objects, the exact count settled by the terrain, the characters' skeletons and walk / wave
// cycles (SceneGenRig.h; they add no triangles), and the light and camera.

#include <scene/SceneGenerator.h>

#include "SceneGenObjects.h"
#include "SceneGenRig.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <stdexcept>

namespace fl {

namespace {

using gen::Kind;
using gen::ObjectDesign;
using gen::Rng;
using gen::Terrain;

/// Terrain's share of the budget; object weights are in ObjectDesign::weight. With the base
/// set the weights add up to 100, so they read as percentages.
constexpr int kTerrainWeight = 18;
/// Scenes larger than this many triangles are refused: memory, not correctness, is the limit.
constexpr std::size_t kMaxTriangles = 50'000'000;

constexpr glm::vec2 kCameraGround{2.8f, 10.5f};

ObjectDesign design(Kind kind, glm::vec2 at, float yaw, float scale, int weight, Rng& rng) {
    ObjectDesign d;
    d.kind = kind;
    d.at = at;
    d.yaw = yaw;
    d.scale = scale;
    d.weight = weight;
    const std::uint64_t hi = rng.next();
    d.seed = (hi << 32u) | rng.next();
    return d;
}

/// The thesis' cast at fixed, composed places around the pergola and the tree.
std::vector<ObjectDesign> baseSet(Rng& rng) {
    std::vector<ObjectDesign> set;
    set.push_back(design(Kind::Tree, {-3.5f, -2.5f}, rng.uniform(0.0f, 6.28f), 1.0f, 30, rng));
    set.push_back(design(Kind::Pergola, {2.6f, -1.6f}, 0.3f, 1.0f, 7, rng));
    set.push_back(design(Kind::Mushroom, {-0.7f, 2.4f}, 0.0f, 1.0f, 4, rng));
    set.push_back(design(Kind::Mushroom, {0.1f, 3.1f}, 0.0f, 0.75f, 4, rng));
    set.push_back(design(Kind::Mushroom, {-1.4f, 3.2f}, 0.0f, 0.55f, 4, rng));
    set.push_back(design(Kind::Rock, {1.7f, 2.5f}, rng.uniform(0.0f, 6.28f), 1.0f, 5, rng));
    set.push_back(design(Kind::Flower, {-2.6f, 1.0f}, 0.0f, 1.4f, 4, rng));
    set.push_back(design(Kind::Character, {-5.8f, 2.2f}, 0.5f, 1.0f, 6, rng));
    set.push_back(design(Kind::Character, {5.9f, 1.6f}, -0.5f, 0.95f, 6, rng));
    set.push_back(design(Kind::Character, {2.3f, -1.4f}, 0.1f, 1.05f, 6, rng));
    set.push_back(design(Kind::Character, {-1.2f, -5.8f}, 0.3f, 0.9f, 6, rng));
    return set;
}

/// A free spot for an object of `radius`: away from the others and from the camera, drawn
/// from the behind-the-scene part of the terrain. Falls back to the last try when crowded.
glm::vec2 freeSpot(const std::vector<ObjectDesign>& placed, float radius, Rng& rng) {
    glm::vec2 p(0.0f);
    for (int attempt = 0; attempt < 400; ++attempt) {
        p = glm::vec2(rng.uniform(-10.0f, 10.0f), rng.uniform(-10.0f, 3.0f));
        const glm::vec2 toCamera = p - kCameraGround;
        bool free = glm::dot(toCamera, toCamera) > 16.0f;
        for (const ObjectDesign& o : placed) {
            const float minDist = radius + gen::layoutRadius(o.kind, o.scale) + 0.3f;
            const glm::vec2 dd = p - o.at;
            free = free && glm::dot(dd, dd) > minDist * minDist;
        }
        if (free) return p;
    }
    return p;
}

/// Fantasy2-style growth: past 150k triangles, whole extra groups of objects (a tree, a rock,
/// three mushrooms, two characters) rather than only finer tessellation.
void addDuplicates(std::vector<ObjectDesign>& objects, std::size_t triangles, Rng& rng) {
    const std::size_t sets =
        triangles < 150'000 ? 0 : std::min<std::size_t>(8, (triangles - 50'000) / 100'000);
    struct Item {
        Kind kind;
        float scaleLo, scaleHi;
        int weight;
    };
    static constexpr Item kSet[] = {
        {Kind::Tree, 0.8f, 1.1f, 30},     {Kind::Rock, 0.6f, 1.2f, 5},
        {Kind::Mushroom, 0.5f, 1.0f, 4},  {Kind::Mushroom, 0.5f, 1.0f, 4},
        {Kind::Mushroom, 0.5f, 1.0f, 4},  {Kind::Character, 0.9f, 1.05f, 6},
        {Kind::Character, 0.9f, 1.05f, 6}};
    for (std::size_t s = 0; s < sets; ++s) {
        for (const Item& item : kSet) {
            const float scale = rng.uniform(item.scaleLo, item.scaleHi);
            const glm::vec2 at = freeSpot(objects, gen::layoutRadius(item.kind, scale), rng);
            const float yaw = rng.uniform(0.0f, 6.28f);
            objects.push_back(design(item.kind, at, yaw, scale, item.weight, rng));
        }
    }
}

/// "tree", "tree2", …; mushrooms and characters are always numbered ("mushroom1", …).
void nameObjects(std::vector<ObjectDesign>& objects) {
    static constexpr const char* kNames[] = {"tree", "pergola", "mushroom",
                                             "rock", "flower",  "character"};
    int seen[6] = {};
    for (ObjectDesign& o : objects) {
        const auto k = static_cast<std::size_t>(o.kind);
        o.variant = seen[k]++;
        const bool numbered = o.kind == Kind::Mushroom || o.kind == Kind::Character;
        o.name = kNames[k];
        if (numbered || o.variant > 0) o.name += std::to_string(o.variant + 1);
    }
}

/// Highest detail level whose triangle count fits `share` (0 when none does).
int detailWithin(const ObjectDesign& o, const Terrain& terrain, std::size_t share) {
    if (gen::objectTriangles(o, terrain, 0) > share) return 0;
    int lo = 0; // fits
    int hi = 1; // first level not yet known to fit
    while (hi < (1 << 16) && gen::objectTriangles(o, terrain, hi) <= share) {
        lo = hi;
        hi *= 2;
    }
    while (hi - lo > 1) {
        const int mid = lo + (hi - lo) / 2;
        (gen::objectTriangles(o, terrain, mid) <= share ? lo : hi) = mid;
    }
    return lo;
}

/// Detail levels for all objects: each gets the finest level within its weighted share; if
/// that leaves the terrain less than its minimum (tiny budgets), the biggest objects step down.
std::vector<int> allocateDetail(const std::vector<ObjectDesign>& objects, const Terrain& terrain,
                                std::size_t triangles, std::size_t& terrainTriangles) {
    std::size_t totalWeight = kTerrainWeight;
    for (const ObjectDesign& o : objects) totalWeight += static_cast<std::size_t>(o.weight);

    std::vector<int> detail(objects.size());
    std::vector<std::size_t> count(objects.size());
    std::size_t used = 0;
    for (std::size_t i = 0; i < objects.size(); ++i) {
        const std::size_t share =
            triangles * static_cast<std::size_t>(objects[i].weight) / totalWeight;
        detail[i] = detailWithin(objects[i], terrain, share);
        count[i] = gen::objectTriangles(objects[i], terrain, detail[i]);
        used += count[i];
    }
    while (used + Terrain::kMinTriangles > triangles) {
        std::size_t biggest = objects.size();
        for (std::size_t i = 0; i < objects.size(); ++i)
            if (detail[i] > 0 && (biggest == objects.size() || count[i] > count[biggest]))
                biggest = i;
        if (biggest == objects.size())
            throw std::logic_error("generateScene: objects do not fit " +
                                   std::to_string(triangles));
        used -= count[biggest];
        count[biggest] = gen::objectTriangles(objects[biggest], terrain, --detail[biggest]);
        used += count[biggest];
    }
    terrainTriangles = triangles - used;
    return detail;
}

/// Adds a mesh with its own material and node.
void addObject(Scene& scene, const std::string& name, gen::MeshBuilder& builder,
               const glm::vec4& color, const glm::mat4& world) {
    Mesh mesh;
    mesh.name = name;
    builder.moveInto(mesh);
    mesh.material = static_cast<int>(scene.materials.size());
    scene.materials.push_back(Material{name, color, -1, false});
    Instance inst;
    inst.mesh = static_cast<int>(scene.meshes.size());
    inst.world = world;
    inst.objectId = static_cast<std::uint32_t>(scene.instances.size() + 1); // 0: no object
    inst.nodeName = name;
    scene.meshes.push_back(std::move(mesh));
    scene.instances.push_back(std::move(inst));
}

/// Human eye height near the front edge, looking at the pergola and tree.
Camera makeCamera(const Terrain& terrain) {
    const glm::vec3 eye(kCameraGround.x,
                        terrain.surfaceHeight(kCameraGround.x, kCameraGround.y) + 1.7f,
                        kCameraGround.y);
    const glm::vec3 target(-0.4f, terrain.surfaceHeight(-0.4f, -1.8f) + 1.2f, -1.8f);
    Camera cam;
    cam.name = "camera";
    cam.view = glm::lookAt(eye, target, glm::vec3(0.0f, 1.0f, 0.0f));
    cam.yfov = glm::radians(50.0f);
    cam.znear = 0.1f;
    cam.zfar = 100.0f;
    return cam;
}

/// A sun-like key light: 45 degrees up, from the left and slightly behind the scene, so the
/// shadows fall sideways and towards the camera.
Light makeLight() {
    constexpr float kCos45 = 0.70710678f;
    const glm::vec3 toLight(-0.9f * kCos45, kCos45, -0.436f * kCos45);
    const glm::vec3 target(0.0f, 0.5f, -0.5f);
    Light light;
    light.type = Light::Type::Spot;
    light.name = "sun";
    light.direction = -toLight / std::sqrt(glm::dot(toLight, toLight));
    light.position = target - 24.0f * light.direction;
    light.color = glm::vec3(1.0f, 0.95f, 0.85f);
    light.intensity = 1.0f;
    light.radius = 0.3f;
    light.outerConeAngle = 0.75f; // covers the whole terrain from 24 m
    return light;
}

} // namespace

const std::vector<NamedSize>& thesisSceneSizes() {
    static const std::vector<NamedSize> sizes = {{"knight", 634},
                                                 {"teapot", 6320},
                                                 {"bunny", 69451},
                                                 {"fantasy", 101861},
                                                 {"fantasy2", 216440}};
    return sizes;
}

Scene generateScene(const SceneGenParams& params) {
    if (params.triangles < kMinTriangles || params.triangles > kMaxTriangles)
        throw std::invalid_argument(
            "generateScene: triangle count " + std::to_string(params.triangles) + " outside [" +
            std::to_string(kMinTriangles) + ", " + std::to_string(kMaxTriangles) + "]");
    Rng master(params.seed);
    Rng terrainRng = master.fork();
    Rng layoutRng = master.fork();
    Rng colorRng = master.fork();

    Terrain terrain(terrainRng);
    std::vector<ObjectDesign> objects = baseSet(layoutRng);
    addDuplicates(objects, params.triangles, layoutRng);
    nameObjects(objects);

    // Counts do not depend on placement, so the budget comes first; objects are then placed
    // on the terrain as tessellated.
    std::size_t terrainTriangles = 0;
    const std::vector<int> detail =
        allocateDetail(objects, terrain, params.triangles, terrainTriangles);
    terrain.tessellate(terrainTriangles);
    for (ObjectDesign& o : objects) gen::placeOnTerrain(o, terrain);

    Scene scene;
    scene.source = "generated";
    gen::MeshBuilder ground;
    terrain.build(ground);
    addObject(scene, "terrain", ground, glm::vec4(0.22f, 0.36f, 0.12f, 1.0f), glm::mat4(1.0f));
    gen::CharacterAnimations animations;
    for (std::size_t i = 0; i < objects.size(); ++i) {
        const ObjectDesign& o = objects[i];
        std::array<gen::MeshBuilder, 2> parts;
        std::vector<gen::RigPart> rig;
        gen::buildObject(o, terrain, detail[i], parts, &rig);
        const glm::mat4 world = gen::placeYaw(o.origin, o.yaw);
        for (int p = 0; p < gen::partCount(o.kind); ++p) {
            const glm::vec4 color = gen::partColor(o.kind, p, o.variant, colorRng);
            addObject(scene, o.name + gen::partSuffix(o.kind, p),
                      parts[static_cast<std::size_t>(p)], color, world);
        }
        // A character is one part: the instance just added.
        if (o.kind == Kind::Character)
            gen::rigCharacter(scene, o, scene.instances.size() - 1, rig, animations);
    }
    gen::addCharacterAnimations(scene, animations);
    scene.cameras.push_back(makeCamera(terrain));
    scene.light = makeLight();
    scene.computeBounds();

    if (scene.triangleCount() != params.triangles)
        throw std::logic_error("generateScene: built " + std::to_string(scene.triangleCount()) +
                               " triangles instead of " + std::to_string(params.triangles));
    return scene;
}

} // namespace fl
