#include <renderer/overlays/OverlayColours.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace fl::overlay {

glm::vec3 idColour(std::uint32_t id) {
    std::uint32_t h = id * 2654435761u;
    h ^= h >> 15;
    return glm::vec3(float(64u + (h & 0x7fu)), float(64u + ((h >> 8) & 0x7fu)),
                     float(64u + ((h >> 16) & 0x7fu))) /
           255.0f;
}

glm::vec3 ramp(float t) {
    static constexpr std::array<glm::vec3, 5> stops{
        glm::vec3(0.05f, 0.03f, 0.20f), glm::vec3(0.40f, 0.10f, 0.50f),
        glm::vec3(0.80f, 0.25f, 0.30f), glm::vec3(0.98f, 0.60f, 0.10f),
        glm::vec3(0.99f, 0.98f, 0.70f)};
    const float s = std::clamp(t, 0.0f, 1.0f) * 4.0f;
    const int i = std::min(int(s), 3);
    return glm::mix(stops[std::size_t(i)], stops[std::size_t(i) + 1], s - float(i));
}

glm::u8vec3 toBytes(glm::vec3 c) {
    const glm::vec3 v = glm::round(glm::clamp(c, 0.0f, 1.0f) * 255.0f);
    return {std::uint8_t(v.x), std::uint8_t(v.y), std::uint8_t(v.z)};
}

} // namespace fl::overlay
