// Band-limited flooding on the GPU (jfa/Band.h, jfa_gl/GlKernel.h): steps A (per-tile seed reach),
// B (dilation into tile flags) and C (compaction into a tile list and indirect commands per
// stage), all without read-back, and the band programs that run a pass over a tile list.

#include <jfa/CpuKernel.h> // stageScale
#include <jfa_gl/GlKernel.h>

#include "GlKernelUniforms.h"

#include <base/Text.h>

#include <algorithm>
#include <array>
#include <stdexcept>

namespace fl::jfa {

namespace {

constexpr GLbitfield kStorage = GL_DYNAMIC_STORAGE_BIT;
constexpr long long kMaxShaderReach = 0x3fffffff; // kJfaUnboundedReach in the shaders

/// A buffer of at least `uints` 32-bit words (kept when already large enough).
void ensureBuffer(gl::Buffer& b, std::size_t uints) {
    const auto bytes = static_cast<GLsizeiptr>(std::max<std::size_t>(uints, 1) * sizeof(GLuint));
    if (!b || b.size() < bytes) b = gl::Buffer(bytes, nullptr, kStorage);
}

void clearBuffer(const gl::Buffer& b) {
    const GLuint zero = 0;
    glClearNamedBufferData(b.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
}

GLuint groups(int n) {
    return static_cast<GLuint>((n + 7) / 8);
}

// The band programs' uniforms, one table per shader (jfa_band_*.comp.glsl, tile_dilate).
constexpr struct {
    gl::Uniform<glm::ivec2> size{"uSize"};
    gl::Uniform<int> mode{"uMode"};
} kBandSeeds;
constexpr struct {
    gl::Uniform<glm::ivec2> size{"uSize"};
    gl::Uniform<int> tile{"uTile"};
    gl::Uniform<int> tilesX{"uTilesX"};
} kBandReach;
constexpr struct {
    gl::Uniform<glm::ivec2> tiles{"uTiles"};
    gl::Uniform<int> tile{"uTile"};
    gl::Uniform<int> planReach{"uPlanReach"};
} kBandMark;
constexpr gl::Uniform<glm::ivec2> kBandViewTiles{"uTiles"};
constexpr struct {
    gl::Uniform<glm::ivec2> tiles{"uTiles"};
    gl::Uniform<int> tile{"uTile"};
    gl::Uniform<glm::ivec2> stageTiles{"uStageTiles"};
    gl::Uniform<glm::ivec2> stageSize{"uStageSize"};
    gl::Uniform<int> scale{"uScale"};
} kBandCompact;
constexpr struct {
    gl::Uniform<glm::ivec2> tiles{"uTiles"};
    gl::Uniform<glm::ivec2> size{"uSize"};
    gl::Uniform<int> tile{"uTile"};
    gl::Uniform<int> step{"uStep"};
} kBandFront;
constexpr struct {
    gl::Uniform<glm::ivec2> size{"uSize"};
    gl::Uniform<int> tile{"uTile"};
} kBandClear;
constexpr struct {
    gl::Uniform<glm::ivec2> tiles{"uTiles"};
    gl::Uniform<int> reach{"uReach"};
    gl::Uniform<int> axis{"uAxis"};
    gl::Uniform<int> spans{"uSpans"};
} kDilate;

} // namespace

void GlFloodKernelBase::setRegion(FloodRegion region, int tile) {
    if (const std::string bad = checkBandTile(tile); !bad.empty())
        throw std::invalid_argument("jfa: " + bad);
    region_ = region;
    // The stages' tile lists are in tiles of the old size: what they describe cannot be cleared
    // through them at the new one.
    if (tile != tile_)
        for (auto& entry : pairs_) entry.second.dirt[0] = entry.second.dirt[1] = kDirtWhole;
    tile_ = tile;
}

void GlFloodKernelBase::buildBandPrograms() {
    if (reachProgram_.id() != 0) return;
    reachProgram_ = gl::Program::build(shaders_, {{GL_COMPUTE_SHADER, "jfa_band_reach.comp.glsl"},
                                                  {GL_COMPUTE_SHADER, criterionFile_}});
    seedsProgram_ = gl::Program::build(shaders_, {{GL_COMPUTE_SHADER, "jfa_band_seeds.comp.glsl"},
                                                  {GL_COMPUTE_SHADER, criterionFile_}});
    markProgram_ = gl::Program::build(shaders_, {{GL_COMPUTE_SHADER, "jfa_band_mark.comp.glsl"}});
    compactProgram_ =
        gl::Program::build(shaders_, {{GL_COMPUTE_SHADER, "jfa_band_compact.comp.glsl"}});
    const std::vector<std::string> cellDefines{detail::cellFormatDefine(cellFormat_ == GL_R32F)};
    clearProgram_ = gl::Program::build(shaders_, {{GL_COMPUTE_SHADER, "jfa_band_clear.comp.glsl"}},
                                       cellDefines);
    viewProgram_ = gl::Program::build(shaders_, {{GL_COMPUTE_SHADER, "jfa_band_view.comp.glsl"}});
    frontProgram_ = gl::Program::build(shaders_, {{GL_COMPUTE_SHADER, "jfa_band_front.comp.glsl"}});
    reachProgram_.bindUniforms({&kBandReach.size, &kBandReach.tile, &kBandReach.tilesX});
    bindCriterion_(reachProgram_);
    seedsProgram_.bindUniforms({&kBandSeeds.size, &kBandSeeds.mode});
    bindCriterion_(seedsProgram_);
    markProgram_.bindUniforms({&kBandMark.tiles, &kBandMark.tile, &kBandMark.planReach});
    const auto& c = kBandCompact;
    compactProgram_.bindUniforms({&c.tiles, &c.tile, &c.stageTiles, &c.stageSize, &c.scale});
    clearProgram_.bindUniforms({&kBandClear.size, &kBandClear.tile});
    viewProgram_.bindUniforms({&kBandViewTiles});
    const auto& f = kBandFront;
    frontProgram_.bindUniforms({&f.tiles, &f.size, &f.tile, &f.step});
    dilation_ = std::make_unique<GlTileDilation>(shaders_);
    for (bool expand : {false, true}) {
        std::vector<std::string> defines = cellDefines;
        defines.emplace_back("JFA_BAND");
        if (expand) defines.emplace_back("JFA_EXPAND");
        if (keyed_) defines.emplace_back("JFA_KEYED");
        gl::Program p = gl::Program::build(
            shaders_,
            {{GL_COMPUTE_SHADER, "jfa_pass.comp.glsl"}, {GL_COMPUTE_SHADER, criterionFile_}},
            defines);
        detail::bindKernelPassUniforms(p, true);
        bindCriterion_(p);
        (expand ? bandExpandProgram_ : bandPassProgram_) = std::move(p);
    }
}

std::vector<const gl::Program*> GlFloodKernelBase::criterionPrograms(bool needBand) {
    std::vector<const gl::Program*> out{&passProgram_, &expandProgram_};
    if (needBand) buildBandPrograms();
    if (reachProgram_.id() != 0) {
        out.insert(out.end(),
                   {&seedsProgram_, &reachProgram_, &bandPassProgram_, &bandExpandProgram_});
    }
    return out;
}

void GlFloodKernelBase::measureReach(const gl::Texture& seeds) {
    buildBandPrograms();
    const int tilesX = (seeds.width() + tile_ - 1) / tile_;
    const int tilesY = (seeds.height() + tile_ - 1) / tile_;
    ensureBuffer(tileReach_, 4 * std::size_t(tilesX) * std::size_t(tilesY));
    ensureBuffer(maxReach_, 1);
    const std::array<GLuint, 4> emptyRect{~0u, ~0u, 0u, 0u}; // min > max
    glClearNamedBufferData(tileReach_.id(), GL_RGBA32UI, GL_RGBA_INTEGER, GL_UNSIGNED_INT,
                           emptyRect.data());
    clearBuffer(maxReach_);
    ensureBuffer(front_, std::size_t(tilesX) * std::size_t(tilesY));
    clearBuffer(front_); // step A flags every seed's tile
    // Step A0: the seed texels in a list, and step A's indirect dispatch over it.
    // A producer that listed the seeds as it wrote them (beginSeedList) saves the sweep.
    const bool listed = listedSeeds_ == seeds.id();
    listedSeeds_ = 0;
    gl::BindScope scope;
    if (!listed) beginSeedList(scope, seeds.width(), seeds.height());
    seedsProgram_.set(kBandSeeds.size, glm::ivec2(seeds.width(), seeds.height()));
    scope.texture(gl::bind::FloodSeeds, seeds.id()).storage(gl::bind::SeedList, seedList_.id());
    glUseProgram(seedsProgram_.id());
    if (!listed) {
        seedsProgram_.set(kBandSeeds.mode, 0);
        glDispatchCompute(groups(seeds.width()), groups(seeds.height()), 1);
    }
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    seedsProgram_.set(kBandSeeds.mode, 1);
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
    // Step A over the list.
    reachProgram_.set(kBandReach.size, glm::ivec2(seeds.width(), seeds.height()));
    reachProgram_.set(kBandReach.tile, tile_);
    reachProgram_.set(kBandReach.tilesX, tilesX);
    scope.storage(gl::bind::BandTileRects, tileReach_.id())
        .storage(gl::bind::BandMaxReach, maxReach_.id())
        .storage(gl::bind::FloodFront, front_.id());
    glUseProgram(reachProgram_.id());
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, seedList_.id());
    glDispatchComputeIndirect(sizeof(GLuint)); // SeedList::dispatch
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    glUseProgram(0);
    measuredSeeds_ = seeds.id();
}

void GlFloodKernelBase::beginSeedList(gl::BindScope& scope, int width, int height) {
    ensureBuffer(seedList_, 4 + std::size_t(width) * std::size_t(height));
    const GLuint zero = 0;
    glClearNamedBufferSubData(seedList_.id(), GL_R32UI, 0, sizeof(GLuint), GL_RED_INTEGER,
                              GL_UNSIGNED_INT, &zero);
    scope.storage(gl::bind::SeedList, seedList_.id());
    listedSeeds_ = 0;
}

void GlFloodKernelBase::seedsListed(const gl::Texture& seeds) {
    listedSeeds_ = seeds.id();
}

long long GlFloodKernelBase::readMaxReach() const {
    GLuint stored = 0;
    glGetNamedBufferSubData(maxReach_.id(), 0, sizeof(stored), &stored);
    if (stored == 0) return -1;
    const long long r = static_cast<long long>(stored) - 1;
    return r >= kMaxShaderReach ? kUnboundedReach : r;
}

bool GlFloodKernelBase::buildBand(const Plan& plan, const gl::Texture& seeds) {
    const int w = plan.width(), h = plan.height();
    const long long planReach = planBandReach(plan);
    if (!criterionBounds_ && planReach >= std::max(w, h) - 1) return false; // the plan fills it
    if (measuredSeeds_ != seeds.id()) measureReach(seeds);
    const glm::ivec2 tiles((w + tile_ - 1) / tile_, (h + tile_ - 1) / tile_);
    ensureBuffer(flags_, std::size_t(tiles.x) * std::size_t(tiles.y));
    clearBuffer(flags_);
    // Step B: mark the tiles each seed tile's rect touches, within the plan's square.
    markProgram_.set(kBandMark.tiles, tiles);
    markProgram_.set(kBandMark.tile, tile_);
    markProgram_.set(kBandMark.planReach, int(std::min(planReach, kMaxShaderReach)));
    gl::BindScope scope;
    scope.storage(gl::bind::BandTileRects, tileReach_.id())
        .storage(gl::bind::BandFlags, flags_.id());
    glUseProgram(markProgram_.id());
    glDispatchCompute(groups(tiles.x), groups(tiles.y), 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    // The view limit: off the tiles no view texel depends on.
    if (const int reach = viewTileReach(plan, tile_);
        region_ == FloodRegion::View && viewTiles_ != nullptr && reach >= 0) {
        if (viewTiles_->size() < GLsizeiptr(sizeof(GLuint)) * tiles.x * tiles.y)
            throw std::invalid_argument("jfa: the view tiles buffer is smaller than the band's " +
                                        std::to_string(tiles.x * tiles.y) + " tiles");
        ensureBuffer(viewNear_, std::size_t(tiles.x) * std::size_t(tiles.y));
        dilation_->run(*viewTiles_, viewNear_, tiles, reach);
        viewProgram_.set(kBandViewTiles, tiles);
        // In the step's scope: the dilation above unbound only its own points.
        scope.storage(gl::bind::BandFlags, flags_.id())
            .storage(gl::bind::BandNearView, viewNear_.id());
        glUseProgram(viewProgram_.id());
        glDispatchCompute(groups(tiles.x), groups(tiles.y), 1);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
    // Step C: per stage, the tiles holding a band texel's grid point, and the commands.
    const std::vector<Stage>& stages = plan.stages();
    compactProgram_.set(kBandCompact.tiles, tiles);
    compactProgram_.set(kBandCompact.tile, tile_);
    for (std::size_t s = 0; s < stages.size(); ++s) {
        const glm::ivec2 size(stages[s].width, stages[s].height);
        const glm::ivec2 stageTiles = (size + tile_ - 1) / tile_;
        StageBandList& band = stageBands_[s];
        // The stage's ping-pong pair starts empty, since texels outside the band are never
        // written: what the last band run of this stage wrote is cleared over its tile list
        // before the list is rebuilt, anything else over the whole texture.
        (void)otherTexture(size.x, size.y, nullptr); // allocates the pair
        const int stage = static_cast<int>(s);
        for (auto& [key, pair] : pairs_) {
            for (int i = 0; i < 2; ++i) {
                if (key == std::pair{size.x, size.y})
                    emptyTexture(pair, i, stage);
                else if (pair.dirt[i] == stage) // its list is about to describe another size
                    pair.dirt[i] = kDirtWhole;
            }
        }
        restartList(band, stageTiles, true);
        compactProgram_.set(kBandCompact.stageTiles, stageTiles);
        compactProgram_.set(kBandCompact.stageSize, size);
        compactProgram_.set(kBandCompact.scale, stageScale(plan, s));
        scope.storage(gl::bind::BandTiles, band.tiles.id())
            .storage(gl::bind::BandCommands, band.commands.id());
        glUseProgram(compactProgram_.id());
        glDispatchCompute(groups(stageTiles.x), groups(stageTiles.y), 1);
    }
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
    glUseProgram(0);
    bandStages_ = static_cast<int>(stages.size());
    bandArea_ = double(w) * double(h);
    return true;
}

void GlFloodKernelBase::restartList(StageBandList& list, glm::ivec2 tiles, bool texelsToo) {
    ensureBuffer(list.tiles, std::size_t(tiles.x) * std::size_t(tiles.y));
    if (!list.commands) list.commands = gl::Buffer(4 * sizeof(GLuint), nullptr, kStorage);
    const auto blocks = static_cast<GLuint>((tile_ / 8) * (tile_ / 8));
    const std::array<GLuint, 4> init{0, blocks, 1, 0};
    glNamedBufferSubData(list.commands.id(), 0, (texelsToo ? 4 : 3) * sizeof(GLuint), init.data());
}

void GlFloodKernelBase::startFront(glm::ivec2 size) {
    frontTiles_ = (size + tile_ - 1) / tile_;
    restartList(frontList_, frontTiles_, true); // [3] then sums the texels over the run
    frontProgram_.set(kBandFront.tiles, frontTiles_);
    frontProgram_.set(kBandFront.size, size);
    frontProgram_.set(kBandFront.tile, tile_);
}

void GlFloodKernelBase::listFront(int step) {
    restartList(frontList_, frontTiles_, false);
    frontProgram_.set(kBandFront.step, step);
    gl::BindScope scope;
    scope.storage(gl::bind::BandFlags, flags_.id())
        .storage(gl::bind::BandTiles, frontList_.tiles.id())
        .storage(gl::bind::BandCommands, frontList_.commands.id())
        .storage(gl::bind::FloodFront, front_.id());
    glUseProgram(frontProgram_.id());
    glDispatchCompute(groups(frontTiles_.x), groups(frontTiles_.y), 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
    glUseProgram(0);
}

void GlFloodKernelBase::emptyTexture(Pair& pair, int i, int stage) {
    const gl::Texture& t = pair.tex[i];
    if (pair.dirt[i] == stage && stageBands_[stage].commands) {
        clearProgram_.set(kBandClear.size, glm::ivec2(t.width(), t.height()));
        clearProgram_.set(kBandClear.tile, tile_);
        gl::BindScope scope;
        scope.image(gl::bind::FloodOut, t.id(), GL_WRITE_ONLY, cellFormat_)
            .storage(gl::bind::BandTiles, stageBands_[stage].tiles.id());
        glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, stageBands_[stage].commands.id());
        glUseProgram(clearProgram_.id());
        glDispatchComputeIndirect(0);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                        GL_SHADER_STORAGE_BARRIER_BIT);
        glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
        glUseProgram(0);
    } else if (pair.dirt[i] != kDirtClean) {
        const std::array<float, 4> empty{0.0f, 0.0f, -1.0f, 0.0f}; // kEmptyCell
        glClearTexImage(t.id(), 0, GL_RGBA, GL_FLOAT, empty.data());
    }
    pair.dirt[i] = kDirtClean;
}

GlTileDilation::GlTileDilation(const gl::ShaderLibrary& shaders)
    : program_(gl::Program::build(shaders, {{GL_COMPUTE_SHADER, "tile_dilate.comp.glsl"}})) {
    program_.bindUniforms({&kDilate.tiles, &kDilate.reach, &kDilate.axis, &kDilate.spans});
}

void GlTileDilation::run(const gl::Buffer& in, const gl::Buffer& out, glm::ivec2 tiles, int reach,
                         std::initializer_list<const gl::Buffer*> spanLists) {
    if (spanLists.size() > 2)
        throw std::invalid_argument("jfa: a tile dilation widens at most two span lists");
    ensureBuffer(rows_, std::size_t(tiles.x) * std::size_t(tiles.y));
    glUseProgram(program_.id());
    program_.set(kDilate.tiles, tiles);
    program_.set(kDilate.reach, reach);
    gl::BindScope scope;
    const gl::StorageBinding spanBindings[] = {gl::bind::RowSpans, gl::bind::OwnSpans};
    const gl::StorageBinding* binding = spanBindings;
    for (const gl::Buffer* spans : spanLists) scope.storage(*binding++, spans->id());
    const std::pair<const gl::Buffer*, const gl::Buffer*> halves[] = {{&in, &rows_},
                                                                      {&rows_, &out}};
    for (int axis = 0; axis < 2; ++axis) {
        program_.set(kDilate.axis, axis);
        program_.set(kDilate.spans, axis == 1 ? int(spanLists.size()) : 0);
        scope.storage(gl::bind::DilateIn, halves[axis].first->id())
            .storage(gl::bind::DilateOut, halves[axis].second->id());
        glDispatchCompute(groups(tiles.x), groups(tiles.y), 1);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
    glUseProgram(0);
}

double GlFloodKernelBase::computedShare() const {
    if (!frontRun_) return activeShare();
    GLuint texels = 0;
    glGetNamedBufferSubData(frontList_.commands.id(), 3 * sizeof(GLuint), sizeof(texels), &texels);
    return passesRun_ > 0 && bandArea_ > 0.0 ? double(texels) / passesRun_ / bandArea_ : 1.0;
}

double GlFloodKernelBase::activeShare() const {
    if (!lastRunBanded_) return 1.0;
    GLuint texels = 0;
    glGetNamedBufferSubData(stageBands_[bandStages_ - 1].commands.id(), 3 * sizeof(GLuint),
                            sizeof(texels), &texels);
    return bandArea_ > 0.0 ? double(texels) / bandArea_ : 1.0;
}

} // namespace fl::jfa
