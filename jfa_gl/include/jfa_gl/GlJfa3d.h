#pragma once
// The 3D floods of jfa/Jfa3d.h on the GPU (thesis §4.6): one compute kernel on an r32i image3D
// ping-pong pair (shaders/jfa3d_pass.comp.glsl) for the 3D passes (27 reads a voxel) and the
// slice-by-slice variant (9 reads within the voxel's own slice, every slice in one dispatch).
// Cells are indices into the site list as on the CPU and the same integer rule picks the site,
// so a run equals its CPU twin voxel for voxel (flood3d, floodSliceBySlice; tests/
// jfa3d_gltest.cpp). Needs a current GL 4.5 context.

#include <jfa/Jfa3d.h>
#include <jfa/Plan.h>

#include <gpu/Gl.h>
#include <gpu/Program.h>
#include <gpu/ShaderLibrary.h>

#include <vector>

namespace fl::jfa {

/// Throws std::invalid_argument naming the limit when `extent` does not fit this context's 3D
/// textures (GL_MAX_3D_TEXTURE_SIZE per side) or Jfa3d's limits (kMaxGridExtent3d, kMaxVoxels3d).
void checkGlExtent3d(Extent3 extent);

/// The GL kernel: upload once, run plans on the uploaded seeds, read the result back.
class GlJfa3d {
  public:
    /// Builds the pass program from `shaders`.
    explicit GlJfa3d(const gl::ShaderLibrary& shaders);

    /// Uploads the site list and the grid the flood starts from (startGrid3d: seedGrid3d for a
    /// Volume run, projectedSeeds3d for a Slices run). Throws std::invalid_argument for
    /// an extent checkGlExtent3d refuses or a cell that names no site.
    void upload(const std::vector<Site3>& sites, const SiteGrid3& seeds);
    /// Runs every pass of `plan` on the uploaded seeds (left unmodified), without waiting for the
    /// GPU. Volume: a plan3d() plan; Slices: a plan for the W x H slice. Either single-stage and
    /// not "until unchanged"; std::invalid_argument otherwise.
    void run(const Plan& plan, Flood3dShape shape);
    /// The last run's result (the seeds before any run).
    [[nodiscard]] SiteGrid3 read() const;

  private:
    gl::Program program_;
    Extent3 extent_;
    gl::Buffer sites_;
    gl::Texture3D seeds_, ping_[2];
    const gl::Texture3D* result_ = nullptr;
};

/// The GL twin of floodVariant3d: start grid, upload, every pass, read back.
SiteGrid3 glFloodVariant3d(GlJfa3d& kernel, const Flood3dVariant& variant,
                           const std::vector<Site3>& sites, Extent3 extent);

} // namespace fl::jfa
