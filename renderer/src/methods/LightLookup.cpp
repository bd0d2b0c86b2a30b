#include "LightLookup.h"

#include <renderer/soft/OccluderEdge.h>
#include <renderer/soft/PenumbraCriterion.h>

#include <stdexcept>

namespace fl {

namespace {

// light_visibility.frag.glsl's own uniform (--penumbra both: soft_penumbra.glsl).
constexpr gl::Uniform<float> kLookupSilhouetteThreshold{"uSilhouetteThreshold"};

// Binds what draw() sets on a lookup program: the shadow map and the eye's surfaces; with the
// penumbra map the disk light and the map's receivers; with `both` the silhouette threshold.
void bindLookupUniforms(gl::Program& program, bool penumbra, bool both) {
    bindShadowMapUniforms(program);
    SurfacePositions::bindUniforms(program);
    if (penumbra) {
        bindDiskLightUniforms(program);
        MapPositions::bindUniforms(program);
    }
    if (both) program.bindUniforms({&kLookupSilhouetteThreshold});
}

} // namespace

LightLookup::LightLookup(const gl::ShaderLibrary& shaders, bool penumbra)
    : penumbra_(penumbra),
      program_(gl::Program::build(shaders,
                                  {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                   {GL_FRAGMENT_SHADER, "light_visibility.frag.glsl"}},
                                  penumbra ? std::vector<std::string>{"SOFT_PENUMBRA_MAP 1"}
                                           : std::vector<std::string>{})),
      emptyVao_(gl::VertexArray::create()) {
    bindLookupUniforms(program_, penumbra, false);
    // Its own program, so that outer's is the thesis' lookup instruction for instruction (the
    // same picture and cost as before the umbra side).
    if (penumbra) {
        bothProgram_ = gl::Program::build(shaders,
                                          {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                           {GL_FRAGMENT_SHADER, "light_visibility.frag.glsl"}},
                                          {"SOFT_PENUMBRA_MAP 1", "SOFT_PENUMBRA_BOTH 1"});
        edgesProgram_ =
            gl::Program::build(shaders,
                               {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                {GL_FRAGMENT_SHADER, "light_visibility.frag.glsl"}},
                               {"SOFT_PENUMBRA_MAP 1", "SOFT_PENUMBRA_BOTH 1", "PENUMBRA_EDGES 1"});
        bindLookupUniforms(bothProgram_, true, true);
        bindLookupUniforms(edgesProgram_, true, true);
    }
}

void LightLookup::resize(int width, int height) {
    if (visibility_ && visibility_.width() == width && visibility_.height() == height) return;
    visibility_ = gl::Texture(GL_R32F, width, height);
    if (penumbra_) {
        mask_ = gl::Texture(GL_DEPTH_COMPONENT16, width, height);
        fbo_ = gl::Framebuffer::withTargets({&visibility_}, &mask_, "light-space lookup");
    } else {
        fbo_ = gl::Framebuffer::forColor(visibility_, "light-space lookup");
    }
}

void LightLookup::draw(const FrameInputs& in, const gl::Program& program,
                       const gl::Texture* penumbraMap, bool bothSides) const {
    gl::BindScope scope;
    bindShadowMap(scope, program, in.shadow);
    in.surfaces.positions().bind(scope, program, gl::bind::PenumbraSurfacesDepth);
    in.surfaces.bindLookup(scope);
    if (penumbra_) {
        setDiskLightUniforms(program, in.disk);
        scope.texture(gl::bind::PenumbraMap, penumbraMap->id());
        // the packed cells' occluders
        in.shadow.receivers->bind(scope, program, gl::bind::PenumbraReceivers);
    }
    if (penumbra_ && bothSides) {
        program.set(kLookupSilhouetteThreshold, silhouetteThreshold(in.sceneBounds.radius()));
        // surfacePlane (hard-shadowed points)
        scope.texture(gl::bind::PenumbraNormals, in.surfaces.normals.id());
    }
    gl::drawFullscreenTriangle(program, emptyVao_);
    scope.release();
}

const gl::Texture& LightLookup::execute(const FrameInputs& in, const gl::Texture* penumbraMap,
                                        bool bothSides) {
    if (penumbra_ && penumbraMap == nullptr)
        throw std::logic_error("LightLookup: the penumbra lookup needs a penumbra map");
    resize(in.width(), in.height());
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, in.width(), in.height());
    const bool both = penumbra_ && bothSides;
    const auto drawWith = [&](const gl::Program& program) { draw(in, program, penumbraMap, both); };
    // --penumbra both: the first pass marks the points the edges recompute; the second runs
    // only there (soft_penumbra.glsl).
    if (both) {
        gl::drawMarkedThenRefined(drawWith, bothProgram_,
                                  in.disk.radius > 0.0f ? &edgesProgram_ : nullptr);
    } else {
        glDisable(GL_DEPTH_TEST);
        drawWith(program_);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return visibility_;
}

} // namespace fl
