// vsm: variance shadow maps (Donnelly & Lauritzen 2006; Filament's soft-shadow option). The
// shadow map's depths become moments (d, d^2) of the light-view depth, a separable box blur
// sized from the disk light's radius averages them, and each pixel takes Chebyshev's upper
// bound on its lit fraction, with light-bleeding reduction.
//
// Blur size: one filter for the whole map (VSM has no blocker search), --vsm-blur x R in world
// units at the scene centre's light depth, converted to map texels there. R (the penumbra of an
// occluder halfway to the light) is far wider than most penumbrae of a scene standing on its
// ground, and a wide blur erases thin and contact shadows (light leaks through the bound), so
// the defaults (blur 0.1, bleed 0.2) are small: chosen by measurement, the table of settings in
// docs/history/hard-shadows-and-frame-costs.md, "VSM (the method added through the table)". With
// TSM the blur runs over warped texels, so its world width varies across the map.
//
// The CPU reference of all three phases (moments, blur, lookup: parts of frame step 3) is in
// tests/vsm_gltest.cpp.

#include <renderer/methods/ShadowMethod.h>
#include <renderer/passes/Phases.h>

#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>
#include <cmath>

namespace fl {

namespace {

// Its options, declared here and bound to this struct's fields once (MethodOptions.h); its row
// in MethodTable.cpp takes them as kVsmOptions.
struct VsmOptions {
    float blur;
    float bleed;
};

constexpr MethodOption kVsmBlur{"--vsm-blur",
                                "blur",
                                OptionKind::Float,
                                "0.1",
                                "Blur radius as a multiple of the disk light's radius at the "
                                "scene's centre (0 = no blur)",
                                0.0,
                                8.0};
constexpr MethodOption kVsmBleed{"--vsm-bleed",
                                 "bleed",
                                 OptionKind::Float,
                                 "0.2",
                                 "Light-bleeding reduction: the share of Chebyshev's bound cut "
                                 "off as shadow",
                                 0.0,
                                 0.95};

constexpr OptionField kVsmFields[] = {field<&VsmOptions::blur>(kVsmBlur),
                                      field<&VsmOptions::bleed>(kVsmBleed)};

// The three VSM programs' uniforms: moments (vsm_moments), blur (vsm_blur), lookup (vsm_lookup).
constexpr struct {
    gl::Uniform<glm::mat4> invLightProj{"uInvLightProj"};
    gl::Uniform<int> radius{"uRadius"};
    gl::Uniform<glm::ivec2> direction{"uDirection"};
    gl::Uniform<glm::mat4> lightView{"uLightView"};
    gl::Uniform<float> bleed{"uBleed"};
    gl::Uniform<float> minVariance{"uMinVariance"};
} kVsmUniforms;

class Vsm final : public ShadowMethod {
  public:
    explicit Vsm(const gl::ShaderLibrary& shaders)
        : moments_(gl::Program::build(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                                {GL_FRAGMENT_SHADER, "vsm_moments.frag.glsl"}})),
          blur_(gl::Program::build(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                             {GL_FRAGMENT_SHADER, "vsm_blur.frag.glsl"}})),
          lookup_(gl::Program::build(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                               {GL_FRAGMENT_SHADER, "vsm_lookup.frag.glsl"}})),
          emptyVao_(gl::VertexArray::create()), rawDepth_(gl::makeRawTexelSampler()) {
        moments_.bindUniforms({&kVsmUniforms.invLightProj});
        blur_.bindUniforms({&kVsmUniforms.radius, &kVsmUniforms.direction});
        lookup_.bindUniforms(
            {&kVsmUniforms.lightView, &kVsmUniforms.bleed, &kVsmUniforms.minVariance});
        bindShadowMapUniforms(lookup_);
        SurfacePositions::bindUniforms(lookup_);
    } // the map's depths, not depth tests

    void resize(int width, int height) override {
        if (visibility_ && visibility_.width() == width && visibility_.height() == height) return;
        visibility_ = gl::Texture(GL_R32F, width, height);
        visibilityFbo_ = gl::Framebuffer::forColor(visibility_, "vsm visibility");
    }

    const gl::Texture& execute(const FrameInputs& in) override {
        resize(in.width(), in.height());
        const int size = in.shadow.depth.width();
        resizeMaps(size);
        glDisable(GL_DEPTH_TEST);

        // 1. Moments of the light-view depth per map texel.
        gl::TimedPass timedVsmMoments(in.timer, phase::kVsmMoments);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo_[0].id());
        glViewport(0, 0, size, size);
        moments_.set(kVsmUniforms.invLightProj, glm::inverse(in.lightVolume.proj));
        {
            gl::BindScope scope;
            scope.texture(gl::bind::VsmDepth, in.shadow.depth.id())
                .sampler(gl::bind::VsmDepth, rawDepth_.id());
            gl::drawFullscreenTriangle(moments_, emptyVao_);
        }
        timedVsmMoments.wrote(gl::textureBytes(maps_[0]));
        timedVsmMoments.end();

        // 2. Separable box blur: map 0 -> 1 horizontally, 1 -> 0 vertically.
        gl::TimedPass timedVsmBlur(in.timer, phase::kVsmBlur);
        const int radius = blurRadius(in);
        if (radius > 0) {
            blur_.set(kVsmUniforms.radius, radius);
            gl::BindScope scope;
            for (int pass = 0; pass < 2; ++pass) {
                glBindFramebuffer(GL_FRAMEBUFFER, fbo_[1 - pass].id());
                blur_.set(kVsmUniforms.direction, pass == 0 ? glm::ivec2(1, 0) : glm::ivec2(0, 1));
                scope.texture(gl::bind::VsmBlurIn, maps_[pass].id());
                gl::drawFullscreenTriangle(blur_, emptyVao_);
            }
        }
        if (radius > 0) timedVsmBlur.wrote(gl::textureBytes(maps_[0]) + gl::textureBytes(maps_[1]));
        timedVsmBlur.end();

        // 3. Chebyshev's bound per pixel of the frame's surfaces.
        gl::TimedPass timedVsmLookup(in.timer, phase::kVsmLookup);
        glBindFramebuffer(GL_FRAMEBUFFER, visibilityFbo_.id());
        glViewport(0, 0, in.width(), in.height());
        gl::BindScope scope;
        bindShadowMap(scope, lookup_, in.shadow);
        lookup_.set(kVsmUniforms.lightView, in.lightVolume.view);
        lookup_.set(kVsmUniforms.bleed, in.options<VsmOptions>().bleed);
        lookup_.set(kVsmUniforms.minVariance, kMinVariance);
        in.surfaces.positions().bind(scope, lookup_, gl::bind::SurfacesDepth);
        in.surfaces.bindLookup(scope);
        scope.texture(gl::bind::VsmMoments, maps_[0].id());
        gl::drawFullscreenTriangle(lookup_, emptyVao_);
        scope.release();
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        timedVsmLookup.wrote(gl::textureBytes(visibility_));
        timedVsmLookup.end();
        return visibility_;
    }

  private:
    // Variance floor, relative to the receiver's depth: keeps a receiver from shadowing itself
    // where the blur mixes depths of its own sloped surface (VSM's "minimum variance").
    static constexpr float kMinVariance = 2e-3f;

    void resizeMaps(int size) {
        if (maps_[0] && maps_[0].width() == size) return;
        for (int i = 0; i < 2; ++i) {
            maps_[i] = gl::Texture(GL_RG32F, size, size);
            maps_[i].setSampling(GL_LINEAR, GL_LINEAR); // bilinear moments, edges clamped
            fbo_[i] = gl::Framebuffer::forColor(maps_[i], "vsm moments");
        }
    }

    // The blur radius in map texels (see the top of the file); 0 = no blur.
    static int blurRadius(const FrameInputs& in) {
        const float scale = in.options<VsmOptions>().blur;
        const glm::mat4& proj = in.lightVolume.proj;
        const float centreDepth =
            std::max(-(in.lightVolume.view * glm::vec4(in.sceneBounds.center(), 1.0f)).z, 1e-6f);
        // World width the map covers at the centre's depth: 2 d / P00 (perspective), 2 / P00
        // (orthographic, where P33 = 1).
        const bool ortho = proj[3][3] == 1.0f;
        const float mapWidth = (ortho ? 2.0f : 2.0f * centreDepth) / std::max(proj[0][0], 1e-9f);
        const float texels =
            scale * in.disk.radius / mapWidth * static_cast<float>(in.shadow.depth.width());
        return std::clamp(static_cast<int>(std::lround(texels)), 0, kMaxBlurRadius);
    }
    static constexpr int kMaxBlurRadius = 64; // 129 taps per direction

    gl::Program moments_, blur_, lookup_;
    gl::VertexArray emptyVao_;
    gl::Handle<gl::detail::SamplerDeleter> rawDepth_;
    gl::Texture maps_[2];
    gl::Framebuffer fbo_[2];
    gl::Texture visibility_;
    gl::Framebuffer visibilityFbo_;
};

} // namespace

extern constexpr MethodOptionSet kVsmOptions = optionSet<VsmOptions>(kVsmFields);

std::unique_ptr<ShadowMethod> makeVsm(const gl::ShaderLibrary& shaders) {
    return std::make_unique<Vsm>(shaders);
}

} // namespace fl
