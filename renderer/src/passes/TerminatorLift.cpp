#include <renderer/passes/TerminatorLift.h>

#include <algorithm>
#include <cmath>

namespace fl::surface {

TangentPlanes terminatorPlanes(const std::array<glm::vec3, 3>& corner,
                               const std::array<glm::vec3, 3>& normals) {
    TangentPlanes t;
    const glm::vec3 c = glm::cross(corner[1] - corner[0], corner[2] - corner[0]);
    const float area = glm::length(c);
    if (!(area > 0.0f)) return t;
    glm::vec3 front = c / area;
    std::array<glm::vec3, 3> n{};
    glm::vec3 sum(0.0f);
    for (int i = 0; i < 3; ++i) {
        const float len = glm::length(normals[i]);
        if (!(len > 0.0f)) return t;
        n[i] = normals[i] / len;
        sum += n[i];
    }
    if (glm::dot(sum, front) < 0.0f) front = -front;
    bool flat = true;
    for (int i = 0; i < 3; ++i) flat = flat && glm::dot(n[i], front) >= 1.0f - 1e-6f;
    if (flat) return t;
    for (int i = 0; i < 3; ++i) t.planes[i] = glm::vec4(n[i], glm::dot(n[i], corner[i]));
    t.front = front;
    return t;
}

glm::vec3 terminatorMove(glm::vec3 p, glm::vec3 w, const TangentPlanes& t, glm::vec3 side) {
    const float s = glm::dot(t.front, side) < 0.0f ? -1.0f : 1.0f;
    glm::vec3 move(0.0f);
    for (int i = 0; i < 3; ++i) {
        const glm::vec3 n(t.planes[i]);
        const float e = s * (glm::dot(n, p) - t.planes[i].w);
        move -= w[i] * std::min(e, 0.0f) * s * n;
    }
    return glm::dot(move, s * t.front) < 0.0f ? glm::vec3(0.0f) : move;
}

float terminatorAmount(float nl, float ngl) {
    return rt::offsetAmount(nl, ngl, kTerminatorOffset);
}

float terminatorLift(glm::vec3 p, glm::vec3 w, const TangentPlanes& t, glm::vec3 n, glm::vec3 plane,
                     glm::vec3 l) {
    const glm::vec3 move = terminatorMove(p, w, t, plane);
    return std::max(glm::dot(move, n), 0.0f) * terminatorAmount(glm::dot(n, l), glm::dot(plane, l));
}

float mapTexelWorld(glm::vec3 world, const glm::mat4& m, float size) {
    const glm::vec4 c = m * glm::vec4(world, 1.0f);
    const glm::vec3 rowX(m[0][0], m[1][0], m[2][0]), rowY(m[0][1], m[1][1], m[2][1]);
    const glm::vec3 rowW(m[0][3], m[1][3], m[2][3]);
    const glm::vec3 gx = (rowX * c.w - c.x * rowW) / (c.w * c.w);
    const glm::vec3 gy = (rowY * c.w - c.y * rowW) / (c.w * c.w);
    const float perUnit = std::min(glm::length(gx), glm::length(gy)) * 0.5f * size;
    return perUnit > 0.0f ? 1.0f / perUnit : 0.0f;
}

glm::vec3 normalOffset(glm::vec3 world, glm::vec3 n, glm::vec3 toLight,
                       const glm::mat4& mapViewProj, float size) {
    const float c = glm::dot(n, toLight);
    if (!(c > 0.0f)) return world;
    const float s = std::sqrt(std::max(1.0f - c * c, 0.0f));
    return world + n * (kNormalOffsetTexels * s * mapTexelWorld(world, mapViewProj, size));
}

} // namespace fl::surface
