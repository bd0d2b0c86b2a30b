#include <scene/Scene.h>

namespace fl {

std::optional<float> shadowCutoff(const Material& m) {
    switch (m.alphaMode) {
    case AlphaMode::Mask:
        return m.alphaCutoff;
    case AlphaMode::Blend:
        return 0.5f;
    case AlphaMode::Opaque:
        break;
    }
    return std::nullopt;
}

std::size_t Scene::triangleCount() const {
    std::size_t n = 0;
    for (const Instance& inst : instances) n += meshes.at(inst.mesh).triangleCount();
    return n;
}

void Scene::computeBounds() {
    bounds = {};
    for (const Instance& inst : instances) {
        geom::Aabb local;
        for (const glm::vec3& p : meshes.at(inst.mesh).positions) local.extend(p);
        bounds.extend(local.transformed(inst.world));
    }
}

} // namespace fl
