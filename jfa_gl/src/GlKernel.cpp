#include <jfa_gl/GlKernel.h>

#include "GlKernelUniforms.h"

#include <stdexcept>
#include <string>

namespace fl::jfa {

static_assert(sizeof(Cell) == 4 * sizeof(float), "a Cell must be one RGBA32F texel");

namespace {
// Integer-site distances are squared in 32-bit ints on the GPU: 2 * 16383² < 2^31.
constexpr int kMaxGlGridExtent = 16384;
} // namespace

const char* kernelName(GlKernelKind kind) {
    return kind == GlKernelKind::Fragment ? "fragment" : "compute";
}

namespace {
constexpr gl::Uniform<int> kJfaIntegerSites{"uJfaIntegerSites"}; // jfa_nearest_site.glsl
} // namespace

// NearestSite binds no textures: the scope stays empty.
void setCriterionUniforms(gl::BindScope& /*scope*/, const gl::Program& program,
                          const NearestSite& criterion) {
    program.set(kJfaIntegerSites, criterion.integerSites ? 1 : 0);
}

void bindCriterionUniforms(gl::Program& program, const NearestSite* /*criterion*/) {
    program.bindUniforms({&kJfaIntegerSites});
}

gl::Texture uploadGrid(const Grid& grid) {
    gl::Texture t(GL_RGBA32F, grid.width, grid.height);
    glTextureSubImage2D(t.id(), 0, 0, 0, grid.width, grid.height, GL_RGBA, GL_FLOAT,
                        grid.cells.data());
    return t;
}

Grid readGrid(const gl::Texture& texture) {
    Grid g(texture.width(), texture.height());
    glGetTextureImage(texture.id(), 0, GL_RGBA, GL_FLOAT,
                      static_cast<GLsizei>(g.cells.size() * sizeof(Cell)), g.cells.data());
    gl::throwIfErrors("jfa grid read-back");
    return g;
}

Grid readPackedGrid(const gl::Texture& packed, const Grid& source,
                    std::size_t (*seedIndex)(float stored)) {
    std::vector<float> stored(static_cast<std::size_t>(packed.width()) *
                              static_cast<std::size_t>(packed.height()));
    glGetTextureImage(packed.id(), 0, GL_RED, GL_FLOAT,
                      static_cast<GLsizei>(stored.size() * sizeof(float)), stored.data());
    gl::throwIfErrors("jfa packed grid read-back");
    Grid out(packed.width(), packed.height(), kEmptyCell);
    for (std::size_t i = 0; i < stored.size(); ++i) {
        if (stored[i] == 0.0f) continue;
        const std::size_t seed = seedIndex(stored[i]);
        if (seed >= source.cells.size())
            throw std::logic_error("readPackedGrid: a seed index beyond the source grid");
        const Cell& o = source.cells[seed];
        out.cells[i] = {o.x, o.y, o.z, stored[i]};
    }
    return out;
}

namespace {

gl::Program buildKernel(const gl::ShaderLibrary& shaders, const std::string& criterionFile,
                        GlKernelKind kind, bool expand, bool keyed, bool packed) {
    std::vector<std::string> defines{detail::cellFormatDefine(packed)};
    if (expand) defines.emplace_back("JFA_EXPAND");
    if (keyed) defines.emplace_back("JFA_KEYED");
    if (kind == GlKernelKind::Fragment)
        return gl::Program::build(shaders,
                                  {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                   {GL_FRAGMENT_SHADER, "jfa_pass.frag.glsl"},
                                   {GL_FRAGMENT_SHADER, criterionFile}},
                                  defines);
    return gl::Program::build(
        shaders, {{GL_COMPUTE_SHADER, "jfa_pass.comp.glsl"}, {GL_COMPUTE_SHADER, criterionFile}},
        defines);
}

} // namespace

std::string detail::cellFormatDefine(bool packed) {
    return packed ? "JFA_CELL_FORMAT r32f" : "JFA_CELL_FORMAT rgba32f";
}

GlFloodKernelBase::GlFloodKernelBase(const gl::ShaderLibrary& shaders,
                                     const std::string& criterionFile, GlKernelKind kind,
                                     bool keyed, bool packed, void (*bindCriterion)(gl::Program&))
    : passProgram_(buildKernel(shaders, criterionFile, kind, false, keyed, packed)),
      expandProgram_(buildKernel(shaders, criterionFile, kind, true, keyed, packed)),
      shaders_(shaders), criterionFile_(criterionFile), bindCriterion_(bindCriterion),
      keyed_(keyed), cellFormat_(packed ? GL_R32F : GL_RGBA32F), kind_(kind),
      emptyVao_(gl::VertexArray::create()),
      changedCounter_(sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT) {
    for (gl::Program* p : {&passProgram_, &expandProgram_}) {
        detail::bindKernelPassUniforms(*p, false);
        bindCriterion_(*p);
    }
}

const gl::Texture& GlFloodKernelBase::otherTexture(int width, int height,
                                                   const gl::Texture* current) {
    auto [it, inserted] = pairs_.try_emplace({width, height});
    Pair& pair = it->second;
    if (inserted) {
        for (int i = 0; i < 2; ++i) {
            pair.tex[i] = gl::Texture(cellFormat_, width, height);
            pair.fbo[i] = gl::Framebuffer::forColor(pair.tex[i], "jfa ping-pong");
        }
    }
    return current == &pair.tex[0] ? pair.tex[1] : pair.tex[0];
}

void GlFloodKernelBase::noteWritten(const gl::Texture& dst, int bandStage) {
    Pair& pair = pairs_.at({dst.width(), dst.height()});
    pair.dirt[&dst == &pair.tex[0] ? 0 : 1] = bandStage >= 0 ? bandStage : kDirtWhole;
}

void GlFloodKernelBase::dispatch(const gl::Texture& src, const gl::Texture& seeds,
                                 const gl::Texture& dst, GlDispatch what, int step, int scale,
                                 bool countChanges, int bandStage) {
    const bool banded = bandStage >= 0 && what != GlDispatch::Downsample;
    const bool expand = what == GlDispatch::ExpandThenPass;
    const gl::Program& p = banded ? (expand ? bandExpandProgram_ : bandPassProgram_)
                                  : (expand ? expandProgram_ : passProgram_);
    const detail::KernelPassUniforms& u = detail::kKernelPass;
    p.set(u.size, glm::ivec2(dst.width(), dst.height()));
    p.set(u.srcSize, glm::ivec2(src.width(), src.height()));
    p.set(u.step, step);
    p.set(u.scale, scale);
    p.set(u.mode, static_cast<int>(what));
    p.set(u.countChanges, countChanges ? 1 : 0);
    gl::BindScope scope;
    scope.texture(gl::bind::FloodIn, src.id())
        .texture(gl::bind::FloodSeeds, seeds.id())
        .counter(gl::bind::ChangedCounter, changedCounter_.id());
    if (banded) {
        // The flood's front: of the band, the tiles this pass may change (listFront lists
        // them; the pass binds that list and the front's flags, which it extends).
        const bool front = frontRun_ && what == GlDispatch::Pass;
        if (front) listFront(step);
        p.set(u.tile, tile_);
        p.set(u.front, front ? 1 : 0);
        p.set(u.tilesX, (dst.width() + tile_ - 1) / tile_);
        const StageBandList& band = front ? frontList_ : stageBands_[bandStage];
        scope.storage(gl::bind::BandTiles, band.tiles.id())
            .storage(gl::bind::FloodFront, front ? front_.id() : 0);
        glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, band.commands.id());
    }
    glUseProgram(p.id());
    // Band passes are always compute (an indirect dispatch over the tile list), whatever the
    // kernel's kind: on llvmpipe the fragment kernel's instanced tile quads cost twice as much
    // per pass on a small band (docs/history/soft-shadows.md, jfa_bench "flood:15 ... band").
    if (kind_ == GlKernelKind::Compute || banded) {
        scope.image(gl::bind::FloodOut, dst.id(), GL_WRITE_ONLY, cellFormat_);
        if (banded)
            glDispatchComputeIndirect(0);
        else
            glDispatchCompute(static_cast<GLuint>((dst.width() + 7) / 8),
                              static_cast<GLuint>((dst.height() + 7) / 8), 1);
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_ATOMIC_COUNTER_BARRIER_BIT |
                        GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    } else {
        const Pair& pair = pairs_.at({dst.width(), dst.height()});
        const gl::Framebuffer& fbo = &dst == &pair.tex[0] ? pair.fbo[0] : pair.fbo[1];
        glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
        glViewport(0, 0, dst.width(), dst.height());
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_BLEND);
        glBindVertexArray(emptyVao_.id());
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glBindVertexArray(0);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glMemoryBarrier(GL_ATOMIC_COUNTER_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    }
    noteWritten(dst, banded ? bandStage : -1);
    glUseProgram(0);
    if (banded) glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
}

const gl::Texture& GlFloodKernelBase::runPlan(const Plan& plan, const gl::Texture& seeds,
                                              gl::PassTimer* timer, const PassCallback& callback) {
    if (seeds.width() != plan.width() || seeds.height() != plan.height())
        throw std::invalid_argument("jfa: seeds are " + std::to_string(seeds.width()) + "x" +
                                    std::to_string(seeds.height()) + " but the plan is for " +
                                    std::to_string(plan.width()) + "x" +
                                    std::to_string(plan.height()));
    if (plan.width() > kMaxGlGridExtent || plan.height() > kMaxGlGridExtent)
        throw std::invalid_argument("jfa: GL kernels support grids up to 16384 per side");
    passesRun_ = 0;
    const auto& stages = plan.stages();
    // The thesis' variants have one half-resolution stage at most; deeper pyramids would need a
    // scale-4+ downsample the kernels do not implement.
    if (stages.size() > 2)
        throw std::invalid_argument("jfa: GL kernels run plans of at most two stages, got " +
                                    std::to_string(stages.size()));
    const bool halfRes = stages.size() > 1;
    if (preparedSeeds_ == seeds.id())
        lastRunBanded_ = preparedBanded_; // prepareBand() built it for this plan and seeds
    else
        lastRunBanded_ = banded(region_) && buildBand(plan, seeds);
    // The front needs one stage: a half-resolution stage's tiles are not the seeds' (step A's).
    frontRun_ = lastRunBanded_ && !halfRes && frontEnabled_;
    if (frontRun_) startFront({plan.width(), plan.height()});
    // Steps A-C are consumed: the next frame's seeds may reuse the texture.
    measuredSeeds_ = 0;
    preparedSeeds_ = 0;
    listedSeeds_ = 0;
    const gl::Texture* current = &seeds;
    if (halfRes) {
        const Stage& s0 = stages.front();
        const gl::Texture& dst = otherTexture(s0.width, s0.height, nullptr);
        gl::TimedPass timedDownsample(timer, "downsample");
        dispatch(seeds, seeds, dst, GlDispatch::Downsample, 0, 2, false, -1);
        timedDownsample.end();
        current = &dst;
    }
    bool expanded = false;
    bool stageSettled = false; // an "until unchanged" stage saw a pass that changed nothing
    int index = 0;
    for (const Pass& pass : plan.passes()) {
        if (pass.expandBefore) {
            expanded = true;
            stageSettled = false;
        }
        if (pass.untilUnchanged && stageSettled) {
            ++index;
            continue;
        }
        const GlDispatch what = pass.expandBefore ? GlDispatch::ExpandThenPass : GlDispatch::Pass;
        const int scale = halfRes && !expanded ? 2 : 1;
        const gl::Texture& dst = otherTexture(pass.width, pass.height, current);
        if (pass.untilUnchanged) {
            const GLuint zero = 0;
            glNamedBufferSubData(changedCounter_.id(), 0, sizeof(zero), &zero);
        }
        gl::TimedPass timedStep(timer, "jfa step");
        const int stage = halfRes && !expanded ? 0 : (halfRes ? 1 : 0);
        dispatch(*current, seeds, dst, what, pass.step, scale, pass.untilUnchanged,
                 lastRunBanded_ ? stage : -1);
        timedStep.end();
        ++passesRun_;
        if (pass.untilUnchanged) {
            GLuint changed = 0;
            glGetNamedBufferSubData(changedCounter_.id(), 0, sizeof(changed), &changed);
            stageSettled = changed == 0;
        }
        current = &dst;
        if (callback) callback(index, pass, dst);
        ++index;
    }
    if (current == &seeds) {
        // A plan without passes (a 1x1 grid): the result is a copy of the seeds.
        const gl::Texture& dst = otherTexture(seeds.width(), seeds.height(), nullptr);
        glCopyImageSubData(seeds.id(), GL_TEXTURE_2D, 0, 0, 0, 0, dst.id(), GL_TEXTURE_2D, 0, 0, 0,
                           0, seeds.width(), seeds.height(), 1);
        noteWritten(dst, -1);
        current = &dst;
    }
    gl::throwIfErrors("jfa flood");
    return *current;
}

} // namespace fl::jfa
