#include <renderer/passes/Phases.h>
#include <renderer/soft/FilteredShadow.h>

#include <geometry/DiskSampling.h>

#include <renderer/passes/SurfacesPass.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fl {

std::optional<PcssPreset> parsePcssPreset(std::string_view text) {
    if (text == "16/16") return PcssPreset{16, 16};
    if (text == "16/24") return PcssPreset{16, 24};
    if (text == "32/64") return PcssPreset{32, 64};
    return std::nullopt;
}

std::vector<glm::vec2> vogelDisk(int count) {
    std::vector<glm::vec2> out;
    const double golden = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < count; ++i) {
        // Radius sqrt((i + 0.5) / n): each point stands for an equal area of the disk.
        const double r = std::sqrt((i + 0.5) / count);
        const double a = golden * i;
        out.emplace_back(static_cast<float>(r * std::cos(a)), static_cast<float>(r * std::sin(a)));
    }
    return out;
}

std::vector<glm::vec2> pcfOffsets(int kernel) {
    std::vector<glm::vec2> out;
    const float half = 0.5f * static_cast<float>(kernel - 1);
    for (int j = 0; j < kernel; ++j)
        for (int i = 0; i < kernel; ++i)
            out.emplace_back(static_cast<float>(i) - half, static_cast<float>(j) - half);
    return out;
}

namespace {

glm::vec3 unproject(const glm::mat4& invProj, glm::vec3 ndc) {
    const glm::vec4 v = invProj * glm::vec4(ndc, 1.0f);
    return glm::vec3(v) / v.w;
}

struct Tap {
    float lit;
    float stored;
};

// Same operations as tap() in shaders/filtered_shadow.frag.glsl.
Tap tap(const FilterFrame& f, const glm::mat4& invProj, glm::vec2 s, glm::vec3 pv, glm::vec3 nv,
        float receiverNdcZ) {
    const glm::vec4 m = f.warp * glm::vec4(s, receiverNdcZ, 1.0f);
    if (m.w <= 0.0f) return {1.0f, 1.0f};
    const glm::vec2 uv = glm::vec2(m) / m.w * 0.5f + 0.5f;
    if (uv.x < 0.0f || uv.y < 0.0f || uv.x > 1.0f || uv.y > 1.0f) return {1.0f, 1.0f};
    const int tx = std::clamp(static_cast<int>(std::floor(uv.x * f.size)), 0, f.size - 1);
    const int ty = std::clamp(static_cast<int>(std::floor(uv.y * f.size)), 0, f.size - 1);
    const float stored = f.depth[static_cast<std::size_t>(ty) * f.size + tx];
    const glm::vec3 a = unproject(invProj, {s, -1.0f});
    const glm::vec3 b = unproject(invProj, {s, 1.0f});
    const float den = glm::dot(nv, b - a);
    float ref = receiverNdcZ * 0.5f + 0.5f;
    if (std::abs(den) > 1e-6f * glm::length(b - a)) {
        const float t = glm::dot(nv, pv - a) / den;
        if (t > 0.0f && t < 1.0f) {
            const glm::vec4 c = f.lightProj * glm::vec4(a + t * (b - a), 1.0f);
            ref = c.z / c.w * 0.5f + 0.5f;
        }
    }
    return {ref <= stored ? 1.0f : 0.0f, stored};
}

glm::vec4 diskThrough(const FilterFrame& f, glm::vec3 pv, glm::vec3 cv, float d) {
    const float dR = -pv.z, dC = -cv.z;
    const float k = (dR - d) / std::max(dR - dC, 1e-6f);
    const glm::vec3 x = pv + (cv - pv) * k;
    const glm::vec4 clip = f.lightProj * glm::vec4(x, 1.0f);
    const float r = f.disk.radius * std::max(k, 0.0f);
    return {clip.x / clip.w, clip.y / clip.w, f.lightProj[0][0] * r / clip.w,
            f.lightProj[1][1] * r / clip.w};
}

// PCSS's filter region: the disk light seen from the receiver pv through the plane parallel to
// the disk at distance `blocker` in front of it (the blockers' mean distance), projected into
// the light's NDC: centre and the images of the disk's two tangents (the projection taken as
// affine across the small region). Same operations as diskImage() in the shader.
struct DiskImage {
    glm::vec2 centre, u, v;
};
DiskImage diskImage(const FilterFrame& f, glm::vec3 pv, glm::vec3 cv, float blocker) {
    const float dR = glm::dot(pv - cv, f.diskNormalView);
    const float k = (dR - blocker) / std::max(dR, 1e-6f);
    const glm::vec3 x = pv + (cv - pv) * k;
    const float r = f.disk.radius * std::max(k, 0.0f);
    auto ndc = [&](glm::vec3 q) {
        const glm::vec4 c = f.lightProj * glm::vec4(q, 1.0f);
        return glm::vec2(c.x / c.w, c.y / c.w);
    };
    const glm::vec2 c0 = ndc(x);
    return {c0, ndc(x + r * f.diskTangentView) - c0, ndc(x + r * f.diskBitangentView) - c0};
}

} // namespace

std::vector<float> readDepthMap(const gl::Texture& depth) {
    return gl::readTexels<float>(depth, GL_DEPTH_COMPONENT, GL_FLOAT);
}

float filteredVisibility(const FilterFrame& f, glm::vec3 p, glm::vec3 n) {
    const glm::mat4 invProj = glm::inverse(f.lightProj);
    const glm::vec3 pv = glm::vec3(f.lightView * glm::vec4(p, 1.0f));
    const glm::vec3 nv = glm::mat3(f.lightView) * n;
    const glm::vec4 clip = f.lightProj * glm::vec4(pv, 1.0f);
    if (clip.w <= 0.0f) return 1.0f;
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    // The taps at centre + u * t.x + v * t.y (PCF: u, v the unit axes, an exact no-op).
    auto filter = [&](glm::vec2 centre, glm::vec2 u, glm::vec2 v) {
        float lit = 0.0f;
        for (glm::vec2 t : f.taps)
            lit += tap(f, invProj, centre + u * t.x + v * t.y, pv, nv, ndc.z).lit;
        return lit / static_cast<float>(f.taps.size());
    };
    if (f.mode == FilterFrame::Mode::Pcf) return filter(glm::vec2(ndc), {1.0f, 0.0f}, {0.0f, 1.0f});
    const glm::vec3 cv = glm::vec3(f.lightView * glm::vec4(f.disk.center, 1.0f));
    const glm::vec4 search = diskThrough(f, pv, cv, f.searchDepth);
    float blockers = 0.0f, depthSum = 0.0f;
    for (glm::vec2 b : f.blockerTaps) {
        const glm::vec2 s = glm::vec2(search) + glm::vec2(search.z, search.w) * b;
        const Tap r = tap(f, invProj, s, pv, nv, ndc.z);
        if (r.lit == 0.0f) {
            blockers += 1.0f;
            // The blocker's distance in front of the disk, from its point in the map.
            const glm::vec3 bv = unproject(invProj, {s, 2.0f * r.stored - 1.0f});
            depthSum += glm::dot(bv - cv, f.diskNormalView);
        }
    }
    if (blockers == 0.0f) return 1.0f;
    const DiskImage d = diskImage(f, pv, cv, depthSum / blockers);
    return filter(d.centre, d.u, d.v);
}

namespace {
// filtered_shadow.frag.glsl's own uniforms.
constexpr struct {
    gl::Uniform<glm::mat4> lightView{"uLightView"};
    gl::Uniform<glm::mat4> lightProj{"uLightProj"};
    gl::Uniform<glm::mat4> invLightProj{"uInvLightProj"};
    gl::Uniform<glm::mat4> warp{"uShadowWarp"};
    gl::Uniform<int> pcss{"uPcss"};
    gl::Uniform<glm::vec3> diskCenter{"uDiskCenter"};
    gl::Uniform<float> diskRadius{"uDiskRadius"};
    gl::Uniform<float> searchDepth{"uSearchDepth"};
    gl::Uniform<glm::vec3> diskNormalView{"uDiskNormalView"};
    gl::Uniform<glm::vec3> diskTangentView{"uDiskTangentView"};
    gl::Uniform<glm::vec3> diskBitangentView{"uDiskBitangentView"};
    gl::Uniform<int> tapCount{"uTapCount"};
    gl::UniformArray<glm::vec2> taps{"uTaps"};
    gl::Uniform<int> blockerCount{"uBlockerCount"};
    gl::UniformArray<glm::vec2> blockerTaps{"uBlockerTaps"};
} kFiltered;
} // namespace

FilteredShadowPass::FilteredShadowPass(const gl::ShaderLibrary& shaders)
    : program_(gl::Program::build(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                            {GL_FRAGMENT_SHADER, "filtered_shadow.frag.glsl"}})),
      rawDepth_(gl::makeRawTexelSampler()), emptyVao_(gl::VertexArray::create()) {
    const auto& u = kFiltered;
    program_.bindUniforms({&u.lightView, &u.lightProj, &u.invLightProj, &u.warp, &u.pcss,
                           &u.diskCenter, &u.diskRadius, &u.searchDepth, &u.diskNormalView,
                           &u.diskTangentView, &u.diskBitangentView, &u.tapCount, &u.taps,
                           &u.blockerCount, &u.blockerTaps});
    SurfacePositions::bindUniforms(program_);
}

void FilteredShadowPass::resize(int width, int height) {
    if (visibility_ && visibility_.width() == width && visibility_.height() == height) return;
    visibility_ = gl::Texture(GL_R32F, width, height);
    fbo_ = gl::Framebuffer::forColor(visibility_, "filtered shadows");
}

FilterFrame FilteredShadowPass::frame(const Inputs& in) const {
    FilterFrame f;
    f.mode = in.pcss ? FilterFrame::Mode::Pcss : FilterFrame::Mode::Pcf;
    f.lightView = in.lightVolume.view;
    f.lightProj = in.lightVolume.proj;
    f.warp = in.shadow.warp;
    f.disk = in.light;
    // The blocker search looks through the near plane, but never at or behind the disk.
    const float diskDepth = -(in.lightVolume.view * glm::vec4(in.light.center, 1.0f)).z;
    f.searchDepth = std::max(in.lightVolume.znear, diskDepth + 1e-3f * in.lightVolume.znear);
    const glm::mat3 toView(in.lightVolume.view);
    const geom::DiskFrame axes = geom::diskFrame(in.light.normal);
    f.diskNormalView = glm::normalize(toView * in.light.normal);
    f.diskTangentView = toView * axes.tangent;
    f.diskBitangentView = toView * axes.bitangent;
    const int k = in.settings.pcfKernel;
    if (in.pcss) {
        f.taps = vogelDisk(in.settings.pcss.filterSamples);
        f.blockerTaps = vogelDisk(in.settings.pcss.blockerSamples);
    } else {
        // One uniform-map texel is 2 / size in NDC.
        const float texel = 2.0f / static_cast<float>(in.shadow.depth.width());
        for (glm::vec2 o : pcfOffsets(k)) f.taps.push_back(o * texel);
    }
    f.size = in.shadow.depth.width();
    return f;
}

FilteredShadowPass::Outputs FilteredShadowPass::execute(const Inputs& in, gl::PassTimer* timer) {
    const FilteredShadowSettings& s = in.settings;
    if (s.pcfKernel < 1 || s.pcfKernel > kMaxPcfKernel)
        throw std::invalid_argument("PCF kernel " + std::to_string(s.pcfKernel) +
                                    " is outside [1, " + std::to_string(kMaxPcfKernel) + "]");
    if (s.pcss.blockerSamples < 1 || s.pcss.blockerSamples > 64 || s.pcss.filterSamples < 1 ||
        s.pcss.filterSamples > 225)
        throw std::invalid_argument("PCSS sample counts must be in [1, 64] / [1, 225]");
    const int width = in.surfaces.width, height = in.surfaces.height;
    resize(width, height);
    gl::TimedPass timedFilter(timer, in.pcss ? phase::kBlockerSearchFilter : phase::kPcfFilter);
    const FilterFrame f = frame(in);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, width, height);
    glDisable(GL_DEPTH_TEST);
    const auto& u = kFiltered;
    program_.set(u.lightView, f.lightView);
    program_.set(u.lightProj, f.lightProj);
    program_.set(u.invLightProj, glm::inverse(f.lightProj));
    program_.set(u.warp, f.warp);
    program_.set(u.pcss, in.pcss ? 1 : 0);
    program_.set(u.diskCenter, f.disk.center);
    program_.set(u.diskRadius, f.disk.radius);
    program_.set(u.searchDepth, f.searchDepth);
    program_.set(u.diskNormalView, f.diskNormalView);
    program_.set(u.diskTangentView, f.diskTangentView);
    program_.set(u.diskBitangentView, f.diskBitangentView);
    program_.set(u.tapCount, static_cast<int>(f.taps.size()));
    program_.set(u.taps, f.taps);
    program_.set(u.blockerCount, static_cast<int>(f.blockerTaps.size()));
    program_.set(u.blockerTaps, f.blockerTaps);
    gl::BindScope scope;
    scope.texture(gl::bind::ShadowDepth, in.shadow.depth.id())
        .sampler(gl::bind::ShadowDepth, rawDepth_.id());
    in.surfaces.positions().bind(scope, program_, gl::bind::SurfacesDepth);
    scope.texture(gl::bind::SurfacesNormals, in.surfaces.normals.id());
    in.surfaces.bindLookup(scope);
    gl::drawFullscreenTriangle(program_, emptyVao_);
    scope.release();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    timedFilter.wrote(gl::textureBytes(visibility_));
    timedFilter.end();
    return {visibility_};
}

} // namespace fl
