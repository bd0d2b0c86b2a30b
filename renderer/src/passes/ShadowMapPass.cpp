#include <renderer/passes/ShadowMapDecode.h>
#include <renderer/passes/ShadowMapPass.h>

#include <array>
#include <stdexcept>

namespace fl {

namespace {

// Each measure alone and combined is in docs/history/tsm.md, "Stable TSM (issue 30 item 3)".
const std::array<TsmOption, 3> kTsmOptions{{
    {"--tsm-quantize", "quantize",
     "TSM: the trapezoid's parameters move in steps of this size (angle in radians, lines in "
     "light NDC, slopes, blend weight), extents rounded outwards; 0 = continuous (the paper's "
     "fit)",
     0.0, 0.5, &geom::TrapezoidParams::quantize},
    {"--tsm-snap", "snap",
     "TSM: the trapezoid's lines snap to multiples of this many shadow-map texels; 0 = off", 0.0,
     64.0, &geom::TrapezoidParams::snapTexels},
    {"--tsm-hysteresis", "hysteresis",
     "TSM: keep the previous frame's trapezoid while it holds the view and its focus line, "
     "resolution and direction stay within this band (refits fitted to the view scaled by 1 + "
     "this); 0 = refit every frame",
     0.0, 0.5, &geom::TrapezoidParams::hysteresis},
}};

// shaders/shadow_map_decode.glsl's uniforms (MapPositions::bind).
constexpr struct {
    gl::Uniform<glm::mat3> unwarp{"uMapUnwarp"};
    gl::Uniform<glm::mat4> inverseLightViewProj{"uMapInverseLightViewProj"};
} kMapDecode;

// shadow_lookup.glsl's and shadow_depth.*.glsl's uniforms (one home: ShadowMapPass.h).
const ShadowLookupUniforms& kShadowLookup = kShadowLookupUniforms;
const ShadowDepthUniforms& kShadowDepth = kShadowDepthUniforms;

bool sameParams(const geom::TrapezoidParams& a, const geom::TrapezoidParams& b) {
    return a.focusFraction == b.focusFraction && a.xi == b.xi && a.rLow == b.rLow &&
           a.rHigh == b.rHigh && a.wBand == b.wBand && a.quantize == b.quantize &&
           a.snapTexels == b.snapTexels && a.hysteresis == b.hysteresis && a.mapSize == b.mapSize;
}

} // namespace

std::span<const TsmOption> tsmOptions() {
    return kTsmOptions;
}

std::string_view providerName(ShadowMapProvider p) {
    return p == ShadowMapProvider::Tsm ? "tsm" : "uniform";
}

std::optional<ShadowMapProvider> parseProvider(std::string_view name) {
    if (name == "uniform") return ShadowMapProvider::Uniform;
    if (name == "tsm") return ShadowMapProvider::Tsm;
    return std::nullopt;
}

void MapPositions::bind(gl::BindScope& scope, const gl::Program& program,
                        gl::TextureUnit unit) const {
    scope.texture(unit, depth->id());
    program.set(kMapDecode.unwarp, unwarp);
    program.set(kMapDecode.inverseLightViewProj, inverseLightViewProj);
}

void MapPositions::bindUniforms(gl::Program& program) {
    program.bindUniforms({&kMapDecode.unwarp, &kMapDecode.inverseLightViewProj});
}

const gl::Texture& MapPositions::decoded() const {
    if (pass == nullptr) throw std::logic_error("MapPositions::decoded: no shadow map pass");
    return pass->decodedReceivers();
}

std::vector<glm::vec4> MapPositions::read() const {
    const int n = size();
    std::vector<float> raw(static_cast<std::size_t>(n) * static_cast<std::size_t>(n));
    glGetTextureImage(depth->id(), 0, GL_RED, GL_FLOAT,
                      static_cast<GLsizei>(raw.size() * sizeof(float)), raw.data());
    gl::throwIfErrors("shadow map receiver read-back");
    std::vector<glm::vec4> out(raw.size());
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * n + x;
            out[i] = shadowmap::receiverPosition(raw[i], {x, y}, n, unwarp, inverseLightViewProj);
        }
    return out;
}

ShadowMapPass::ShadowMapPass(const gl::ShaderLibrary& shaders)
    : program_(gl::Program::build(shaders, {{GL_VERTEX_SHADER, "shadow_depth.vert.glsl"},
                                            {GL_FRAGMENT_SHADER, "shadow_depth.frag.glsl"}})),
      decodeProgram_(
          gl::Program::build(shaders, {{GL_COMPUTE_SHADER, "shadow_map_positions.comp.glsl"}})) {
    const auto& u = kShadowDepth;
    program_.bindUniforms({&u.lightViewProj, &u.warp, &u.slopeBias, &u.constantBias});
    MapPositions::bindUniforms(decodeProgram_);
}

gl::Texture makeShadowDepthTexture(int size) {
    gl::Texture depth(GL_DEPTH_COMPONENT32F, size, size);
    // Hard shadows compare one texel: NEAREST keeps the test binary (LINEAR would give
    // hardware 2x2 PCF, a different method).
    depth.setSampling(GL_NEAREST, GL_NEAREST);
    glTextureParameteri(depth.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTextureParameteri(depth.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    return depth;
}

void ShadowMapPass::resize(int size) {
    if (depth_ && depth_.width() == size) return;
    history_.reset();
    gl::checkTextureSize("shadow map", size, size);
    depth_ = makeShadowDepthTexture(size);
    fbo_ = gl::Framebuffer::withTargets({}, &depth_, "shadow map");
    receiverDepth_ = gl::Texture(GL_R32F, size, size);
    receiversFbo_ =
        gl::Framebuffer::withTargets({&receiverDepth_}, &depth_, "shadow map with receivers");
    receiversWritten_ = false;
}

ShadowMapPass::Outputs ShadowMapPass::execute(const Inputs& in) {
    resize(in.settings.size);
    const glm::mat4 lightViewProj = in.light.viewProj();
    glm::mat4 warp(1.0f);
    const bool tsm = in.settings.provider == ShadowMapProvider::Tsm;
    if (tsm) {
        // Fit to the part of the eye frustum the scene occupies: receivers exist only there.
        const glm::mat4 eyeProj = geom::clampDepthRange(in.eyeProj, in.eyeView, in.sceneBounds);
        geom::TrapezoidParams params = in.settings.tsm;
        params.mapSize = in.settings.size;
        // Hysteresis reads the last fit only if it was made for this light and these settings.
        const bool continues = history_ && history_->lightViewProj == lightViewProj &&
                               sameParams(history_->params, params);
        fit_ = geom::fitTrapezoid(lightViewProj,
                                  glm::inverse(glm::dmat4(eyeProj) * glm::dmat4(in.eyeView)),
                                  params, continues ? &fit_ : nullptr);
        history_ = History{lightViewProj, params};
        warp = fit_.nt;
    } else {
        history_.reset();
    }

    const gl::Framebuffer& target = in.writeReceivers ? receiversFbo_ : fbo_;
    glBindFramebuffer(GL_FRAMEBUFFER, target.id());
    glViewport(0, 0, depth_.width(), depth_.height());
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    const float one = 1.0f;
    glClearNamedFramebufferfv(target.id(), GL_DEPTH, 0, &one);
    if (in.writeReceivers) {
        const float nothing[4] = {shadowmap::kNoReceiver, 0.0f, 0.0f, 0.0f};
        glClearNamedFramebufferfv(target.id(), GL_COLOR, 0, nothing);
    }
    // Both faces are drawn: the generated and loaded scenes contain open and double-sided
    // surfaces, and culling either face would let light through them.
    glDisable(GL_CULL_FACE);
    program_.set(kShadowDepth.lightViewProj, lightViewProj);
    program_.set(kShadowDepth.warp, warp);
    program_.set(kShadowDepth.slopeBias, in.settings.slopeBias);
    program_.set(kShadowDepth.constantBias, in.settings.constantBias);
    in.scene.draw(program_, GpuScene::Uniforms::Geometry);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    receiversWritten_ = in.writeReceivers;
    if (in.writeReceivers)
        positions_ = {&receiverDepth_, shadowmap::unwarp(warp),
                      shadowmap::inverseLightViewProj(lightViewProj), this};
    return {depth_,
            lightViewProj,
            warp,
            tsm ? &fit_ : nullptr,
            in.settings.provider,
            in.writeReceivers ? &positions_ : nullptr};
}

const gl::Texture& ShadowMapPass::decodedReceivers() const {
    if (!receiversWritten_)
        throw std::logic_error("decodedReceivers: the last shadow map wrote no receiver target");
    const int n = positions_.size();
    if (!decoded_ || decoded_.width() != n) decoded_ = gl::Texture(GL_RGBA32F, n, n);
    glUseProgram(decodeProgram_.id());
    gl::BindScope scope;
    positions_.bind(scope, decodeProgram_, gl::bind::MapReceiverDepth);
    scope.image(gl::bind::MapPositions, decoded_.id(), GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute(GLuint((n + 7) / 8), GLuint((n + 7) / 8), 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                    GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    scope.release();
    glUseProgram(0);
    return decoded_;
}

void bindShadowMap(gl::BindScope& scope, const gl::Program& program,
                   const ShadowMapPass::Outputs& shadow) {
    scope.texture(gl::bind::ShadowMap, shadow.depth.id());
    program.set(kShadowLookup.lightViewProj, shadow.lightViewProj);
    program.set(kShadowLookup.warp, shadow.warp);
    program.set(kShadowLookup.light, shadowLight(shadow.lightViewProj));
}

void bindShadowMapUniforms(gl::Program& program) {
    program.bindUniforms({&kShadowLookup.lightViewProj, &kShadowLookup.warp, &kShadowLookup.light});
}

glm::vec4 shadowLight(const glm::mat4& lightViewProj) {
    return glm::vec4(glm::inverse(glm::dmat4(lightViewProj)) * glm::dvec4(0.0, 0.0, 1.0, 0.0));
}

} // namespace fl
