#pragma once
// The GL kernels: a Plan run on the GPU with a ping-pong pair of RGBA32F textures per grid size,
// either as fragment passes (full-screen triangle into an FBO) or as compute passes (imageStore).
// Semantics are exactly those of jfa/CpuKernel.h — downsampling to the half-resolution stage,
// candidate reads, expansion, "until unchanged" — and tests compare the two texel for texel.

#include <jfa/Grid.h>
#include <jfa/NearestSite.h>
#include <jfa/Plan.h>

#include <gpu/Gl.h>
#include <gpu/PassTimer.h>
#include <gpu/Program.h>

#include <functional>
#include <map>
#include <string>
#include <utility>

namespace fl::jfa {

enum class GlKernelKind { Fragment, Compute };
/// "fragment" or "compute".
const char* kernelName(GlKernelKind kind);

/// Sets a criterion's uniforms on a kernel program; one overload per criterion.
void setCriterionUniforms(const gl::Program& program, const NearestSite& criterion);

/// Uploads a grid as an RGBA32F texture (row y of the grid = texel row y).
gl::Texture uploadGrid(const Grid& grid);
/// Reads an RGBA32F texture back into a grid.
Grid readGrid(const gl::Texture& texture);

/// What one dispatch of the kernel programs does: the jfa_pass shaders' uMode, so the values are
/// fixed by the GLSL.
enum class GlDispatch : int {
    Pass = 0,           // one pass of jump length uStep (a JFA step, not a frame step)
    ExpandThenPass = 1, // the first pass of the full-resolution stage (on expandProgram_)
    Downsample = 2,     // full-resolution seeds to the half-resolution stage
};

/// The criterion-independent part of a GL kernel: programs, ping-pong textures, dispatches and
/// the plan loop. Use GlFloodKernel<C>, which ties the programs to a criterion type.
class GlFloodKernelBase {
  public:
    /// Called after every pass with its index, the pass and the texture it wrote.
    using PassCallback = std::function<void(int, const Pass&, const gl::Texture&)>;

    /// Passes the last run actually executed ("until unchanged" stages may stop early).
    [[nodiscard]] int passesRun() const { return passesRun_; }
    [[nodiscard]] GlKernelKind kind() const { return kind_; }

  protected:
    /// Builds the kernel programs with `criterionFile` (a criterion's glslFile) linked in.
    GlFloodKernelBase(const gl::ShaderLibrary& shaders, const std::string& criterionFile,
                      GlKernelKind kind);

    /// The plan loop, once the criterion's uniforms are set on both programs.
    const gl::Texture& runPlan(const Plan& plan, const gl::Texture& seeds, gl::PassTimer* timer,
                               const PassCallback& callback);

    gl::Program passProgram_;   // passes and downsampling
    gl::Program expandProgram_; // the pass that expands the half-resolution stage (JFA_EXPAND)

  private:
    void dispatch(const gl::Texture& src, const gl::Texture& seeds, const gl::Texture& dst,
                  GlDispatch what, int step, int scale, bool countChanges);
    const gl::Texture& otherTexture(int width, int height, const gl::Texture* current);

    GlKernelKind kind_;
    gl::VertexArray emptyVao_;
    gl::Buffer changedCounter_;
    struct Pair {
        gl::Texture tex[2];
        gl::Framebuffer fbo[2];
    };
    std::map<std::pair<int, int>, Pair> pairs_;
    int passesRun_ = 0;
};

/// A GL kernel for criterion C. Its programs link C::glslFile when it is built, and run() takes
/// a C only, so a kernel cannot run a criterion whose GLSL it was not built with: that does not
/// compile.
template <Criterion C>
class GlFloodKernel : public GlFloodKernelBase {
    static_assert(C::glslFile != nullptr, "a GL kernel needs a criterion with a GLSL file");

  public:
    /// Builds the kernel programs with C::glslFile linked in.
    GlFloodKernel(const gl::ShaderLibrary& shaders, GlKernelKind kind)
        : GlFloodKernelBase(shaders, C::glslFile, kind) {}

    /// Runs `plan` on full-resolution `seeds` (plan.width() x plan.height(), not modified);
    /// returns the full-resolution result, owned by the kernel until the next run. If `timer`
    /// is given, each pass is timed as "jfa step K", K the jump length (and "downsample").
    const gl::Texture& run(const Plan& plan, const gl::Texture& seeds, const C& criterion,
                           gl::PassTimer* timer = nullptr, const PassCallback& callback = {}) {
        for (const gl::Program* p : {&passProgram_, &expandProgram_})
            setCriterionUniforms(*p, criterion);
        return runPlan(plan, seeds, timer, callback);
    }

    /// Convenience for tests and tools: upload, run, read back.
    Grid run(const Plan& plan, const Grid& seeds, const C& criterion) {
        const gl::Texture in = uploadGrid(seeds);
        return readGrid(run(plan, in, criterion));
    }
};

} // namespace fl::jfa
