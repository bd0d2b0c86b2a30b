#include <io/ImageIO.h>
#include <renderer/passes/SurfaceDecode.h>

#include <cmath>

namespace fl::surface {

namespace {
// Clip z' = (w - z) / 2 takes GL's [-1, 1] depth to [0, 1] reversed. Applied to the projection
// in double, so the z row's coefficients (n / (f - n), f n / (f - n) for a perspective) are
// rounded once, without the cancellation of computing them from the [-1, 1] row in float.
glm::dmat4 reversedDouble(const glm::mat4& proj, const glm::mat4& view) {
    glm::dmat4 reverse(1.0);
    reverse[2][2] = -0.5;
    reverse[3][2] = 0.5;
    return reverse * glm::dmat4(proj) * glm::dmat4(view);
}

float signNotZero(float v) {
    return v >= 0.0f ? 1.0f : -1.0f;
}
} // namespace

glm::mat4 reversedViewProj(const glm::mat4& proj, const glm::mat4& view) {
    return glm::mat4(reversedDouble(proj, view));
}

glm::mat4 inverseReversedViewProj(const glm::mat4& proj, const glm::mat4& view) {
    return glm::mat4(glm::inverse(reversedDouble(proj, view)));
}

glm::vec4 position(float depth, glm::ivec2 pixel, glm::ivec2 size,
                   const glm::mat4& inverseViewProj) {
    if (depth == kBackgroundDepth) return glm::vec4(0.0f);
    // The same operations, in the same order, as surfacePosition() in surface_decode.glsl.
    const glm::vec2 ndc = (glm::vec2(pixel) + 0.5f) / glm::vec2(size) * 2.0f - 1.0f;
    const glm::vec4 w = inverseViewProj * glm::vec4(ndc, depth, 1.0f);
    return glm::vec4(glm::vec3(w) / w.w, 1.0f);
}

glm::vec2 octEncode(glm::vec3 n) {
    n /= std::abs(n.x) + std::abs(n.y) + std::abs(n.z);
    if (n.z >= 0.0f) return {n.x, n.y};
    return {(1.0f - std::abs(n.y)) * signNotZero(n.x), (1.0f - std::abs(n.x)) * signNotZero(n.y)};
}

glm::vec3 octDecode(glm::vec2 e) {
    glm::vec3 n(e.x, e.y, 1.0f - std::abs(e.x) - std::abs(e.y));
    if (n.z < 0.0f) {
        const glm::vec2 folded((1.0f - std::abs(e.y)) * signNotZero(e.x),
                               (1.0f - std::abs(e.x)) * signNotZero(e.y));
        n.x = folded.x;
        n.y = folded.y;
    }
    return glm::normalize(n);
}

glm::vec3 linearToSrgb(glm::vec3 c) {
    return {fl::linearToSrgb(c.x), fl::linearToSrgb(c.y), fl::linearToSrgb(c.z)};
}

glm::vec3 srgbToLinear(glm::vec3 c) {
    glm::vec3 out;
    for (int i = 0; i < 3; ++i)
        out[i] = c[i] < 0.04045f ? c[i] / 12.92f : std::pow((c[i] + 0.055f) / 1.055f, 2.4f);
    return out;
}

} // namespace fl::surface
