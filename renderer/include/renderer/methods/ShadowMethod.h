#pragma once
// Step 3 of a frame: a shadow method turns the frame's inputs (the shadow map of step 1 and the
// surfaces of step 2) into a visibility texture. Shading (step 4) and the metrics are shared, so
// a method computes visibility only.
//
// Every method is one class behind this interface (one file each in renderer/src/methods/) and
// one row of the descriptor table (MethodTable.cpp). The CLI, capture scripts, `compare`, the
// viewer, the overlays, the HUD and the benchmarks read the table; adding a method is one file
// plus one row.

#include <gpu/Gl.h>
#include <gpu/PassTimer.h>
#include <gpu/ShaderLibrary.h>
#include <jfa/Band.h>
#include <jfa/Plan.h>
#include <jfa_gl/GlKernel.h>
#include <renderer/methods/MethodOptions.h>
#include <renderer/passes/ShadowMapPass.h>
#include <renderer/passes/SurfacesPass.h>
#include <renderer/scene/GpuScene.h>
#include <renderer/soft/PenumbraReach.h>
#include <scene/DiskLight.h>
#include <scene/Scene.h>

#include <base/Aabb.h>
#include <base/Framing.h>

#include <any>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fl {

struct EyeCells;     // renderer/soft/EyeDecode.h
struct FloodOptions; // renderer/methods/OptionStructs.h

struct MethodDescriptor;

/// Everything a method may read in a frame.
struct FrameInputs {
    const GpuScene& scene;
    const CameraView& camera;
    const Light& light;
    const DiskLight& disk;
    const geom::Aabb& sceneBounds;
    const geom::Aabb& casterBounds;      // what casts shadows (shadowCasterBounds, scene/Camera.h)
    const geom::ViewVolume& lightVolume; // the volume the shadow map was made with
    const ShadowMapSettings& shadowSettings;
    const ShadowMapPass::Outputs& shadow;  // step 1
    const SurfacesPass::Outputs& surfaces; // step 2
    const MethodDescriptor& method;        // this method's table row
    const std::any& parsedOptions;         // its options struct (the row's options.parse())
    gl::PassTimer* timer = nullptr;        // times the method's phases (the row's names)
    const std::function<void(double)>* progress = nullptr; // RenderSettings::progress, if set

    /// This method's options struct (renderer/methods/OptionStructs.h); std::bad_any_cast when
    /// S is not its row's.
    template <class S>
    [[nodiscard]] const S& options() const {
        return std::any_cast<const S&>(parsedOptions);
    }
    [[nodiscard]] int width() const { return surfaces.width; }
    [[nodiscard]] int height() const { return surfaces.height; }
};

struct FloodFrame;

/// What differs between the spaces a flood runs in (light: the shadow map's grid, JFA-L and
/// flood-L; eye: the frame's pixels, JFA-E and flood-E): how its cells unpack and draw, how it
/// plans and re-runs a flood. A flooding method's FloodFrame points to its space, so that the
/// overlays draw any flood through it without asking which space it is.
class FloodSpace {
  public:
    virtual ~FloodSpace() = default;
    /// Where the overlays place the flood's grid in a frame: the whole frame (a grid of its
    /// pixels) or the centred square (the shadow map's grid).
    enum class Placement { WholeFrame, CentredSquare };
    [[nodiscard]] virtual Placement placement() const = 0;
    /// `frame`'s flood plan at its pass count, with JFA or standard flooding.
    [[nodiscard]] virtual jfa::Plan plan(const FloodFrame& frame, bool standardFlooding) const = 0;
    /// Runs `plan` on `frame`'s seeds with its criterion, flood region and penumbra bound (an
    /// overlay's re-run: pass by pass, or the other flooding); the texture is this space's own
    /// kernel's, valid until the next call.
    virtual const gl::Texture& rerun(const FloodFrame& frame, const jfa::Plan& plan,
                                     const DiskLight& light) const = 0;
    /// The texture that unpacks `frame`'s packed cells (read back once by FloodGridReader).
    [[nodiscard]] virtual const gl::Texture& unpackSource(const FloodFrame& frame) const = 0;
    /// `grid`'s cells unpacked with `source` (unpackSource() read back).
    [[nodiscard]] virtual jfa::Grid unpack(const gl::Texture& grid,
                                           const jfa::Grid& source) const = 0;
    /// The decoded positions an occluder grid's picture is coloured with, and whether they are
    /// the eye's points (GridDraw::eyeSpace) rather than the map's receivers.
    [[nodiscard]] virtual const gl::Texture& occluderPositions(const FloodFrame& frame) const = 0;
    [[nodiscard]] virtual bool positionsAreEyePoints() const = 0;
    /// Captions: "silhouette seeds (light space, JFA-L phase 2)", "penumbra map (JFA-L)", and
    /// the seeds' kind ("silhouette").
    [[nodiscard]] virtual std::string_view seedsCaption() const = 0;
    [[nodiscard]] virtual std::string_view floodCaption() const = 0;
    [[nodiscard]] virtual std::string_view seedKind() const = 0;
    /// Appends to `key` what a re-run depends on besides the seeds, views, light and plan (an
    /// overlay's cache key): the space and its criterion's switches.
    virtual void appendKey(const FloodFrame& frame, std::vector<float>& key) const = 0;
};

/// What a flooding method (JFA-L/E and their standard-flooding references) keeps of its last
/// frame, the typed view the overlays re-run and draw: its textures, plan, region and kernel,
/// the criterion's inputs, and its space (what differs between light and eye).
struct FloodFrame {
    const gl::Texture* seeds = nullptr;
    const gl::Texture* flooded = nullptr;
    const FloodSpace* space = nullptr;
    bool standardFlooding = false;
    int passes = 0;                                   // flood passes run
    jfa::FloodRegion region = jfa::FloodRegion::Full; // --flood-region
    PenumbraReach reach;                              // the criterion's band bound
    const jfa::GlFloodKernelBase* kernel = nullptr;   // ran the flood (activeShare())
    const EyeCells* eyeCells = nullptr; // eye only: phase 2's packed cells (EyeDecode.h)
    bool objectIdFix = true;            // eye only: the criterion's switches
    bool midpointFix = true;
    const MapPositions* map = nullptr; // light only: the shadow map's receiver target
    float umbraDepth = 0.0f; // light only: PenumbraCriterion::umbraDepth (--penumbra both)
};

/// Reads `frame`'s grids (its seeds, its flood, or an overlay's re-run of it) back as cells. The
/// GPU's cells are packed; they unpack with the texture its space names (FloodSpace::
/// unpackSource: eye cells with phase 2's occluders, light cells with the map's positions, as
/// the GPU decodes them), read back once, when the reader is made, for every grid it then reads.
class FloodGridReader {
  public:
    explicit FloodGridReader(const FloodFrame& frame);
    [[nodiscard]] jfa::Grid read(const gl::Texture& grid) const;

  private:
    const FloodSpace* space_;
    jfa::Grid source_;
};

/// One grid of `frame` as cells: FloodGridReader(frame).read(grid).
jfa::Grid readFloodGrid(const FloodFrame& frame, const gl::Texture& grid);

class ShadowMethod {
  public:
    virtual ~ShadowMethod() = default;
    ShadowMethod() = default;
    ShadowMethod(const ShadowMethod&) = delete;
    ShadowMethod& operator=(const ShadowMethod&) = delete;

    /// (Re)allocates what depends on the frame size; execute() calls it when the size changes.
    virtual void resize(int width, int height) = 0;
    /// Step 3: the visibility of every pixel of the frame (R32F; 1 lit, 0 shadowed; any value
    /// on background, which the shading pass ignores). Throws std::invalid_argument for options
    /// it cannot use, fl::gl::GlError on GL errors.
    virtual const gl::Texture& execute(const FrameInputs& in) = 0;
    /// The last frame's flood (flooding methods), else nullptr.
    [[nodiscard]] virtual const FloodFrame* flood() const { return nullptr; }
};

/// Where a method works: on the light's shadow map (filtered or flooded in light space), or on
/// the eye's pixels (flooded in eye space).
enum class MethodSpace { Light, Eye };

/// One row of the method table.
struct MethodDescriptor {
    std::string_view name;      // as the CLI and scripts spell it: "jfa-l"
    std::string_view help;      // one line
    std::string_view reference; // its standard-flooding reference ("" none): "flood-l"
    MethodSpace space = MethodSpace::Light;
    MethodOptionSet options;                  // what it takes, in --help order, and its struct
    std::span<const std::string_view> phases; // its timed phase names, in frame order
    bool cycles = true;                       // the window's M key steps through it
    bool shadowMapPositions = false;          // needs the shadow map's receiver positions (step 1)
    bool floods = false;                      // a flooding method: passes and FloodFrame
    std::unique_ptr<ShadowMethod> (*make)(const gl::ShaderLibrary&) = nullptr;
    /// Checks the options for a frame before any rendering; throws std::invalid_argument with the
    /// option's flag and the valid range. Null: nothing to check beyond each option's range.
    void (*check)(const MethodOptions&, const MethodDescriptor&, int mapSize, int width,
                  int height) = nullptr;
    /// A ground truth (what the others are measured against): the kind capture scripts name it
    /// by ("maps", "raytrace"); "" for the methods being measured.
    std::string_view truth = {};
    /// A ground truth's options in words, for capture's log and report ("256 point-light shadow
    /// maps of 2048^2 (spiral)"); null for the methods being measured.
    std::string (*describe)(const MethodOptions&) = nullptr;
    /// The cheapest method, every frame-time ratio's denominator ("x hard" in the tables).
    bool cheapest = false;

    /// The row's option with capture-script key `key`, or nullptr.
    [[nodiscard]] const MethodOption* option(std::string_view key) const;
    /// True when the row declares an option with CLI flag `flag`.
    [[nodiscard]] bool takesFlag(std::string_view flag) const;
};

/// The ground truth of kind `kind` ("maps": N point-light shadow maps; "raytrace": shadow rays);
/// throws std::invalid_argument listing the kinds.
const MethodDescriptor& groundTruth(std::string_view kind);
/// The ground truths' kinds, "|"-separated, in table order.
std::string groundTruthKinds();
/// The ground truth every figure is measured against unless asked otherwise: the exact one.
inline constexpr std::string_view kExactTruth = "raytrace";
/// The ground truth a capture script gets when it names none: the shadow maps (on the GPU, the
/// faster of the two on this machine).
inline constexpr std::string_view kCaptureTruth = "maps";

/// The row marked cheapest (hard shadows): what the frame-time ratios divide by.
const MethodDescriptor& cheapestMethod();

/// The table: every method, in the order the window cycles through them.
std::span<const MethodDescriptor> methodTable();
/// The row named `name`, or nullptr.
const MethodDescriptor* findMethod(std::string_view name);
/// The row named `name`; throws std::invalid_argument listing the valid names.
const MethodDescriptor& methodOrThrow(std::string_view name);
/// Every method name, separated by `separator`.
std::string methodNames(std::string_view separator = ", ");
/// The names of the methods for which `pred` holds, ", "-separated, in table order (for messages
/// such as "only pcf takes --pcf-kernel").
std::string methodNamesWhere(const std::function<bool(const MethodDescriptor&)>& pred);
/// Every option of the table once (by flag), in table order.
std::vector<const MethodOption*> allMethodOptions();
/// The pass-count option every flooding method takes (--jfa-passes; the window's -/= keys and the
/// capture scripts' "jfaPasses" set it).
const MethodOption& floodPassesOption();
/// The option that chooses band-limited or full-grid flooding (--flood-region).
const MethodOption& floodRegionOption();
/// jfa-l's and flood-l's --penumbra: which halves of each penumbra they compute.
const MethodOption& penumbraSidesOption();
/// Whether --penumbra is both (the umbra side too) rather than outer (the thesis' lit side).
bool penumbraBothSides(const MethodOptions& options);
/// requestedPasses() for --jfa-passes auto: the method chooses per frame (passesForReach).
inline constexpr int kAutoPasses = 0;
/// The flood pass count a flooding method's options ask for at this map and frame size (what
/// --jfa-passes, --full-jfa mean for it), kAutoPasses for auto; 0 for the other methods.
int requestedPasses(const MethodDescriptor& m, const MethodOptions& options, int mapSize, int width,
                    int height);
/// The same from a flooding method's parsed options.
int requestedPasses(MethodSpace space, const FloodOptions& flood, int mapSize, int width,
                    int height);

} // namespace fl
