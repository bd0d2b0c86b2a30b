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
      emptyVao_(gl::VertexArray::create()) {}

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
    bindShadowMap(program_, in.shadow);
    in.surfaces.positions().bind(program_, 2);
    if (penumbra_) {
        setDiskLightUniforms(program_, in.disk);
        program_.set("uPenumbraBoth", bothSides ? 1 : 0);
        program_.set("uSilhouetteThreshold", silhouetteThreshold(in.sceneBounds.radius()));
        glBindTextureUnit(3, penumbraMap->id());
        in.shadow.receivers->bind(program_, 4); // the packed cells' occluders
    }
    gl::drawFullscreenTriangle(program_, emptyVao_);
    for (GLuint unit : {0u, 1u, 2u, 3u, 4u}) glBindTextureUnit(unit, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return visibility_;
}

} // namespace fl
