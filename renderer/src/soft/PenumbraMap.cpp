#include <renderer/passes/Phases.h>
#include <renderer/soft/OccluderEdge.h>
#include <renderer/soft/PenumbraMap.h>

#include <jfa/CpuKernel.h>

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fl {

namespace {

// silhouette.frag.glsl's own uniforms; the region's (SILHOUETTE_REGION, with tile_rows.vert.glsl)
// apart.
constexpr struct {
    gl::Uniform<float> threshold{"uSilhouetteThreshold"};
    gl::Uniform<int> listSeeds{"uListSeeds"};
} kSilhouette;
constexpr struct {
    gl::Uniform<int> regionTile{"uRegionTile"};
    gl::Uniform<int> regionTilesX{"uRegionTilesX"};
    gl::Uniform<int> tile{"uTile"};
    gl::Uniform<glm::ivec2> size{"uSize"};
} kSilhouetteRegion;

// penumbra_view.frag.glsl's uniforms.
constexpr struct {
    gl::Uniform<glm::mat4> lightViewProj{"uLightViewProj"};
    gl::Uniform<glm::mat4> warp{"uShadowWarp"};
    gl::Uniform<int> mapSize{"uMapSize"};
    gl::Uniform<int> tile{"uTile"};
} kPenumbraView;

// Bytes of one flag (a uint) per band tile of a size^2 map: the view's and the seed region's.
GLsizeiptr tileFlagBytes(int size, int tile) {
    const GLsizeiptr tiles = (size + tile - 1) / tile;
    return GLsizeiptr(sizeof(GLuint)) * tiles * tiles;
}
// Bytes of one list of row spans (each row's first and last tile, two ints).
GLsizeiptr rowSpanBytes(int size, int tile) {
    return GLsizeiptr(2 * sizeof(GLint)) * ((size + tile - 1) / tile);
}
} // namespace

int penumbraMaxPasses(int size) {
    return jfa::jfaMaxPasses(size);
}

jfa::Plan penumbraPlan(const PenumbraSettings& settings, int size) {
    const int maxPasses = penumbraMaxPasses(size);
    if (settings.passes < 1 || settings.passes > maxPasses)
        throw std::invalid_argument("JFA pass count " + std::to_string(settings.passes) +
                                    " is outside [1, " + std::to_string(maxPasses) + "] for a " +
                                    std::to_string(size) + "^2 shadow map");
    const int reach = (1 << settings.passes) - 1;
    if (settings.standardFlooding) return jfa::Plan::flood(reach, size, size);
    std::vector<int> steps;
    for (int s = 1 << (settings.passes - 1); s >= 1; s /= 2) steps.push_back(s);
    jfa::Stage stage;
    stage.width = size;
    stage.height = size;
    stage.steps = steps;
    return jfa::Plan("JFA " + std::to_string(settings.passes) + " passes", {stage});
}

jfa::Grid readPenumbraGrid(const gl::Texture& packed, const jfa::Grid& positions) {
    return jfa::readPackedGrid(packed, positions,
                               [](float tag) -> std::size_t { return shadowmap::seedIndex(tag); });
}

jfa::Grid silhouetteSeeds(const ReceiverGrid& r, const DiskLight& light, float threshold,
                          const jfa::Band* region) {
    jfa::Grid out(r.width, r.height, jfa::kEmptyCell);
    for (int y = 0; y < r.height; ++y)
        for (int x = 0; x < r.width; ++x) {
            const glm::vec4& self = r.at(x, y);
            if (self.w == 0.0f || (region != nullptr && !region->covers(x, y))) continue;
            bool silhouette = false;
            for (int j = -1; j <= 1; ++j)
                for (int i = -1; i <= 1; ++i) {
                    const int qx = x + i, qy = y + j;
                    if ((i == 0 && j == 0) || qx < 0 || qy < 0 || qx >= r.width || qy >= r.height)
                        continue;
                    silhouette =
                        silhouette || acrossSilhouette(light, self, r.at(qx, qy), threshold);
                }
            if (silhouette)
                out.at(x, y) = {self.x, self.y, self.z, shadowmap::seedTag(x, y, r.width)};
        }
    return out;
}

std::vector<std::uint8_t> penumbraViewTiles(const ReceiverGrid& eyePositions,
                                            const glm::mat4& lightViewProj, const glm::mat4& warp,
                                            int mapSize, int tile) {
    const int tiles = (mapSize + tile - 1) / tile;
    std::vector<std::uint8_t> out(std::size_t(tiles) * std::size_t(tiles), 0);
    for (const glm::vec4& p : eyePositions.points) {
        if (p.w == 0.0f) continue;
        const std::optional<glm::vec3> coord =
            shadowmap::mapCoord(lightViewProj, warp, glm::vec3(p));
        if (!coord) continue;
        const glm::vec3 uvz = *coord;
        constexpr float kMargin = 1e-4f;
        if (glm::any(glm::lessThan(uvz, glm::vec3(-kMargin))) ||
            glm::any(glm::greaterThan(uvz, glm::vec3(1.0f + kMargin))))
            continue;
        const glm::ivec2 t = glm::clamp(glm::ivec2(glm::vec2(uvz) * float(mapSize)), glm::ivec2(0),
                                        glm::ivec2(mapSize - 1));
        out[std::size_t(t.y / tile) * std::size_t(tiles) + std::size_t(t.x / tile)] = 1;
    }
    return out;
}

PenumbraMapPass::PenumbraMapPass(const gl::ShaderLibrary& shaders)
    : silhouette_(gl::Program::build(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                               {GL_FRAGMENT_SHADER, "silhouette.frag.glsl"}})),
      emptyVao_(gl::VertexArray::create()), kernel_(shaders, jfa::GlKernelKind::Fragment),
      bounds_(shaders),
      viewProgram_(gl::Program::build(shaders, {{GL_VERTEX_SHADER, "fullscreen.vert.glsl"},
                                                {GL_FRAGMENT_SHADER, "penumbra_view.frag.glsl"}})),
      viewFbo_(gl::Framebuffer::create()), dilation_(shaders),
      silhouetteRows_(gl::Program::build(
          shaders,
          {{GL_VERTEX_SHADER, "tile_rows.vert.glsl"}, {GL_FRAGMENT_SHADER, "silhouette.frag.glsl"}},
          {"SILHOUETTE_REGION 1"})) {
    for (gl::Program* program : {&silhouette_, &silhouetteRows_}) {
        program->bindUniforms({&kSilhouette.threshold, &kSilhouette.listSeeds});
        bindDiskLightUniforms(*program);
        MapPositions::bindUniforms(*program);
    }
    const auto& r = kSilhouetteRegion;
    silhouetteRows_.bindUniforms({&r.regionTile, &r.regionTilesX, &r.tile, &r.size});
    const auto& v = kPenumbraView;
    viewProgram_.bindUniforms({&v.lightViewProj, &v.warp, &v.mapSize, &v.tile});
    SurfacePositions::bindUniforms(viewProgram_);
}

PenumbraMapPass::Outputs PenumbraMapPass::execute(const Inputs& in, gl::PassTimer* timer) {
    const int size = in.receivers.size();
    if (in.settings.passes != 0)
        (void)penumbraPlan(in.settings, size); // validates before any GL work
    if (!seeds_ || seeds_.width() != size) {
        seeds_ = gl::Texture(GL_R32F, size, size); // packed: a seed's tag (jfa_penumbra.glsl)
        seedsOffSpansEmpty_ = false;
        fbo_ = gl::Framebuffer::forColor(seeds_, "silhouette seeds");
    }
    // --flood-region view: the tiles the lookup reads, and the region around them where seeds
    // and receivers count (seedRegion_; jfa/Band.h, the view limit).
    const bool limited = in.settings.region == jfa::FloodRegion::View && in.view != nullptr;
    long long regionReach = limited ? in.viewSeedReach : -1;
    viewTileCount_ = 0;
    bool region = limited && markViewRegion(in, regionReach, timer);
    // Phase 2 (thesis; within frame step 3): silhouettes.
    gl::TimedPass timedSilhouettes(timer, phase::kSilhouettes);
    findSeeds(in, region);
    // The whole map: exact without a region; with one, an upper bound (the pass draws only the
    // region's row spans, which only the GPU knows).
    timedSilhouettes.wrote(gl::textureBytes(seeds_));
    timedSilhouettes.end();
    // Phase 3: flood the occluders through the penumbra region; its band (jfa/Band.h) and,
    // with auto, its pass count first, timed apart.
    gl::TimedPass timedBand(timer, phase::kBand);
    PenumbraCriterion criterion;
    criterion.light = in.light;
    criterion.map = in.receivers;
    criterion.reachBound = in.reach;
    criterion.umbraDepth = in.umbraDepth;
    kernel_.setRegion(in.settings.region, in.settings.bandTile);
    kernel_.setViewTiles(limited ? &viewTiles_ : nullptr);
    const PenumbraSettings settings = planBand(in, criterion, region, regionReach, timedBand);
    seedRegionCount_ = region ? viewTileCount_ : 0;
    const jfa::Plan plan = penumbraPlan(settings, size);
    kernel_.prepareBand(plan, seeds_, criterion);
    timedBand.end();
    gl::TimedPass timedFlood(timer, phase::kFlood);
    const gl::Texture& map = kernel_.run(plan, seeds_, criterion);
    timedFlood.end();
    kernel_.setViewTiles(nullptr);
    return {seeds_, map, kernel_.passesRun(), settings.passes};
}

bool PenumbraMapPass::markViewRegion(const Inputs& in, long long regionReach,
                                     gl::PassTimer* timer) {
    const int size = in.receivers.size();
    const int tile = in.settings.bandTile;
    gl::TimedPass timedView(timer, phase::kView);
    markView(*in.view, size, tile);
    const bool region = regionReach >= 0 && markSeedRegion(size, tile, regionReach);
    // The view's tile flags; the seed region's flags and its two lists of row spans.
    timedView.wrote(tileFlagBytes(size, tile) +
                    (region ? tileFlagBytes(size, tile) + 2 * rowSpanBytes(size, tile) : 0));
    timedView.end();
    return region;
}

PenumbraSettings PenumbraMapPass::planBand(const Inputs& in, PenumbraCriterion& criterion,
                                           bool& region, long long& regionReach,
                                           const gl::TimedPass& band) {
    const int size = in.receivers.size();
    const int tile = in.settings.bandTile;
    PenumbraSettings settings = in.settings;
    for (;;) {
        if (criterion.reachBound.enabled) { // receivers are the texels with w = 1
            bounds_.build(in.receivers, in.light, criterion.reachBound,
                          region ? &seedRegion_ : nullptr, tile);
            band.wrote(bounds_.bytes());
        }
        // auto: one value read back (the plan is recorded on the CPU). The count covers the lit
        // side's reach on the real receivers (umbraDepth 0): the umbra side's half of a penumbra
        // on a receiver is as wide as the lit side's on one as deep (a straight edge's penumbra
        // runs symmetric about the hard edge, segmentFraction from 0 to 1), while its stand-ins lie
        // at the scene's deepest point, whose cones would ask for a pass more everywhere.
        if (settings.passes == 0) {
            PenumbraCriterion litSide = criterion;
            litSide.umbraDepth = 0.0f;
            // The band itself is measured again with the umbra side's rects (keep = false).
            settings.passes = jfa::passesForReach(
                kernel_.maxSeedReach(seeds_, litSide, criterion.umbraDepth == 0.0f),
                penumbraMaxPasses(size));
        }
        // Auto may choose more passes than the region covers (it covers the widest penumbra,
        // rounded up to tiles, not the passes that rounds up to): then once more over the
        // flood's cone, seeds and receivers included (timed within "band").
        if (!region || in.settings.passes != 0 || (1LL << settings.passes) <= regionReach) break;
        regionReach = 1LL << settings.passes;
        settings.passes = 0;
        region = markSeedRegion(size, tile, regionReach);
        findSeeds(in, region);
        band.wrote(gl::textureBytes(seeds_)); // as above, an upper bound
    }
    return settings;
}

void PenumbraMapPass::findSeeds(const Inputs& in, bool region) {
    const int size = in.receivers.size();
    const int tile = in.settings.bandTile;
    const gl::Program& program = region ? silhouetteRows_ : silhouette_;
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, size, size);
    glDisable(GL_DEPTH_TEST);
    setDiskLightUniforms(program, in.light);
    program.set(kSilhouette.threshold, in.threshold);
    // A banded flood lists its seeds here, in the pass that finds them, rather than sweeping
    // the map for them again (GlFloodKernelBase::beginSeedList).
    const bool listSeeds = jfa::banded(in.settings.region);
    program.set(kSilhouette.listSeeds, listSeeds ? 1 : 0);
    gl::BindScope scope;
    if (listSeeds) kernel_.beginSeedList(scope, size, size);
    in.receivers.bind(scope, program, gl::bind::SilhouetteReceivers);
    if (region) {
        // The spans drawn are this region's and the last one's (markSeedRegion), so every texel
        // off them was off the last spans too, and empty since: cleared only when the texture
        // held more (a new one, a pass over the whole map, another tile size).
        if (!seedsOffSpansEmpty_) {
            const std::array<float, 4> empty{0.0f, 0.0f, -1.0f, 0.0f}; // jfa::kEmptyCell
            glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 0, empty.data());
        }
        const int tiles = (size + tile - 1) / tile;
        program.set(kSilhouetteRegion.regionTile, tile);
        program.set(kSilhouetteRegion.regionTilesX, tiles);
        program.set(kSilhouetteRegion.tile, tile);
        program.set(kSilhouetteRegion.size, glm::ivec2(size));
        scope.storage(gl::bind::SeedRegion, seedRegion_.id())
            .storage(gl::bind::RowSpans, rowSpans_.id());
        glUseProgram(program.id());
        glBindVertexArray(emptyVao_.id());
        glDrawArraysInstanced(GL_TRIANGLES, 0, 6, tiles);
        glBindVertexArray(0);
        glUseProgram(0);
        seedsOffSpansEmpty_ = true;
        spansTile_ = tile;
    } else {
        gl::drawFullscreenTriangle(program, emptyVao_);
        seedsOffSpansEmpty_ = false;
    }
    if (listSeeds) kernel_.seedsListed(seeds_);
    scope.release();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

bool PenumbraMapPass::markSeedRegion(int size, int tile, long long reach) {
    const int tiles = (size + tile - 1) / tile;
    const long long tileReach = (reach + tile - 1) / tile;
    if (tileReach >= tiles - 1) return false; // the whole map
    const GLsizeiptr bytes = tileFlagBytes(size, tile);
    if (!seedRegion_ || seedRegion_.size() < bytes)
        seedRegion_ = gl::Buffer(bytes, nullptr, GL_DYNAMIC_STORAGE_BIT);
    // Each row's first and last tile, found by the second half (tile_rows.vert.glsl draws them).
    // rowSpans_ (drawn) starts from the last region's own spans, lastSpans_ from none.
    const GLsizeiptr spanBytes = rowSpanBytes(size, tile);
    for (gl::Buffer* b : {&rowSpans_, &lastSpans_})
        if (!*b || b->size() < spanBytes)
            *b = gl::Buffer(spanBytes, nullptr, GL_DYNAMIC_STORAGE_BIT);
    const std::array<GLint, 2> noSpan{tiles, -1};
    if (seedsOffSpansEmpty_ && spansTile_ == tile)
        glCopyNamedBufferSubData(lastSpans_.id(), rowSpans_.id(), 0, 0, spanBytes);
    else
        glClearNamedBufferData(rowSpans_.id(), GL_RG32I, GL_RG_INTEGER, GL_INT, noSpan.data());
    if (spansTile_ != tile) seedsOffSpansEmpty_ = false;
    glClearNamedBufferData(lastSpans_.id(), GL_RG32I, GL_RG_INTEGER, GL_INT, noSpan.data());
    dilation_.run(viewTiles_, seedRegion_, glm::ivec2(tiles), int(tileReach),
                  {&rowSpans_, &lastSpans_});
    return true;
}

void PenumbraMapPass::markView(const PenumbraView& view, int size, int tile) {
    const int tiles = (size + tile - 1) / tile;
    const GLsizeiptr bytes = tileFlagBytes(size, tile);
    if (!viewTiles_ || viewTiles_.size() < bytes)
        viewTiles_ = gl::Buffer(bytes, nullptr, GL_DYNAMIC_STORAGE_BIT);
    viewTileCount_ = tiles * tiles;
    const GLuint zero = 0;
    glClearNamedBufferData(viewTiles_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    viewProgram_.set(kPenumbraView.lightViewProj, view.lightViewProj);
    viewProgram_.set(kPenumbraView.warp, view.warp);
    viewProgram_.set(kPenumbraView.mapSize, size);
    viewProgram_.set(kPenumbraView.tile, tile);
    // One fragment per eye pixel, into a framebuffer without attachments.
    const int w = view.positions.width(), h = view.positions.height();
    glNamedFramebufferParameteri(viewFbo_.id(), GL_FRAMEBUFFER_DEFAULT_WIDTH, w);
    glNamedFramebufferParameteri(viewFbo_.id(), GL_FRAMEBUFFER_DEFAULT_HEIGHT, h);
    glBindFramebuffer(GL_FRAMEBUFFER, viewFbo_.id());
    glViewport(0, 0, w, h);
    glDisable(GL_DEPTH_TEST);
    gl::BindScope scope;
    view.positions.bind(scope, viewProgram_, gl::bind::PenumbraSurfacesDepth);
    scope.storage(gl::bind::ViewTiles, viewTiles_.id());
    gl::drawFullscreenTriangle(viewProgram_, emptyVao_);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    scope.release();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

namespace {
std::vector<std::uint8_t> readFlags(const gl::Buffer& b, int count) {
    std::vector<GLuint> flags(static_cast<std::size_t>(count));
    if (!flags.empty())
        glGetNamedBufferSubData(b.id(), 0, GLsizeiptr(flags.size() * sizeof(GLuint)), flags.data());
    return {flags.begin(), flags.end()};
}
} // namespace

std::vector<std::uint8_t> PenumbraMapPass::viewTiles() const {
    return readFlags(viewTiles_, viewTileCount_);
}

std::vector<std::uint8_t> PenumbraMapPass::seedRegion() const {
    return readFlags(seedRegion_, seedRegionCount_);
}

} // namespace fl
