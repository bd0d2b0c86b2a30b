#include <renderer/soft/PenumbraReach.h>

#include <renderer/soft/PenumbraCriterion.h> // setDiskLightUniforms

#include <algorithm>
#include <cmath>

namespace fl {

float farthestLightDepth(const DiskLight& light, const geom::Aabb& bounds) {
    if (!bounds.valid()) return 0.0f;
    float far = 0.0f;
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner((i & 1) ? bounds.max.x : bounds.min.x,
                               (i & 2) ? bounds.max.y : bounds.min.y,
                               (i & 4) ? bounds.max.z : bounds.min.z);
        far = std::max(far, std::abs(glm::dot(corner - light.center, light.normal)));
    }
    return far * 1.001f + 1e-4f * std::max(glm::length(bounds.max - bounds.min), 1e-3f);
}

PenumbraReach penumbraReach(const DiskLight& light, const glm::mat4& worldToClip, glm::ivec2 size,
                            const geom::Aabb& bounds) {
    return {true, worldToClip, size, farthestLightDepth(light, bounds)};
}

jfa::ReachRect penumbraReachRect(const DiskLight& light, const PenumbraReach& reach, glm::vec3 o) {
    if (!reach.enabled) return {};
    const glm::vec3 n = light.normal;
    const float depth = std::abs(glm::dot(o - light.center, n));
    if (!(depth > 1e-6f)) return {}; // on the light's plane: any direction
    const float t = std::max((reach.farDepth - depth) / depth, 0.0f) * 1.01f + 1e-3f;
    const glm::vec3 capCenter = o + t * (o - light.center);
    const float capRadius = t * light.radius * 1.01f;
    const glm::vec3 a = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    const glm::vec3 u = glm::normalize(glm::cross(n, a)) * capRadius;
    const glm::vec3 v = glm::cross(glm::normalize(n), glm::normalize(u)) * capRadius;
    glm::vec2 lo(1e30f), hi(-1e30f);
    for (int i = 0; i < 5; ++i) {
        const glm::vec3 q = i == 4 ? o : capCenter + ((i & 1) ? -u : u) + ((i & 2) ? -v : v);
        const glm::vec4 c = reach.worldToClip * glm::vec4(q, 1.0f);
        if (!(c.w > 1e-6f)) return {}; // behind the projection: no bound
        const glm::vec2 texel = (glm::vec2(c) / c.w * 0.5f + 0.5f) * glm::vec2(reach.size);
        lo = glm::min(lo, texel);
        hi = glm::max(hi, texel);
    }
    if (!(hi.x - lo.x < 1e9f && hi.y - lo.y < 1e9f)) return {}; // also NaN
    return {
        static_cast<long long>(std::floor(lo.x)) - 2, static_cast<long long>(std::floor(lo.y)) - 2,
        static_cast<long long>(std::floor(hi.x)) + 2, static_cast<long long>(std::floor(hi.y)) + 2};
}

void setPenumbraReachUniforms(const gl::Program& program, const PenumbraReach& reach) {
    program.set("uReachEnabled", reach.enabled ? 1 : 0);
    program.set("uReachMatrix", reach.worldToClip);
    program.set("uReachSize", reach.size);
    program.set("uReachFarDepth", reach.farDepth);
    program.set("uReachLevels", reach.boundsLo != 0 ? reach.boundsLevels : 0);
    glBindTextureUnit(4, reach.boundsLo);
    glBindTextureUnit(5, reach.boundsHi);
}

void unbindPenumbraReach() {
    glBindTextureUnit(4, 0);
    glBindTextureUnit(5, 0);
}

ReceiverBoundsPyramid::ReceiverBoundsPyramid(const gl::ShaderLibrary& shaders)
    : program_(gl::Program::build(shaders, {{GL_COMPUTE_SHADER, "reach_bounds.comp.glsl"}})) {}

void ReceiverBoundsPyramid::build(const gl::Texture& positions, float validMin,
                                  const DiskLight& light, PenumbraReach& reach) {
    const int w0 = (positions.width() + 7) / 8, h0 = (positions.height() + 7) / 8;
    if (!lo_ || lo_.width() != w0 || lo_.height() != h0) {
        levels_ = 1; // GL's mip chain: sizes halve rounding down, to 1 x 1
        for (int w = w0, h = h0; w > 1 || h > 1; w = std::max(1, w / 2), h = std::max(1, h / 2))
            ++levels_;
        lo_ = gl::Texture(GL_RGBA32F, w0, h0, levels_);
        hi_ = gl::Texture(GL_RGBA32F, w0, h0, levels_);
    }
    glUseProgram(program_.id());
    setDiskLightUniforms(program_, light);
    program_.set("uValidMin", validMin);
    glBindTextureUnit(0, positions.id());
    int w = w0, h = h0, sw = positions.width(), sh = positions.height();
    for (int level = 0; level < levels_; ++level) {
        program_.set("uMode", level == 0 ? 0 : 1);
        program_.set("uDstSize", glm::ivec2(w, h));
        program_.set("uSrcSize", glm::ivec2(sw, sh));
        glBindImageTexture(0, lo_.id(), level, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
        glBindImageTexture(1, hi_.id(), level, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
        if (level > 0) {
            glBindImageTexture(2, lo_.id(), level - 1, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
            glBindImageTexture(3, hi_.id(), level - 1, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
        }
        glDispatchCompute(GLuint((w + 7) / 8), GLuint((h + 7) / 8), 1);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
        sw = w;
        sh = h;
        w = std::max(1, w / 2);
        h = std::max(1, h / 2);
    }
    for (GLuint unit = 0; unit < 4; ++unit)
        glBindImageTexture(unit, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindTextureUnit(0, 0);
    glUseProgram(0);
    reach.boundsLo = lo_.id();
    reach.boundsHi = hi_.id();
    reach.boundsLevels = levels_;
}

} // namespace fl
