#pragma once
// The per-pixel light-space lookup shared by hard shadows and JFA-L / flood-L: each eye pixel's
// surface point (step 2) is looked up in the shadow map, or in the flooded penumbra map
// (shaders/light_visibility.frag.glsl). Private to renderer/src/methods.

#include <gpu/Gl.h>
#include <gpu/Program.h>
#include <gpu/ShaderLibrary.h>
#include <renderer/methods/ShadowMethod.h>

namespace fl {

class LightLookup {
  public:
    /// `penumbra`: look up a penumbra map (SOFT_PENUMBRA_MAP) instead of the hard test.
    LightLookup(const gl::ShaderLibrary& shaders, bool penumbra);
    void resize(int width, int height);
    /// Visibility per pixel; `penumbraMap` is required when built with `penumbra`; `bothSides`:
    /// hard-shadowed points take the map's occluder too (--penumbra both).
    const gl::Texture& execute(const FrameInputs& in, const gl::Texture* penumbraMap = nullptr,
                               bool bothSides = false);

  private:
    /// One fullscreen pass of `program` with every input it reads bound.
    void draw(const FrameInputs& in, const gl::Program& program, const gl::Texture* penumbraMap,
              bool bothSides) const;

    bool penumbra_;
    gl::Program program_;
    gl::Program bothProgram_; // with `penumbra`: --penumbra both (SOFT_PENUMBRA_BOTH)
    // --penumbra both's second pass (PENUMBRA_EDGES): the occluders' edges where the first
    // marked mask_ (soft_penumbra.glsl).
    gl::Program edgesProgram_;
    gl::VertexArray emptyVao_;
    gl::Texture visibility_, mask_;
    gl::Framebuffer fbo_;
};

} // namespace fl
