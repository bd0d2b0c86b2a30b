#include <scene/AlphaCoverage.h>

#include <cmath>

namespace fl {

AlphaCoverage::AlphaCoverage(const Scene& scene) : scene_(&scene) {
    cutoff_.reserve(scene.meshes.size());
    for (const Mesh& m : scene.meshes) {
        std::optional<float> cutoff;
        if (m.material >= 0 && static_cast<std::size_t>(m.material) < scene.materials.size())
            cutoff = shadowCutoff(scene.materials[static_cast<std::size_t>(m.material)]);
        any_ = any_ || cutoff.has_value();
        cutoff_.push_back(cutoff);
    }
}

bool AlphaCoverage::cutsOut(int mesh) const {
    return mesh >= 0 && static_cast<std::size_t>(mesh) < cutoff_.size() &&
           cutoff_[static_cast<std::size_t>(mesh)].has_value();
}

bool AlphaCoverage::blocks(int mesh, std::size_t triangle, float u, float v) const {
    if (!cutsOut(mesh)) return true;
    const Mesh& m = scene_->meshes[static_cast<std::size_t>(mesh)];
    const Material& mat = scene_->materials[static_cast<std::size_t>(m.material)];
    const std::uint32_t* tri = &m.indices.at(3 * triangle);
    const float w = 1.0f - u - v;
    float alpha = mat.baseColorFactor.a;
    // The same interpolation GL does for the vertex stage's outputs (per-vertex values, then
    // barycentric weights), so that texture look-ups land on the same texel.
    if (!m.colors.empty())
        alpha *= w * m.colors[tri[0]].a + u * m.colors[tri[1]].a + v * m.colors[tri[2]].a;
    if (mat.baseColorTexture >= 0 &&
        static_cast<std::size_t>(mat.baseColorTexture) < scene_->images.size()) {
        const glm::vec2 uv =
            m.texcoords.empty()
                ? glm::vec2(0.0f)
                : w * m.texcoords[tri[0]] + u * m.texcoords[tri[1]] + v * m.texcoords[tri[2]];
        alpha *= sampleAlpha(scene_->images[static_cast<std::size_t>(mat.baseColorTexture)], uv);
    }
    return alpha >= *cutoff_[static_cast<std::size_t>(mesh)];
}

float sampleAlpha(const Image& image, glm::vec2 uv) {
    if (image.width <= 0 || image.height <= 0 || !std::isfinite(uv.x) || !std::isfinite(uv.y))
        return 1.0f;
    // GL: texel coordinates u * width - 0.5, the two nearest texels each way, wrapped (REPEAT).
    const double x = static_cast<double>(uv.x) * image.width - 0.5;
    const double y = static_cast<double>(uv.y) * image.height - 0.5;
    const double x0 = std::floor(x), y0 = std::floor(y);
    const auto fx = static_cast<float>(x - x0), fy = static_cast<float>(y - y0);
    auto wrap = [](double i, int n) {
        const double r = std::fmod(i, static_cast<double>(n));
        return static_cast<std::size_t>(r < 0 ? r + n : r);
    };
    auto at = [&](double i, double j) {
        const std::size_t xi = wrap(i, image.width), yi = wrap(j, image.height);
        return static_cast<float>(
                   image.rgba[4 * (yi * static_cast<std::size_t>(image.width) + xi) + 3]) /
               255.0f;
    };
    const float top = (1.0f - fx) * at(x0, y0) + fx * at(x0 + 1, y0);
    const float bottom = (1.0f - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1);
    return (1.0f - fy) * top + fy * bottom;
}

} // namespace fl
