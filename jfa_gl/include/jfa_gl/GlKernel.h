#pragma once
// The GL kernels: a Plan run on the GPU with a ping-pong pair of RGBA32F textures per grid size,
// either as fragment passes (full-screen triangle into an FBO) or as compute passes (imageStore).
// Semantics are exactly those of jfa/CpuKernel.h — downsampling to the half-resolution stage,
// candidate reads, expansion, "until unchanged" — and tests compare the two texel for texel.
// With FloodRegion::Band (setRegion) the passes run only over the band's tiles (jfa/Band.h): the
// tile list is built on the GPU (per-tile seed reach, dilation, compaction into indirect
// commands) with no read-back, and each pass is an indirect compute dispatch over it, for either
// kind: instanced tile quads through the fragment kernel measured twice as slow per pass on
// llvmpipe (docs/BENCHMARKS.md), while the fragment kernel stays the faster one on the full grid.

#include <jfa/Band.h>
#include <jfa/Grid.h>
#include <jfa/NearestSite.h>
#include <jfa/Plan.h>

#include <gpu/BindScope.h>
#include <gpu/Gl.h>
#include <gpu/PassTimer.h>
#include <gpu/Program.h>

#include <functional>
#include <initializer_list>
#include <map>
#include <memory>
#include <string>
#include <utility>

namespace fl::jfa {

enum class GlKernelKind { Fragment, Compute };
/// "fragment" or "compute".
const char* kernelName(GlKernelKind kind);

/// Sets a criterion's uniforms on a kernel program and binds its textures in `scope`, which
/// the kernel holds for the run; one overload per criterion.
void setCriterionUniforms(gl::BindScope& scope, const gl::Program& program,
                          const NearestSite& criterion);
/// Binds the uniforms setCriterionUniforms sets on a kernel program, once it is built; one
/// overload per criterion, found the same way (the pointer only chooses the overload).
void bindCriterionUniforms(gl::Program& program, const NearestSite*);

/// Uploads a grid as an RGBA32F texture (row y of the grid = texel row y).
gl::Texture uploadGrid(const Grid& grid);
/// Reads an RGBA32F texture back into a grid.
Grid readGrid(const gl::Texture& texture);
/// Reads a grid of packed cells (R32F, 0 empty; see PackedCells) back: the cell of stored value
/// v is source's cell seedIndex(v) with w = v (the criterion's jfaLoad, on the CPU). Throws
/// std::logic_error for an index beyond `source`.
Grid readPackedGrid(const gl::Texture& packed, const Grid& source,
                    std::size_t (*seedIndex)(float stored));

/// Widens a set of tiles by `reach` tiles per axis, a square, on the GPU: one uint per tile of a
/// tiles.x x tiles.y grid, row-major, nonzero where set (shaders/tile_dilate.comp.glsl, along x
/// then along y; fl::jfa::viewRegion on the CPU). The view limit's region around the tiles a
/// reader reads: the band kernels' (GlFloodKernelBase::setViewTiles) and JFA-L's seed region.
class GlTileDilation {
  public:
    explicit GlTileDilation(const gl::ShaderLibrary& shaders);
    /// `out` = `in` widened. Each span list given (two ints per row, each starting from
    /// (tiles.x, -1) or from spans of before; at most two) is widened to hold each row's first
    /// and last set tile of `out`.
    void run(const gl::Buffer& in, const gl::Buffer& out, glm::ivec2 tiles, int reach,
             std::initializer_list<const gl::Buffer*> spanLists = {});

  private:
    gl::Program program_;
    gl::Buffer rows_; // the x half
};

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

    /// Where the next runs flood: the band (tiles of side `tile`, a multiple of 8), the band
    /// less what a view cannot read (setViewTiles), or the full grid. Throws
    /// std::invalid_argument for a bad tile. Full by default.
    void setRegion(FloodRegion region, int tile = kDefaultBandTile);
    /// With FloodRegion::View: the tiles the reader of the result reads (one uint per band tile
    /// of the seeds' grid, row-major, nonzero where it reads a texel); the runs are then exact at
    /// those tiles only (jfa/Band.h). The caller keeps the buffer alive while it is set.
    /// nullptr (the default): View floods the band.
    void setViewTiles(const gl::Buffer* tiles) { viewTiles_ = tiles; }
    [[nodiscard]] FloodRegion region() const { return region_; }
    /// Whether band runs of one-stage plans compute, each pass, only the band tiles within the
    /// flood's front (jfa/Band.h; the same result). On by default; off for comparisons.
    void setFrontLimited(bool on) { frontEnabled_ = on; }
    /// The band's tile side (setRegion).
    [[nodiscard]] int bandTile() const { return tile_; }
    /// False when the last run flooded the full grid: the region is Full, or the plan alone
    /// reaches every texel and the criterion bounds nothing (nothing to save; callers say so).
    [[nodiscard]] bool lastRunBanded() const { return lastRunBanded_; }
    /// For a pass that writes the seeds texture over the whole grid (width x height): binds the
    /// band's seed list, emptied, at gl::bind::SeedList (shaders/jfa_seed_list.glsl) in the
    /// pass' `scope`, for the pass to append every seed it writes with jfaListSeed. Then
    /// seedsListed() says which texture the list describes, and step A0 does not sweep that
    /// grid again. Optional.
    void beginSeedList(gl::BindScope& scope, int width, int height);
    /// The list begun by beginSeedList() holds exactly the seeds of `seeds`.
    void seedsListed(const gl::Texture& seeds);

    /// Share of the full-resolution grid the last run's passes computed: 1 after a full run.
    /// Reads one counter back from the GPU (a sync point): call it after the frame, not in it.
    [[nodiscard]] double activeShare() const;
    /// Share of the grid an average pass of the last run computed: activeShare(), or less when
    /// the passes ran within the flood's front (setFrontLimited). Reads back, like activeShare.
    [[nodiscard]] double computedShare() const;

  protected:
    /// Builds the kernel programs with `criterionFile` (a criterion's glslFile) linked in;
    /// `bindCriterion` binds the criterion's uniforms on each (now, and on the band's programs
    /// when they are built). `packed`: the criterion stores a cell in one R32F texel
    /// (jfaLoad/jfaStore unpack it; JFA_CELL_FORMAT r32f), else one RGBA32F texel as it is.
    GlFloodKernelBase(const gl::ShaderLibrary& shaders, const std::string& criterionFile,
                      GlKernelKind kind, bool keyed, bool packed,
                      void (*bindCriterion)(gl::Program&));

    /// The programs that link the criterion (their uniforms are the criterion's), the band
    /// programs included once built; `needBand` builds them first.
    std::vector<const gl::Program*> criterionPrograms(bool needBand);
    /// Band step A on `seeds` (jfa_band_reach.comp.glsl), once the criterion's uniforms are set;
    /// runPlan() reuses it for the same seeds texture.
    void measureReach(const gl::Texture& seeds);
    /// The largest seed reach step A found (reads it back); -1 without seeds.
    long long readMaxReach() const;
    /// Drops step A's result, so that the next band is measured again.
    void forgetReach() { measuredSeeds_ = 0; }
    /// Whether the criterion can bound a seed's reach (a Reaching criterion).
    bool criterionBounds_ = false;

    /// The plan loop, once the criterion's uniforms are set on both programs.
    const gl::Texture& runPlan(const Plan& plan, const gl::Texture& seeds, gl::PassTimer* timer,
                               const PassCallback& callback);

    gl::Program passProgram_;   // passes and downsampling
    gl::Program expandProgram_; // the pass that expands the half-resolution stage (JFA_EXPAND)

  private:
    void dispatch(const gl::Texture& src, const gl::Texture& seeds, const gl::Texture& dst,
                  GlDispatch what, int step, int scale, bool countChanges, int bandStage);
    const gl::Texture& otherTexture(int width, int height, const gl::Texture* current);
    /// Builds the tile lists of the plan's stages (steps B and C; A if not measured for
    /// `seeds`) and clears the stages' ping-pong textures. False: the band is the whole grid.
    bool buildBand(const Plan& plan, const gl::Texture& seeds);
    void buildBandPrograms();

    gl::ShaderLibrary shaders_;
    std::string criterionFile_;
    void (*bindCriterion_)(gl::Program&); // the criterion's bindCriterionUniforms
    bool keyed_ = false;
    GLenum cellFormat_ = GL_RGBA32F; // GL_R32F for packed cells
    GlKernelKind kind_;
    FloodRegion region_ = FloodRegion::Full;
    int tile_ = kDefaultBandTile;
    gl::Program seedsProgram_;                                // band step A0: the seed list
    gl::Program reachProgram_, markProgram_, compactProgram_; // band steps A, B, C
    gl::Program bandPassProgram_, bandExpandProgram_;         // passes over a tile list
    gl::Program clearProgram_; // the empty cell over a tile list (jfa_band_clear.comp.glsl)
    gl::Program viewProgram_;  // the view limit (jfa_band_view.comp.glsl)
    gl::Program frontProgram_; // a pass's tiles within the flood's front (jfa_band_front)
    std::unique_ptr<GlTileDilation> dilation_; // the view tiles widened into viewNear_
    const gl::Buffer* viewTiles_ = nullptr;
    gl::Buffer viewNear_;
    gl::Buffer tileReach_, maxReach_, flags_, seedList_;
    struct StageBandList {
        gl::Buffer tiles;    // packed tile coordinates (x | y << 16)
        gl::Buffer commands; // jfa_band_compact.comp.glsl's indirect commands
    };
    StageBandList stageBands_[2]; // per stage of a (at most two-stage) plan
    // The flood's front (jfa/Band.h): one flag per tile that has held a non-empty cell (the
    // seeds' tiles, then what the passes wrote), and each pass's tile list within it.
    gl::Buffer front_;
    StageBandList frontList_;
    bool frontEnabled_ = true;
    bool frontRun_ = false;    // this run's passes use the front (a one-stage plan on a band)
    glm::ivec2 frontTiles_{0}; // the run's tiles per axis
    /// Empties `list` for a grid of `tiles`: no tile, and with `texelsToo` no texel counted.
    void restartList(StageBandList& list, glm::ivec2 tiles, bool texelsToo);
    /// Before a run with the front, on a grid of `size`: the count of computed texels zeroed
    /// and the list program's grid set.
    void startFront(glm::ivec2 size);
    /// Lists the band tiles a pass of jump length `step` may change (frontList_).
    void listFront(int step);
    GLuint measuredSeeds_ = 0; // seeds texture step A last ran on (0: none pending)
    GLuint listedSeeds_ = 0;   // seeds texture whose seeds a producer listed (seedsListed)
    GLuint preparedSeeds_ = 0; // seeds texture prepareBand() built the band for
    bool preparedBanded_ = false;

  protected:
    /// prepareBand()'s work once the criterion's uniforms are set.
    void prepare(const Plan& plan, const gl::Texture& seeds) {
        preparedBanded_ = banded(region_) && buildBand(plan, seeds);
        preparedSeeds_ = seeds.id();
    }

  private:
    bool lastRunBanded_ = false;
    int bandStages_ = 0;    // stages of the last banded run
    double bandArea_ = 0.0; // its full-resolution texels
    gl::VertexArray emptyVao_;
    gl::Buffer changedCounter_;
    // What a ping-pong texture may hold besides the empty cell, so that a band run clears only
    // what an earlier run wrote: kDirtWhole (anything: a new texture, a full-grid pass, the
    // downsample), kDirtClean (nothing), or a stage index s: only the tiles of
    // stageBands_[s]'s current list (the band passes wrote nothing else).
    static constexpr int kDirtWhole = -2, kDirtClean = -1;
    struct Pair {
        gl::Texture tex[2];
        gl::Framebuffer fbo[2];
        int dirt[2] = {kDirtWhole, kDirtWhole};
    };
    /// Leaves pair texture `i` holding the empty cell everywhere, by the cheapest means its
    /// dirt allows; `stage` is the band stage about to be rebuilt for it.
    void emptyTexture(Pair& pair, int i, int stage);
    /// Notes what writing `dst` (a pair texture) left in it: band stage `bandStage` or, for -1,
    /// the whole texture.
    void noteWritten(const gl::Texture& dst, int bandStage);
    std::map<std::pair<int, int>, Pair> pairs_;
    int passesRun_ = 0;
};

/// Criteria whose GLSL also has the keyed form of jfa_select.glsl (jfaContext, jfaKey,
/// jfaTieWins): the kernels are built with JFA_KEYED, one key per candidate.
template <class C>
concept Keyed = requires {
    requires C::keyed;
};

namespace detail {
/// The define every program that writes a kernel's cells is built with: "JFA_CELL_FORMAT r32f"
/// for packed cells, else "JFA_CELL_FORMAT rgba32f".
std::string cellFormatDefine(bool packed);
} // namespace detail

/// Criteria whose cells the GL kernels store packed in one R32F texel (the GLSL's jfaLoad and
/// jfaStore unpack and pack them); the GL textures of their grids hold that form.
template <class C>
concept PackedCells = requires {
    requires C::packedCells;
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
        : GlFloodKernelBase(
              shaders, C::glslFile, kind, Keyed<C>, PackedCells<C>,
              [](gl::Program& p) { bindCriterionUniforms(p, static_cast<const C*>(nullptr)); }) {
        criterionBounds_ = Reaching<C>;
    }

    /// Band step A: the largest reach of any seed under `criterion` (what a pass count must
    /// cover), -1 without seeds, kUnboundedReach-ish (2^30 - 1) when unbounded. Reads one value
    /// back; the next run() on the same seeds reuses the step, unless `keep` is false (the count
    /// was measured under another criterion than the flood's: prepareBand / run measure again).
    long long maxSeedReach(const gl::Texture& seeds, const C& criterion, bool keep = true) {
        gl::BindScope scope;
        for (const gl::Program* p : criterionPrograms(true))
            setCriterionUniforms(scope, *p, criterion);
        measureReach(seeds);
        const long long reach = readMaxReach();
        if (!keep) forgetReach();
        return reach;
    }

    /// Builds the band for `plan` on `seeds` now (steps A-C, no read-back), so that it can be
    /// timed apart from the passes; the next run() with the same seeds uses it. Optional.
    void prepareBand(const Plan& plan, const gl::Texture& seeds, const C& criterion) {
        gl::BindScope scope;
        for (const gl::Program* p : criterionPrograms(banded(region())))
            setCriterionUniforms(scope, *p, criterion);
        prepare(plan, seeds);
    }

    /// Runs `plan` on full-resolution `seeds` (plan.width() x plan.height(), not modified);
    /// returns the full-resolution result, owned by the kernel until the next run. If `timer`
    /// is given, each pass is timed as "jfa step K", K the jump length (and "downsample").
    const gl::Texture& run(const Plan& plan, const gl::Texture& seeds, const C& criterion,
                           gl::PassTimer* timer = nullptr, const PassCallback& callback = {}) {
        gl::BindScope scope;
        for (const gl::Program* p : criterionPrograms(banded(region())))
            setCriterionUniforms(scope, *p, criterion);
        return runPlan(plan, seeds, timer, callback);
    }

    /// Convenience for tests and tools: upload, run, read back.
    Grid run(const Plan& plan, const Grid& seeds, const C& criterion) {
        const gl::Texture in = uploadGrid(seeds);
        return readGrid(run(plan, in, criterion));
    }
};

} // namespace fl::jfa
