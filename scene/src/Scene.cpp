#include <scene/Scene.h>

#include <scene/Pose.h>

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
    bounds = restBounds(*this);
    modelBounds = addedGround >= 0 ? restBounds(*this, addedGround) : bounds;
}

} // namespace fl
