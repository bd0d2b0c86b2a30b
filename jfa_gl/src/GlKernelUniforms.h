#pragma once
// The kernel pass programs' uniforms (jfa_pass.{frag,comp}.glsl): GlKernel.cpp builds the
// full-grid pass programs and sets these on every dispatch, GlBand.cpp builds the band's.
// Private to floodlight_jfa_gl.

#include <gpu/Program.h>

namespace fl::jfa::detail {

struct KernelPassUniforms {
    gl::Uniform<glm::ivec2> size{"uSize"};
    gl::Uniform<glm::ivec2> srcSize{"uSrcSize"};
    gl::Uniform<int> step{"uStep"};
    gl::Uniform<int> scale{"uScale"};
    gl::Uniform<int> mode{"uMode"};
    gl::Uniform<int> countChanges{"uCountChanges"};
    // The band's pass programs only (JFA_BAND, compute).
    gl::Uniform<int> tile{"uTile"};
    gl::Uniform<int> front{"uFront"};
    gl::Uniform<int> tilesX{"uTilesX"};
};
inline constexpr KernelPassUniforms kKernelPass;

/// Binds a pass program's uniforms, with `band` the band's too.
inline void bindKernelPassUniforms(gl::Program& program, bool band) {
    const KernelPassUniforms& u = kKernelPass;
    program.bindUniforms({&u.size, &u.srcSize, &u.step, &u.scale, &u.mode, &u.countChanges});
    if (band) program.bindUniforms({&u.tile, &u.front, &u.tilesX});
}

} // namespace fl::jfa::detail
