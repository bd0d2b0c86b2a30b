#include <renderer/soft/ShadowRayInputs.h>

#include <renderer/scene/AlphaCoverage.h>

#include <base/Text.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

namespace fl {

namespace {

/// Which instance and mesh triangle each of worldTriangles' triangles is, for the cut-out test.
struct CutOutTest {
    AlphaCoverage coverage;
    std::vector<std::uint32_t> firstTriangle; // per instance, its first triangle in the list
    std::vector<int> mesh;                    // per instance

    bool transmits(std::uint32_t triangle, float u, float v) const {
        const auto it = std::upper_bound(firstTriangle.begin(), firstTriangle.end(), triangle);
        const auto i = static_cast<std::size_t>(it - firstTriangle.begin()) - 1;
        return !coverage.blocks(mesh[i], triangle - firstTriangle[i], u, v);
    }
};

} // namespace

rt::Triangles worldTriangles(const Scene& scene) {
    rt::Triangles t;
    auto test = std::make_shared<CutOutTest>(CutOutTest{AlphaCoverage(scene), {}, {}});
    for (const Instance& inst : scene.instances) {
        const Mesh& m = scene.meshes.at(static_cast<std::size_t>(inst.mesh));
        const auto base = static_cast<std::uint32_t>(t.vertices.size());
        test->firstTriangle.push_back(static_cast<std::uint32_t>(t.indices.size() / 3));
        test->mesh.push_back(inst.mesh);
        if (test->coverage.any())
            t.cutOut.resize(t.indices.size() / 3 + m.triangleCount(),
                            test->coverage.cutsOut(inst.mesh) ? 1 : 0);
        for (std::size_t v = 0; v < m.positions.size(); ++v) {
            const glm::vec3 p(inst.world * glm::vec4(m.positions[v], 1.0f));
            for (int a = 0; a < 3; ++a)
                if (!(std::abs(p[a]) <= rt::kMaxCoordinate))
                    throw std::invalid_argument(cat("raytrace: node '", inst.nodeName, "' (mesh '",
                                                    m.name, "'): vertex ", v, " lands at ", p[a],
                                                    " in the world, beyond Embree's range (+-",
                                                    rt::kMaxCoordinate, ")"));
            t.vertices.push_back(p);
        }
        for (std::uint32_t i : m.indices) t.indices.push_back(base + i);
    }
    if (test->coverage.any())
        t.transmits = [test](std::uint32_t triangle, float u, float v) {
            return test->transmits(triangle, u, v);
        };
    return t;
}

std::vector<glm::vec3> worldVertices(const Scene& scene, const Pose& pose) {
    std::vector<glm::vec3> out, posed;
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        posedVertices(scene, pose, i, posed);
        out.insert(out.end(), posed.begin(), posed.end());
    }
    return out;
}

std::vector<rt::Receiver> surfaceReceivers(const SurfacesPass::Outputs& surfaces) {
    const std::size_t pixels =
        static_cast<std::size_t>(surfaces.width) * static_cast<std::size_t>(surfaces.height);
    const auto read = [&](const gl::Texture& t) {
        std::vector<float> v(4 * pixels);
        glGetTextureImage(t.id(), 0, GL_RGBA, GL_FLOAT,
                          static_cast<GLsizei>(v.size() * sizeof(float)), v.data());
        return v;
    };
    const std::vector<float> position = read(surfaces.position), plane = read(surfaces.plane),
                             normal = read(surfaces.normal);
    gl::throwIfErrors("surfaces read-back for the ray tracer");
    std::vector<rt::Receiver> receivers(pixels);
    for (std::size_t i = 0; i < pixels; ++i) {
        const auto at = [i](const std::vector<float>& v) {
            return glm::vec3(v[4 * i], v[4 * i + 1], v[4 * i + 2]);
        };
        glm::vec3 n = at(plane);
        if (glm::dot(n, at(normal)) < 0.0f) n = -n;
        receivers[i] = {at(position), n, position[4 * i + 3] != 0.0f}; // w = 0: background
    }
    return receivers;
}

} // namespace fl
