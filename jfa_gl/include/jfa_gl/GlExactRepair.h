#pragma once
// The GL compute twin of jfa::repairNearest (jfa/ExactRepair.h;
// shaders/jfa_exact_repair.comp.glsl): the same walks, texel for texel.

#include <jfa/ExactRepair.h>

#include <gpu/Gl.h>
#include <gpu/Program.h>
#include <gpu/ShaderLibrary.h>

#include <cstdint>

namespace fl::jfa {

/// The GL twin of repairNearest (shaders/jfa_exact_repair.comp.glsl), texel for texel equal.
class GlExactRepair {
  public:
    explicit GlExactRepair(const gl::ShaderLibrary& shaders);
    /// Uploads the graph the next runs walk on (three storage buffers).
    void setGraph(const SiteGraph& graph);
    /// Writes the repaired `flooded` (RGBA32F, integer sites) into a texture this object owns
    /// and returns it; `flooded` itself is not changed. setGraph() first.
    const gl::Texture& run(const gl::Texture& flooded);

  private:
    gl::Program program_;
    gl::Buffer vertices_, offsets_, neighbours_;
    std::uint32_t vertexCount_ = 0;
    gl::Texture out_;
};

} // namespace fl::jfa
