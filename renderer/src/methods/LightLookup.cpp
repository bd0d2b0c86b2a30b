#include "LightLookup.h"

#include <renderer/soft/OccluderEdge.h>
#include <renderer/soft/PenumbraCriterion.h>

#include <stdexcept>

namespace fl {

LightLookup::LightLookup(const gl::ShaderLibrary& shaders, bool penumbra)
    : penumbra_(penumbra),
      program_(gl::Program::build(shaders,
                                  {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                   {GL_FRAGMENT_SHADER, "light_visibility.frag.glsl"}},
                                  penumbra ? std::vector<std::string>{"SOFT_PENUMBRA_MAP 1"}
                                           : std::vector<std::string>{})),
      emptyVao_(gl::VertexArray::create()) {
    // Its own program, so that outer's is the thesis' lookup instruction for instruction (the
    // same picture and cost as before the umbra side).
    if (penumbra)
        bothProgram_ = gl::Program::build(shaders,
                                          {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                           {GL_FRAGMENT_SHADER, "light_visibility.frag.glsl"}},
                                          {"SOFT_PENUMBRA_MAP 1", "SOFT_PENUMBRA_BOTH 1"});
}

void LightLookup::resize(int width, int height) {
    if (visibility_ && visibility_.width() == width && visibility_.height() == height) return;
    visibility_ = gl::Texture(GL_R32F, width, height);
    fbo_ = gl::Framebuffer::forColor(visibility_, "light-space lookup");
}

const gl::Texture& LightLookup::execute(const FrameInputs& in, const gl::Texture* penumbraMap,
                                        bool bothSides) {
    if (penumbra_ && penumbraMap == nullptr)
        throw std::logic_error("LightLookup: the penumbra lookup needs a penumbra map");
    resize(in.width(), in.height());
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, in.width(), in.height());
    glDisable(GL_DEPTH_TEST);
    const gl::Program& program = penumbra_ && bothSides ? bothProgram_ : program_;
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
        program.set("uSilhouetteThreshold", silhouetteThreshold(in.sceneBounds.radius()));
        // surfacePlane (hard-shadowed points)
        scope.texture(gl::bind::PenumbraNormals, in.surfaces.normals.id());
    }
    gl::drawFullscreenTriangle(program, emptyVao_);
    scope.release();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return visibility_;
}

} // namespace fl
