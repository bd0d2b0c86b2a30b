#include <renderer/soft/PenumbraReach.h>

#include <renderer/soft/EyeDecode.h>

#include <renderer/soft/PenumbraCriterion.h> // setDiskLightUniforms

#include <algorithm>
#include <cmath>
#include <limits>

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

glm::vec2 nearestLightDepths(const Scene& scene, const Pose& pose, const DiskLight& light,
                             glm::vec3 axis) {
    glm::vec2 nearest(std::numeric_limits<float>::max());
    std::vector<glm::vec3> positions;
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
        posedVertices(scene, pose, i, positions);
        for (const glm::vec3& v : positions)
            nearest = glm::min(nearest, glm::vec2(glm::dot(v - light.center, light.normal),
                                                  glm::dot(v - light.center, axis)));
    }
    return nearest;
}

std::optional<long long> widestPenumbraTexels(const DiskLight& light,
                                              const geom::ViewVolume& lightVolume, int size,
                                              glm::vec2 nearest, float farDepth) {
    const glm::mat4& p = lightVolume.proj;
    // A perspective projection has w_clip = -z_view (column 2, row 3 is -1; column 3, row 3 0).
    if (p[2][3] != -1.0f || p[3][3] != 0.0f || !(p[0][0] > 0.0f) || !(p[1][1] > 0.0f)) return {};
    const glm::mat4 toWorld = glm::inverse(lightVolume.view);
    const glm::vec3 eye(toWorld[3]);
    const glm::vec3 ex = glm::normalize(glm::vec3(toWorld[0]));
    const glm::vec3 ey = glm::normalize(glm::vec3(toWorld[1]));
    const glm::vec3 axis = -glm::normalize(glm::vec3(toWorld[2])); // the view direction
    const float scale = std::max(farDepth, 1e-3f);
    if (glm::length(eye - light.center) > 1e-5f * scale) return {};
    if (!(nearest.x > 1e-6f * scale) || !(nearest.y > 1e-6f * scale)) return {};
    // The cap's corner vectors, as disk_light.glsl's penumbraRect builds them (unit length).
    const glm::vec3 n = glm::normalize(light.normal);
    const glm::vec3 a = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    const glm::vec3 u = glm::normalize(glm::cross(n, a));
    const glm::vec3 v = glm::cross(n, u);
    const auto across = [&](glm::vec3 e) {
        return std::abs(glm::dot(u, e)) + std::abs(glm::dot(v, e));
    };
    const float lateral = std::max(across(ex), across(ey)), deep = across(axis);
    const float t = std::max((farDepth - nearest.x) / nearest.x, 0.0f) * 1.01f + 1e-3f;
    // The cap's half-side over the capCentre's view depth, at most.
    const float capOverDepth = 1.01f * light.radius * t / ((1.0f + t) * nearest.y);
    const float tanHalf = 1.0f / std::min(p[0][0], p[1][1]);
    const float shrink = 1.0f - capOverDepth * deep; // (z - |dz|) / z
    if (!(shrink > 0.5f)) return {};
    const double ndc =
        double(std::max(p[0][0], p[1][1])) * capOverDepth * (lateral + tanHalf * deep) / shrink;
    if (!(ndc < 4.0)) return {};
    return static_cast<long long>(std::ceil(ndc * 0.5 * size)) + 6;
}

namespace {

// shaders/disk_light.glsl's reach bound (setPenumbraReachUniforms).
constexpr struct {
    gl::Uniform<int> enabled{"uReachEnabled"};
    gl::Uniform<glm::mat4> matrix{"uReachMatrix"};
    gl::Uniform<glm::ivec2> size{"uReachSize"};
    gl::Uniform<float> farDepth{"uReachFarDepth"};
    gl::Uniform<int> levels{"uReachLevels"};
    gl::Uniform<int> cells{"uReachCells"};
} kReach;

// reach_bounds.comp.glsl's own uniforms.
constexpr struct {
    gl::Uniform<float> validMin{"uValidMin"};
    gl::Uniform<int> regionTile{"uRegionTile"};
    gl::Uniform<int> regionTilesX{"uRegionTilesX"};
    gl::Uniform<int> mode{"uMode"};
    gl::Uniform<glm::ivec2> dstSize{"uDstSize"};
    gl::Uniform<glm::ivec2> srcSize{"uSrcSize"};
} kReachBounds;

} // namespace

void setPenumbraReachUniforms(gl::BindScope& scope, const gl::Program& program,
                              const PenumbraReach& reach) {
    program.set(kReach.enabled, reach.enabled ? 1 : 0);
    program.set(kReach.matrix, reach.worldToClip);
    program.set(kReach.size, reach.size);
    program.set(kReach.farDepth, reach.farDepth);
    program.set(kReach.levels, reach.boundsLo != 0 ? reach.boundsLevels : 0);
    program.set(kReach.cells, reach.firstCells);
    scope.texture(gl::bind::ReachLo, reach.boundsLo).texture(gl::bind::ReachHi, reach.boundsHi);
}

void bindPenumbraReachUniforms(gl::Program& program) {
    program.bindUniforms({&kReach.enabled, &kReach.matrix, &kReach.size, &kReach.farDepth,
                          &kReach.levels, &kReach.cells});
}

namespace {
// source 0: a texture of positions, 1: the shadow map's receiver target, 2: JFA-E's eye cells.
gl::Program boundsProgram(const gl::ShaderLibrary& shaders, int source, bool region) {
    std::vector<std::string> defines;
    if (source == 1) defines.emplace_back("MAP_RECEIVERS 1");
    if (source == 2) defines.emplace_back("EYE_CELLS 1");
    if (region) defines.emplace_back("REACH_REGION 1");
    gl::Program program =
        gl::Program::build(shaders, {{GL_COMPUTE_SHADER, "reach_bounds.comp.glsl"}}, defines);
    const auto& u = kReachBounds;
    program.bindUniforms(
        {&u.validMin, &u.regionTile, &u.regionTilesX, &u.mode, &u.dstSize, &u.srcSize});
    bindDiskLightUniforms(program);
    if (source == 1) MapPositions::bindUniforms(program);
    if (source == 2) EyeCells::bindUniforms(program);
    return program;
}
} // namespace

ReceiverBoundsPyramid::ReceiverBoundsPyramid(const gl::ShaderLibrary& shaders)
    : programs_{{boundsProgram(shaders, 0, false), boundsProgram(shaders, 0, true)},
                {boundsProgram(shaders, 1, false), boundsProgram(shaders, 1, true)},
                {boundsProgram(shaders, 2, false), boundsProgram(shaders, 2, true)}} {}

std::int64_t ReceiverBoundsPyramid::bytes() const {
    std::int64_t texels = 0;
    for (int l = 0, w = lo_.width(), h = lo_.height(); l < levels_;
         ++l, w = std::max(1, w / 2), h = std::max(1, h / 2))
        texels += std::int64_t(w) * h;
    return levels_ == 0 ? 0
                        : texels * (gl::texelBytes(lo_.format()) + gl::texelBytes(hi_.format()));
}

void ReceiverBoundsPyramid::build(const gl::Texture& positions, float validMin,
                                  const DiskLight& light, PenumbraReach& reach,
                                  const gl::Buffer* region, int regionTile) {
    const gl::Program& program = programs_[0][region != nullptr];
    gl::BindScope scope;
    scope.texture(gl::bind::ReachPositions, positions.id());
    build(scope, program, positions.width(), positions.height(), validMin, light, reach, region,
          regionTile);
}

void ReceiverBoundsPyramid::build(const EyeCells& eye, const DiskLight& light,
                                  PenumbraReach& reach) {
    const gl::Program& program = programs_[2][0];
    gl::BindScope scope;
    eye.bind(scope, program);
    build(scope, program, eye.width(), eye.height(), -0.5f, light, reach, nullptr, 8); // w >= 0
}

void ReceiverBoundsPyramid::build(const MapPositions& map, const DiskLight& light,
                                  PenumbraReach& reach, const gl::Buffer* region, int regionTile) {
    const gl::Program& program = programs_[1][region != nullptr];
    gl::BindScope scope;
    map.bind(scope, program, gl::bind::ReachPositions);
    build(scope, program, map.size(), map.size(), 0.5f, light, reach, region, regionTile); // w = 1
}

void ReceiverBoundsPyramid::build(gl::BindScope& scope, const gl::Program& program, int width,
                                  int height, float validMin, const DiskLight& light,
                                  PenumbraReach& reach, const gl::Buffer* region, int regionTile) {
    const int w0 = (width + 7) / 8, h0 = (height + 7) / 8;
    if (!lo_ || lo_.width() != w0 || lo_.height() != h0) {
        levels_ = 1; // GL's mip chain: sizes halve rounding down, to 1 x 1
        for (int w = w0, h = h0; w > 1 || h > 1; w = std::max(1, w / 2), h = std::max(1, h / 2))
            ++levels_;
        lo_ = gl::Texture(GL_RGBA32F, w0, h0, levels_);
        hi_ = gl::Texture(GL_RGBA32F, w0, h0, levels_);
    }
    glUseProgram(program.id());
    setDiskLightUniforms(program, light);
    const auto& u = kReachBounds;
    program.set(u.validMin, validMin);
    program.set(u.regionTile, regionTile);
    program.set(u.regionTilesX, (width + regionTile - 1) / regionTile);
    scope.storage(gl::bind::SeedRegion, region != nullptr ? region->id() : 0);
    int w = w0, h = h0, sw = width, sh = height;
    for (int level = 0; level < levels_; ++level) {
        program.set(u.mode, level == 0 ? 0 : 1);
        program.set(u.dstSize, glm::ivec2(w, h));
        program.set(u.srcSize, glm::ivec2(sw, sh));
        scope.image(gl::bind::ReachLoOut, lo_.id(), GL_WRITE_ONLY, GL_RGBA32F, level)
            .image(gl::bind::ReachHiOut, hi_.id(), GL_WRITE_ONLY, GL_RGBA32F, level);
        if (level > 0) {
            scope.image(gl::bind::ReachLoIn, lo_.id(), GL_READ_ONLY, GL_RGBA32F, level - 1)
                .image(gl::bind::ReachHiIn, hi_.id(), GL_READ_ONLY, GL_RGBA32F, level - 1);
        }
        glDispatchCompute(GLuint((w + 7) / 8), GLuint((h + 7) / 8), 1);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
        sw = w;
        sh = h;
        w = std::max(1, w / 2);
        h = std::max(1, h / 2);
    }
    scope.release();
    glUseProgram(0);
    reach.boundsLo = lo_.id();
    reach.boundsHi = hi_.id();
    reach.boundsLevels = levels_;
}

} // namespace fl
