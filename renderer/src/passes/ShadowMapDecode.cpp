#include <renderer/passes/ShadowMapDecode.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace fl::shadowmap {

float seedTag(int x, int y, int width) {
    return std::bit_cast<float>(0x3f800000u + static_cast<std::uint32_t>(y * width + x));
}

std::uint32_t seedIndex(float tag) {
    return std::bit_cast<std::uint32_t>(tag) - 0x3f800000u;
}

glm::mat3 unwarp(const glm::mat4& warp) {
    // Rows and columns x, y, w of the warp (glm is column-major: warp[column][row]).
    constexpr int kAxes[3] = {0, 1, 3};
    glm::dmat3 h(0.0);
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) h[c][r] = warp[kAxes[c]][kAxes[r]];
    for (int r : kAxes)
        if (warp[2][r] != 0.0f)
            throw std::invalid_argument("shadow map warp mixes the light's depth into x, y or w");
    if (std::abs(glm::determinant(h)) < 1e-300)
        throw std::invalid_argument("shadow map warp is singular");
    return glm::mat3(glm::inverse(h));
}

glm::mat4 inverseLightViewProj(const glm::mat4& lightViewProj) {
    return glm::mat4(glm::inverse(glm::dmat4(lightViewProj)));
}

glm::vec3 clipRay(glm::vec2 tc, int size, const glm::mat3& unwarp) {
    const glm::vec2 uv = tc / glm::vec2(float(size)) * 2.0f - 1.0f;
    return unwarp * glm::vec3(uv, 1.0f);
}

glm::vec3 unproject(glm::vec2 tc, float depth, int size, const glm::mat3& unwarp,
                    const glm::mat4& inverseLightViewProj) {
    const glm::vec3 l = clipRay(tc, size, unwarp);
    const glm::vec4 w = inverseLightViewProj * glm::vec4(l.x, l.y, depth * l.z, l.z);
    return glm::vec3(w) / w.w;
}

glm::vec4 receiverPosition(float depth, glm::ivec2 texel, int size, const glm::mat3& unwarp,
                           const glm::mat4& inverseLightViewProj) {
    if (depth == kNoReceiver) return glm::vec4(0.0f);
    return glm::vec4(unproject(glm::vec2(texel) + 0.5f, depth, size, unwarp, inverseLightViewProj),
                     1.0f);
}

std::optional<glm::vec3> mapCoord(const glm::mat4& lightViewProj, const glm::mat4& warp,
                                  glm::vec3 world) {
    const glm::vec4 light = lightViewProj * glm::vec4(world, 1.0f);
    const glm::vec4 map = warp * light;
    if (light.w <= 0.0f || map.w <= 0.0f) return std::nullopt;
    return glm::vec3(glm::vec2(map) / map.w, light.z / light.w) * 0.5f + 0.5f;
}

} // namespace fl::shadowmap
