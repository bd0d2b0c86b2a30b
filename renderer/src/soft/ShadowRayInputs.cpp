#include <renderer/io/TextureImage.h>
#include <renderer/soft/ShadowRayInputs.h>

#include <renderer/passes/SurfaceDecode.h>
#include <scene/AlphaCoverage.h>

#include <base/Text.h>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

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
        // The normals as the vertex stage turns them (the rest pose's inverse transpose); a mesh
        // built without them gets zero, which the offset reads as none.
        const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(inst.world)));
        for (std::size_t v = 0; v < m.positions.size(); ++v)
            t.normals.push_back(v < m.normals.size() ? glm::normalize(normalMatrix * m.normals[v])
                                                     : glm::vec3(0.0f));
        for (std::uint32_t i : m.indices) t.indices.push_back(base + i);
    }
    if (test->coverage.any())
        t.transmits = [test](std::uint32_t triangle, float u, float v) {
            return test->transmits(triangle, u, v);
        };
    return t;
}

std::vector<glm::vec3> worldVertices(const Scene& scene, const Pose& pose,
                                     std::vector<glm::vec3>* normals) {
    std::vector<glm::vec3> out, posed, posedNormals;
    if (normals) normals->clear();
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        posedVertices(scene, pose, i, posed, normals ? &posedNormals : nullptr);
        out.insert(out.end(), posed.begin(), posed.end());
        if (normals) normals->insert(normals->end(), posedNormals.begin(), posedNormals.end());
    }
    return out;
}

std::vector<rt::Receiver> surfaceReceivers(const SurfacesPass::Outputs& surfaces) {
    const int w = surfaces.width, h = surfaces.height;
    // Read once each, in file order (row 0 at the top); the receivers are in GL's (row 0 at the
    // bottom), as the visibility they give is uploaded.
    const FloatImage position = surfaces.positions().read();
    const FloatImage normals = readTexture(surfaces.normals, 4); // octahedral: xy shading, zw plane
    std::vector<rt::Receiver> receivers(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const int row = h - 1 - y;
            const auto oct = [&](int c) {
                return surface::octDecode({normals.at(x, row, c), normals.at(x, row, c + 1)});
            };
            glm::vec3 n = oct(2); // the receiver's plane, facing the shading normal's side
            if (glm::dot(n, oct(0)) < 0.0f) n = -n;
            const glm::vec3 p(position.at(x, row, 0), position.at(x, row, 1),
                              position.at(x, row, 2));
            receivers[static_cast<std::size_t>(y) * w + x] = {
                p, n, position.at(x, row, 3) != 0.0f}; // w = 0: background
        }
    return receivers;
}

SurfaceGeometry surfaceGeometry(const SurfacesPass::Outputs& surfaces, const CameraView& camera) {
    const int w = surfaces.width, h = surfaces.height;
    const std::vector<rt::Receiver> receivers = surfaceReceivers(surfaces); // GL's row order
    SurfaceGeometry g;
    g.positions = {w, h, 4, std::vector<float>(receivers.size() * 4, 0.0f)};
    g.planes = g.positions;
    g.receivers = readTexture(surfaces.receivers, 1);
    g.eye = camera.eye;
    g.pixelAngle = 2.0f / (camera.proj[1][1] * static_cast<float>(h)); // 2 tan(fovy/2) / h
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const rt::Receiver& r = receivers[static_cast<std::size_t>(h - 1 - y) * w + x];
            const std::size_t i = (static_cast<std::size_t>(y) * w + x) * 4;
            for (int c = 0; c < 3; ++c) {
                g.positions.data[i + c] = r.position[c];
                g.planes.data[i + c] = r.normal[c];
            }
            g.positions.data[i + 3] = r.valid ? 1.0f : 0.0f;
        }
    return g;
}

} // namespace fl
