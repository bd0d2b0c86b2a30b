#include <renderer/io/TextureImage.h>
#include <renderer/passes/Phases.h>
#include <renderer/soft/ReferenceShadow.h>

#include <renderer/metrics/Metrics.h>

#include <base/Framing.h>
#include <geometry/DiskSampling.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace fl {

namespace {
// The reference's passes: each sample's depth map (shadow_depth.*.glsl), its lookup added to
// the sum (reference_accumulate.frag.glsl, shadow_lookup.glsl's names) and the mean.
const ShadowDepthUniforms& kReferenceDepth = kShadowDepthUniforms;
const ShadowLookupUniforms& kReferenceAccumulate = kShadowLookupUniforms;
constexpr gl::Uniform<float> kReferenceSamples{"uSamples"};
} // namespace

std::vector<glm::vec3> referenceDiskSamples(const DiskLight& disk, int samples,
                                            geom::DiskPattern pattern) {
    if (samples < 1)
        throw std::invalid_argument("reference samples must be >= 1, got " +
                                    std::to_string(samples));
    const geom::DiskFrame frame = geom::diskFrame(disk.normal);
    const glm::vec3 t = frame.tangent, b = frame.bitangent;
    std::vector<glm::vec3> out;
    for (const glm::dvec2 d : geom::diskPattern(pattern, samples)) {
        if (d.x == 0.0 && d.y == 0.0) {
            out.push_back(disk.center); // exactly the centre (N = 1 is the hard shadow)
            continue;
        }
        out.push_back(disk.center +
                      disk.radius * (static_cast<float>(d.x) * t + static_cast<float>(d.y) * b));
    }
    return out;
}

VisibilityDifference visibilityDifference(const FloatImage& a, const FloatImage& b,
                                          const FloatImage& mask) {
    if (a.data.size() != b.data.size() || (!mask.data.empty() && mask.data.size() != a.data.size()))
        throw std::invalid_argument("visibilityDifference: images of different sizes");
    VisibilityDifference d;
    double sum2 = 0.0;
    for (std::size_t i = 0; i < a.data.size(); ++i) {
        if (!isReceiver(mask, i)) continue;
        const double e = static_cast<double>(a.data[i]) - static_cast<double>(b.data[i]);
        sum2 += e * e;
        d.maxAbs = std::max(d.maxAbs, std::abs(e));
        ++d.pixels;
    }
    d.rmse = d.pixels ? std::sqrt(sum2 / static_cast<double>(d.pixels)) : 0.0;
    return d;
}

ReferenceShadowPass::ReferenceShadowPass(const gl::ShaderLibrary& shaders)
    : depth_(gl::Program::build(shaders, {{GL_VERTEX_SHADER, "shadow_depth.vert.glsl"},
                                          {GL_FRAGMENT_SHADER, "shadow_depth.frag.glsl"}})),
      accumulate_(
          gl::Program::build(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                       {GL_FRAGMENT_SHADER, "reference_accumulate.frag.glsl"}})),
      resolve_(gl::Program::build(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                            {GL_FRAGMENT_SHADER, "reference_resolve.frag.glsl"}})),
      emptyVao_(gl::VertexArray::create()) {
    const auto& d = kReferenceDepth;
    depth_.bindUniforms({&d.lightViewProj, &d.warp, &d.slopeBias, &d.constantBias});
    const auto& a = kReferenceAccumulate;
    accumulate_.bindUniforms({&a.lightViewProj, &a.warp, &a.light});
    SurfacePositions::bindUniforms(accumulate_);
    resolve_.bindUniforms({&kReferenceSamples});
    SurfacePositions::bindUniforms(resolve_);
}

void ReferenceShadowPass::resize(int width, int height, int mapSize) {
    if (!map_ || map_.width() != mapSize) {
        // The shadow pass's kind of map, so one sample is exactly the hard test.
        map_ = makeShadowDepthTexture(mapSize);
        mapFbo_ = gl::Framebuffer::withTargets({}, &map_, "reference depth map");
    }
    if (sum_ && sum_.width() == width && sum_.height() == height) return;
    sum_ = gl::Texture(GL_R32F, width, height);
    visibility_ = gl::Texture(GL_R32F, width, height);
    sumFbo_ = gl::Framebuffer::forColor(sum_, "reference sum");
    visibilityFbo_ = gl::Framebuffer::forColor(visibility_, "reference visibility");
}

ReferenceShadowPass::Outputs ReferenceShadowPass::execute(const Inputs& in, gl::PassTimer* timer) {
    const std::vector<glm::vec3> samples =
        referenceDiskSamples(in.light, in.settings.samples, in.settings.pattern);
    const int maxSize = gl::maxTextureSize();
    if (in.settings.mapSize < 16 || in.settings.mapSize > maxSize)
        throw std::invalid_argument("reference map size " + std::to_string(in.settings.mapSize) +
                                    " is outside [16, " + std::to_string(maxSize) + "]");
    const int width = in.positions.width(), height = in.positions.height();
    resize(width, height, in.settings.mapSize);

    const float none[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    const float far = 1.0f;

    // One depth map per disk sample, each added to the sum.
    gl::TimedPass timedReferenceMaps(timer, phase::kReferenceMaps);
    glClearNamedFramebufferfv(sumFbo_.id(), GL_COLOR, 0, none);
    depth_.set(kReferenceDepth.warp, glm::mat4(1.0f));
    depth_.set(kReferenceDepth.slopeBias, in.shadowSettings.slopeBias);
    depth_.set(kReferenceDepth.constantBias, in.shadowSettings.constantBias);
    accumulate_.set(kReferenceAccumulate.warp, glm::mat4(1.0f));
    {
        gl::BindScope matrix; // the matrix once; the depth is bound per map, below
        in.positions.bind(matrix, accumulate_, gl::bind::SurfacesDepth);
    }
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE);
    for (const glm::vec3& q : samples) {
        // The volume the scene's own point light at q would get (Renderer's lightVolume()).
        const glm::mat4 viewProj =
            geom::fitPerspectiveLight(in.casterBounds, in.sceneBounds, q, in.light.normal, 0.0f)
                .viewProj();
        glBindFramebuffer(GL_FRAMEBUFFER, mapFbo_.id());
        glViewport(0, 0, map_.width(), map_.height());
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDepthMask(GL_TRUE);
        glClearNamedFramebufferfv(mapFbo_.id(), GL_DEPTH, 0, &far);
        depth_.set(kReferenceDepth.lightViewProj, viewProj);
        in.scene.draw(depth_, GpuScene::Uniforms::Geometry);

        glBindFramebuffer(GL_FRAMEBUFFER, sumFbo_.id());
        glViewport(0, 0, width, height);
        // Depth test and blending alternate with the map pass; the rest is set once above.
        glDisable(GL_DEPTH_TEST);
        glEnable(GL_BLEND);
        accumulate_.set(kReferenceAccumulate.lightViewProj, viewProj);
        accumulate_.set(kReferenceAccumulate.light, shadowLight(viewProj));
        // Bound per map: the scene's draw binds alpha cut-out textures on unit 0, and the next
        // map pass draws into map_ (the scope unbinds it first).
        gl::BindScope scope;
        scope.texture(gl::bind::SurfacesDepth, in.positions.depth.id())
            .texture(gl::bind::ShadowMap, map_.id());
        scope.texture(gl::bind::SurfacesLift, in.lift.id())
            .texture(gl::bind::LookupNormals, in.normals.id());
        gl::drawFullscreenTriangle(accumulate_, emptyVao_);
        glDisable(GL_BLEND);
    }
    glBlendFunc(GL_ONE, GL_ZERO); // the default
    // Each sample writes its depth map and adds into the sum.
    timedReferenceMaps.wrote(static_cast<std::int64_t>(samples.size()) *
                             (gl::textureBytes(map_) + gl::textureBytes(sum_)));
    timedReferenceMaps.end();

    gl::TimedPass timedReferenceResolve(timer, phase::kReferenceResolve);
    glBindFramebuffer(GL_FRAMEBUFFER, visibilityFbo_.id());
    glViewport(0, 0, width, height);
    resolve_.set(kReferenceSamples, static_cast<float>(samples.size()));
    {
        gl::BindScope scope;
        scope.texture(gl::bind::ReferenceSum, sum_.id());
        in.positions.bind(scope, resolve_, gl::bind::ReferenceSurfacesDepth);
        gl::drawFullscreenTriangle(resolve_, emptyVao_);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    timedReferenceResolve.wrote(gl::textureBytes(visibility_));
    timedReferenceResolve.end();
    return {visibility_};
}

VisibilityDifference referenceSamplingError(ReferenceShadowPass& pass,
                                            ReferenceShadowPass::Inputs in, int samples) {
    ReferenceSettings s = in.settings;
    s.samples = samples;
    ReferenceShadowPass::Inputs a{
        in.scene, in.positions, in.sceneBounds, in.casterBounds, in.light, in.shadowSettings,
        s,        in.lift,      in.normals};
    const ReferenceShadowPass::Outputs out = pass.execute(a);
    const FloatImage va = readTexture(out.visibility, 1);
    FloatImage mask = in.positions.read();
    FloatImage surface{mask.width, mask.height, 1, {}};
    for (std::size_t i = 3; i < mask.data.size(); i += 4) surface.data.push_back(mask.data[i]);
    s.samples = 2 * samples;
    ReferenceShadowPass::Inputs b{
        in.scene, in.positions, in.sceneBounds, in.casterBounds, in.light, in.shadowSettings,
        s,        in.lift,      in.normals};
    const FloatImage vb = readTexture(pass.execute(b).visibility, 1);
    return visibilityDifference(va, vb, surface);
}

} // namespace fl
