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

class GlFloodKernel {
  public:
    /// Called after every pass with its index, the pass and the texture it wrote.
    using PassCallback = std::function<void(int, const Pass&, const gl::Texture&)>;

    /// Builds the kernel programs with the criterion's GLSL file (Criterion::glslFile) linked in.
    GlFloodKernel(const ShaderLibrary& shaders, const std::string& criterionFile,
                  GlKernelKind kind);

    /// Runs `plan` on full-resolution `seeds` (plan.width() x plan.height(), not modified);
    /// returns the full-resolution result, owned by the kernel until the next run. If `timer`
    /// is given, each pass is timed as "jfa step K" (and "downsample").
    template <Criterion C>
    const gl::Texture& run(const Plan& plan, const gl::Texture& seeds, const C& criterion,
                           PassTimer* timer = nullptr, const PassCallback& callback = {}) {
        for (const gl::Program* p : {&passProgram_, &expandProgram_})
            setCriterionUniforms(*p, criterion);
        return runPlan(plan, seeds, timer, callback);
    }

    /// Convenience for tests and tools: upload, run, read back.
    template <Criterion C>
    Grid run(const Plan& plan, const Grid& seeds, const C& criterion) {
        const gl::Texture in = uploadGrid(seeds);
        return readGrid(run(plan, in, criterion));
    }

    /// Passes the last run actually executed ("until unchanged" stages may stop early).
    [[nodiscard]] int passesRun() const { return passesRun_; }
    [[nodiscard]] GlKernelKind kind() const { return kind_; }

  private:
    const gl::Texture& runPlan(const Plan& plan, const gl::Texture& seeds, PassTimer* timer,
                               const PassCallback& callback);
    // One dispatch: mode 0 pass, 1 expand + pass, 2 downsample.
    void dispatch(const gl::Texture& src, const gl::Texture& seeds, const gl::Texture& dst,
                  int mode, int step, int scale, bool countChanges);
    const gl::Texture& otherTexture(int width, int height, const gl::Texture* current);

    GlKernelKind kind_;
    gl::Program passProgram_;   // passes and downsampling
    gl::Program expandProgram_; // the pass that expands the half-resolution stage (JFA_EXPAND)
    gl::VertexArray emptyVao_;
    gl::Buffer changedCounter_;
    struct Pair {
        gl::Texture tex[2];
        gl::Framebuffer fbo[2];
    };
    std::map<std::pair<int, int>, Pair> pairs_;
    int passesRun_ = 0;
};

} // namespace fl::jfa
