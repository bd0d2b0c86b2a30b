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
    bindShadowMap(program, in.shadow);
    in.surfaces.positions().bind(program, 2);
    if (penumbra_) {
        setDiskLightUniforms(program, in.disk);
        glBindTextureUnit(3, penumbraMap->id());
        in.shadow.receivers->bind(program, 4); // the packed cells' occluders
    }
    if (penumbra_ && bothSides) {
        program.set("uSilhouetteThreshold", silhouetteThreshold(in.sceneBounds.radius()));
        glBindTextureUnit(5, in.surfaces.normals.id()); // surfacePlane (hard-shadowed points)
    }
    gl::drawFullscreenTriangle(program, emptyVao_);
    for (GLuint unit : {0u, 1u, 2u, 3u, 4u, 5u}) glBindTextureUnit(unit, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return visibility_;
}

} // namespace fl
