#include "TestScenes.h"

#include <scene/AlphaCoverage.h>

#include <cmath>

namespace fl::test {

namespace {

void addQuad(Mesh& m, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, glm::vec3 n) {
    const auto base = static_cast<std::uint32_t>(m.positions.size());
    for (const glm::vec3& p : {a, b, c, d}) {
        m.positions.push_back(p);
        m.normals.push_back(n);
        m.texcoords.emplace_back(0.0f);
    }
    for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(base + i);
}

} // namespace

Mesh box(glm::vec3 lo, glm::vec3 hi) {
    Mesh m;
    m.name = "box";
    const glm::vec3 p[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z},
                            {lo.x, hi.y, lo.z}, {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z},
                            {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
    addQuad(m, p[4], p[5], p[6], p[7], {0, 0, 1});
    addQuad(m, p[1], p[0], p[3], p[2], {0, 0, -1});
    addQuad(m, p[5], p[1], p[2], p[6], {1, 0, 0});
    addQuad(m, p[0], p[4], p[7], p[3], {-1, 0, 0});
    addQuad(m, p[7], p[6], p[2], p[3], {0, 1, 0});
    addQuad(m, p[0], p[1], p[5], p[4], {0, -1, 0});
    return m;
}

Scene groundAndBox(float half, glm::vec3 lo, glm::vec3 hi, glm::vec3 lightDir) {
    Scene s;
    s.source = "test:groundAndBox";
    Mesh ground;
    ground.name = "ground";
    addQuad(ground, {-half, 0, half}, {half, 0, half}, {half, 0, -half}, {-half, 0, -half},
            {0, 1, 0});
    ground.material = 0;
    s.meshes = {ground, box(lo, hi)};
    s.meshes[1].material = 1;
    s.materials = {{"ground", glm::vec4(0.8f, 0.8f, 0.8f, 1.0f), -1, false},
                   {"box", glm::vec4(0.8f, 0.3f, 0.2f, 1.0f), -1, false}};
    s.instances = {{0, glm::mat4(1.0f), 1, "ground"}, {1, glm::mat4(1.0f), 2, "box"}};
    Light l;
    l.type = Light::Type::Directional;
    l.direction = glm::normalize(lightDir);
    l.radius = 0.1f;
    s.light = l;
    s.computeBounds();
    return s;
}

float rayCastVisibility(const Scene& scene, const Light& light, glm::vec3 p, float epsilon) {
    glm::vec3 dir;
    float tMax;
    if (light.type == Light::Type::Directional) {
        dir = -light.direction;
        tMax = 1e30f;
    } else {
        dir = light.position - p;
        tMax = glm::length(dir);
        dir /= tMax;
    }
    const AlphaCoverage coverage(scene); // cut-outs let the ray through, as in the GL passes
    for (const Instance& inst : scene.instances) {
        const Mesh& m = scene.meshes[static_cast<size_t>(inst.mesh)];
        for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
            // Möller–Trumbore ray/triangle intersection in world space.
            const glm::vec3 a = glm::vec3(inst.world * glm::vec4(m.positions[m.indices[t]], 1));
            const glm::vec3 b = glm::vec3(inst.world * glm::vec4(m.positions[m.indices[t + 1]], 1));
            const glm::vec3 c = glm::vec3(inst.world * glm::vec4(m.positions[m.indices[t + 2]], 1));
            const glm::vec3 e1 = b - a, e2 = c - a;
            const glm::vec3 pv = glm::cross(dir, e2);
            const float det = glm::dot(e1, pv);
            if (std::abs(det) < 1e-12f) continue;
            const glm::vec3 tv = p - a;
            const float u = glm::dot(tv, pv) / det;
            if (u < 0.0f || u > 1.0f) continue;
            const glm::vec3 qv = glm::cross(tv, e1);
            const float v = glm::dot(dir, qv) / det;
            if (v < 0.0f || u + v > 1.0f) continue;
            const float hit = glm::dot(e2, qv) / det;
            if (hit > epsilon && hit < tMax && coverage.blocks(inst.mesh, t / 3, u, v)) return 0.0f;
        }
    }
    return 1.0f;
}

Scene checkerCardOverGround(AlphaMode mode, int cells, int texelsPerCell) {
    Scene s = groundAndBox(3.0f, {-0.5f, 0.0f, -0.5f}, {0.5f, 1.0f, 0.5f}, {1.2f, -1, 0.3f});
    // A point light: every method and the ray caster agree on where its hard shadow falls (a
    // directional light's disk stands at a finite distance for the soft methods).
    s.light->type = Light::Type::Point;
    s.light->position = glm::vec3(0, 1, 0) - 3.0f * glm::vec3(1.2f, -1, 0.3f);
    // The box becomes a horizontal 2 x 2 card at height 1, textured with the checker.
    Mesh card;
    card.name = "checker card";
    addQuad(card, {-1, 1, 1}, {1, 1, 1}, {1, 1, -1}, {-1, 1, -1}, {0, 1, 0});
    card.texcoords = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    card.material = 1;
    s.meshes[1] = card;
    Image checker;
    checker.name = "checker";
    checker.width = checker.height = cells * texelsPerCell;
    for (int y = 0; y < checker.height; ++y)
        for (int x = 0; x < checker.width; ++x) {
            const bool solid = (x / texelsPerCell + y / texelsPerCell) % 2 == 0;
            for (std::uint8_t c : {std::uint8_t{200}, std::uint8_t{120}, std::uint8_t{40},
                                   static_cast<std::uint8_t>(solid ? 255 : 0)})
                checker.rgba.push_back(c);
        }
    s.images = {checker};
    s.materials[1] = {"checker", glm::vec4(1.0f), 0, true, mode, 0.5f};
    s.computeBounds();
    return s;
}

CameraView lookAtCamera(const Scene& scene, glm::vec3 eye, glm::vec3 target, float fovDegrees) {
    CameraSpec spec;
    spec.kind = CameraSpec::Kind::LookAt;
    spec.eye = eye;
    spec.target = target;
    spec.yfovDegrees = fovDegrees;
    return makeCameraView(scene, spec, 1.0f);
}

SceneView spotLitBox() {
    Scene scene = groundAndBox(3.0f, {-0.5f, 0.0f, -0.5f}, {0.5f, 1.0f, 0.5f}, {0.3f, -1, 0.2f});
    scene.light->type = Light::Type::Spot;
    scene.light->position = {-1.5f, 6.0f, -1.0f};
    scene.light->direction = glm::normalize(glm::vec3(1.5f, -6.0f, 1.0f));
    scene.light->radius = 2.0f;
    CameraSpec spec;
    spec.kind = CameraSpec::Kind::LookAt;
    spec.eye = {2.5f, 4.0f, 4.0f};
    spec.target = {0.3f, 0.0f, 0.3f};
    return {scene, makeCameraView(scene, spec, 1.0f)};
}

} // namespace fl::test
