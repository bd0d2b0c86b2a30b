#include <jfa_gl/GlJfa3d.h>

#include <gpu/BindScope.h>

#include <base/Text.h>

#include <stdexcept>
#include <string>

namespace fl::jfa {

namespace {

// The pass's work group is 4 x 4 x 4 (jfa3d_pass.comp.glsl).
constexpr int kGroup3d = 4;

GLuint groups3d(int n) {
    return GLuint((n + kGroup3d - 1) / kGroup3d);
}

// Uploads or reads one slice at a time: glGetTextureImage's byte count is a GLsizei, which a
// whole volume of more than 2^29 voxels would overflow.
void uploadSlices(const gl::Texture3D& texture, const SiteGrid3& grid) {
    const Extent3 e = grid.extent;
    const std::size_t slice = std::size_t(e.width) * std::size_t(e.height);
    for (int z = 0; z < e.depth; ++z) {
        glTextureSubImage3D(texture.id(), 0, 0, 0, z, e.width, e.height, 1, GL_RED_INTEGER, GL_INT,
                            grid.cells.data() + std::size_t(z) * slice);
    }
}

void checkPlan(const Plan& plan, Flood3dShape shape, Extent3 e) {
    if (plan.stages().size() != 1 || plan.stages().front().untilUnchanged) {
        throw std::invalid_argument(fl::cat("the GL 3D kernel runs single-stage plans of fixed "
                                            "steps only, not ",
                                            plan.describe()));
    }
    if (shape == Flood3dShape::Slices && (plan.width() != e.width || plan.height() != e.height)) {
        throw std::invalid_argument(fl::cat("slice-by-slice flooding of a ", e.width, "x", e.height,
                                            "x", e.depth, " grid needs a plan for ", e.width, "x",
                                            e.height, ", got ", plan.describe()));
    }
}

} // namespace

void checkGlExtent3d(Extent3 e) {
    (void)plan3d("jfa", e); // Jfa3d's own limits, with its message
    const int limit = gl::max3dTextureSize();
    if (e.width > limit || e.height > limit || e.depth > limit) {
        throw std::invalid_argument(fl::cat("3D grid ", e.width, "x", e.height, "x", e.depth,
                                            " is larger than this driver's largest 3D texture, ",
                                            limit, " per side (GL_MAX_3D_TEXTURE_SIZE, ",
                                            gl::rendererName(), ")"));
    }
}

namespace {
// jfa3d_pass.comp.glsl's uniforms.
constexpr struct {
    gl::Uniform<glm::ivec3> size{"uSize"};
    gl::Uniform<int> step{"uStep"};
    gl::Uniform<int> slices{"uSlices"};
} kJfa3d;
} // namespace

GlJfa3d::GlJfa3d(const gl::ShaderLibrary& shaders)
    : program_(gl::Program::build(shaders, {{GL_COMPUTE_SHADER, "jfa3d_pass.comp.glsl"}})) {
    program_.bindUniforms({&kJfa3d.size, &kJfa3d.step, &kJfa3d.slices});
}

void GlJfa3d::upload(const std::vector<Site3>& sites, const SiteGrid3& seeds) {
    const Extent3 e = seeds.extent;
    checkGlExtent3d(e);
    for (std::int32_t c : seeds.cells) {
        if (c != kNoSite && (c < 0 || std::size_t(c) >= sites.size()))
            throw std::invalid_argument("GlJfa3d: a seed names a site outside the site list");
    }
    std::vector<GLint> packed;
    packed.reserve(sites.size() * 4 + 4);
    for (const Site3& s : sites) packed.insert(packed.end(), {s.x, s.y, s.z, s.id});
    if (packed.empty()) packed.resize(4); // a buffer may not be empty; no cell names it
    sites_ = gl::Buffer(GLsizeiptr(packed.size() * sizeof(GLint)), packed.data());
    if (!(extent_ == e)) {
        seeds_ = gl::Texture3D(GL_R32I, e.width, e.height, e.depth);
        for (gl::Texture3D& t : ping_) t = gl::Texture3D(GL_R32I, e.width, e.height, e.depth);
        extent_ = e;
    }
    uploadSlices(seeds_, seeds);
    result_ = &seeds_;
    gl::throwIfErrors("3D flood upload");
}

void GlJfa3d::run(const Plan& plan, Flood3dShape shape) {
    if (!result_) throw std::logic_error("GlJfa3d::run before upload");
    checkPlan(plan, shape, extent_);
    glUseProgram(program_.id());
    program_.set(kJfa3d.slices, shape == Flood3dShape::Slices ? 1 : 0);
    program_.set(kJfa3d.size, glm::ivec3(extent_.width, extent_.height, extent_.depth));
    gl::BindScope scope;
    scope.storage(gl::bind::Flood3dSites, sites_.id());
    const gl::Texture3D* src = &seeds_;
    int next = 0;
    for (int step : plan.stages().front().steps) {
        const gl::Texture3D* dst = &ping_[next];
        next ^= 1;
        program_.set(kJfa3d.step, step);
        scope.image(gl::bind::Flood3dIn, src->id(), GL_READ_ONLY, GL_R32I, 0, GL_TRUE)
            .image(gl::bind::Flood3dOut, dst->id(), GL_WRITE_ONLY, GL_R32I, 0, GL_TRUE);
        glDispatchCompute(groups3d(extent_.width), groups3d(extent_.height),
                          groups3d(extent_.depth));
        // The next pass reads what this one stored.
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        src = dst;
    }
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT); // for read()
    scope.release();
    glUseProgram(0);
    result_ = src;
    gl::throwIfErrors("3D flood passes");
}

SiteGrid3 GlJfa3d::read() const {
    if (!result_) throw std::logic_error("GlJfa3d::read before upload");
    SiteGrid3 grid(extent_);
    const std::size_t slice = std::size_t(extent_.width) * std::size_t(extent_.height);
    for (int z = 0; z < extent_.depth; ++z) {
        glGetTextureSubImage(result_->id(), 0, 0, 0, z, extent_.width, extent_.height, 1,
                             GL_RED_INTEGER, GL_INT, GLsizei(slice * sizeof(std::int32_t)),
                             grid.cells.data() + std::size_t(z) * slice);
    }
    gl::throwIfErrors("3D flood read-back");
    return grid;
}

SiteGrid3 glFloodVariant3d(GlJfa3d& kernel, const Flood3dVariant& variant,
                           const std::vector<Site3>& sites, Extent3 extent) {
    const Plan plan = variantPlan(variant, extent);
    kernel.upload(sites, startGrid3d(sites, extent, variant.shape));
    kernel.run(plan, variant.shape);
    return kernel.read();
}

} // namespace fl::jfa
