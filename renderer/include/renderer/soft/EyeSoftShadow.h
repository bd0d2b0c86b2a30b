#pragma once
// JFA-E (thesis §5.4.1): soft shadows flooded in eye space from an image with hard shadows.
// The phases are the thesis' numbers (§5.4); its phase 1, the shadow map with receiver
// positions, is frame step 1, and phases 2-5 all run inside frame step 3 (the shadow method).
//   phase 2  per pixel of the frame's surfaces (step 2, SurfacesPass): its hard-shadow state
//            and its occluder (the surface the light's centre sees at the pixel's shadow-map
//            texel), packed in one 32-bit cell (EyeDecode.h) from which the pixel's world
//            position, the occluder point and its object id (from a light-space id pass over
//            the shadow map) decode;
//   phase 3  boundary pixels (in hard shadow, with a lit neighbour nearer than a 3D distance
//            threshold) become seeds carrying their occluder;
//   phase 4  jump flooding with EyeSoftCriterion (or standard flooding, the reference);
//   phase 5  composite: per pixel the intensity from its occluder, else 0 inside / 1 outside.
// The CPU functions are the references the GL passes are tested against.

#include <io/ImageIO.h>
#include <renderer/passes/ShadowMapPass.h>
#include <renderer/passes/SurfacesPass.h>
#include <renderer/scene/GpuScene.h>
#include <renderer/soft/EyeDecode.h>
#include <renderer/soft/OccluderEdge.h>
#include <renderer/soft/OccluderLines.h>
#include <renderer/soft/PenumbraReach.h>
#include <scene/DiskLight.h>

#include <jfa/Grid.h>
#include <jfa/Plan.h>

#include <gpu/Gl.h>
#include <gpu/PassTimer.h>
#include <gpu/Program.h>
#include <gpu/ShaderLibrary.h>
#include <jfa_gl/GlKernel.h>

#include <memory>

namespace fl {

struct CameraView;
class EyeFloodEstimator; // renderer/soft/EyeFloodReach.h

/// How `--jfa-passes auto` chooses JFA-E's (and flood-E's) count (--auto-passes).
enum class EyeAutoPasses {
    Measured,  // how far a coarse flood's cells travel (EyeFloodReach.h), capped by Geometric
    Geometric, // the widest penumbra any seed's occluder could cast (an upper bound; measured is
               // tighter)
};

/// Switches and thresholds of JFA-E / flood-E (the pass count is PenumbraSettings::passes).
struct EyeSoftSettings {
    /// Thesis §5.4.2, first fix: an occluder floods into a hard-shadowed pixel only if that
    /// pixel's own occluder belongs to the same object (lit pixels have no occluder).
    bool objectIdFix = true;
    /// Thesis §5.4.2, second fix: the pixel midway between the occluder's boundary pixel and
    /// the pixel must itself get a penumbra intensity from the occluder.
    bool midpointFix = true;
    /// Boundary test (phase 3): a lit neighbour counts if nearer in 3D than this many world
    /// units; 0 = kBoundaryFootprints pixel footprints at the pixel's distance from the eye.
    float boundaryThreshold = 0.0f;
    /// Where a boundary pixel's occluder point lies (OccluderEdge.h): at the shadow map's
    /// silhouette edge, or the thesis' texel centre.
    OccluderPoints occluderPoints = OccluderPoints::Edge;
    /// Depth jump that makes a silhouette edge (silhouetteThreshold(scene radius)).
    float silhouetteThreshold = 1e-3f;
    /// The rule of `--jfa-passes auto` (Inputs::passes 0).
    EyeAutoPasses autoPasses = EyeAutoPasses::Measured;
};

/// Footprints of the automatic boundary threshold: wide enough for a floor seen at ~80 degrees
/// from its normal, narrow enough to exclude the depth jump to an object in front.
inline constexpr float kBoundaryFootprints = 6.0f;

/// The boundary threshold as shader terms: a lit neighbour at squared distance d2 counts when
/// d2 < absolute2 + relative2 * |p - eye|^2.
struct BoundaryThreshold {
    float absolute2 = 0.0f;
    float relative2 = 0.0f;
};
/// Resolves settings.boundaryThreshold for a camera and frame height.
BoundaryThreshold boundaryThreshold(const EyeSoftSettings& settings, const glm::mat4& proj,
                                    int height);
/// Sets jfae_boundary.frag.glsl's own uniforms: the eye, the threshold, whether the pass
/// lists its seeds (the frame's boundaries and EyeFloodEstimator's coarse ones alike) and, with
/// `walkLight`, that seeds' occluders walk to the silhouette (boundaryOccluderPoint) under that
/// light and silhouette threshold; without, they stay phase 2's.
void setBoundaryUniforms(const gl::Program& program, glm::vec3 eye, BoundaryThreshold th,
                         bool listSeeds, const DiskLight* walkLight = nullptr,
                         float silhouetteThreshold = 0.0f);
/// Binds what a jfae_boundary program is set with: its own uniforms and the eye cells'.
void bindBoundaryUniforms(gl::Program& program);

/// The most JFA passes a width x height frame can use: log2(max(width, height)), rounded down.
int eyeSoftMaxPasses(int width, int height);

/// The flooding plan for a width x height frame: JFA with steps 2^(passes-1) .. 1, or with
/// `standardFlooding` 2^passes - 1 step-1 passes. Throws std::invalid_argument when passes is
/// outside [1, log2(max(width, height))] or the frame has 2^24 pixels or more (seed pixel
/// indices must be exact in a float).
jfa::Plan eyeSoftPlan(int passes, bool standardFlooding, int width, int height);

/// What phase 3 walks a seed's occluder to the silhouette with (jfae_boundary.frag.glsl's
/// boundaryOccluder): the frame's packed cells (EyeCells::words), the map's decoded receivers,
/// the light and the silhouette threshold.
struct BoundaryWalk {
    const std::vector<std::uint32_t>& cells;
    const ReceiverGrid& receivers;
    DiskLight light;
    float threshold = 0.0f;
};

/// The occluder point of boundary pixel (x, y) of a width-wide frame whose nearest lit neighbour
/// is (qx, qy): from its texel, walked toward the neighbour's along the map while the surface
/// continues, then moved to the edge (occluderEdgePoint). The GLSL says why.
glm::vec3 boundaryOccluderPoint(const BoundaryWalk& walk, int width, int x, int y, int qx, int qy);

/// CPU reference of phase 3 (shaders/jfae_boundary.frag.glsl): boundary pixels become cells
/// (occluder xyz, w = seed pixel index + 1); others are jfa::kEmptyCell. With `walk`, the
/// occluders are walked to the silhouette (edge points on the frame's grid); without, phase 2's.
jfa::Grid eyeBoundarySeeds(const EyeImage& image, glm::vec3 eye, BoundaryThreshold threshold,
                           const BoundaryWalk* walk = nullptr);

/// The flooding criterion of JFA-E: the CPU functor here, shaders/jfae_criterion.glsl for the
/// GL kernel (bit for bit the same). See the GLSL file for the rule.
struct EyeSoftCriterion {
    static constexpr const char* glslFile = "jfae_criterion.glsl";
    static constexpr bool keyed = true; // the GLSL has jfaKey (jfa_select.glsl)
    /// GL grids hold a cell as its w alone (R32F; jfaLoad takes the occluder from the
    /// occluders texture at the seed pixel): readEyeGrid turns one back into cells.
    static constexpr bool packedCells = true;
    DiskLight light;
    bool objectIdFix = true;
    bool midpointFix = true;
    const EyeImage* image = nullptr; // CPU kernel
    const EyeCells* cells = nullptr; // GL kernel: phase 2's packed cells (eye_decode.glsl)
    int cellsFactor = 1;             // GL kernel: the grid is the frame / this (EyeCells::bind)
    PenumbraReach reachBound;        // the eye's: bounds the band (jfa/Band.h)

    /// Band-limited flooding: the widest penumbra occluder c, seeded at boundary pixel (px, py),
    /// can cast in the image.
    [[nodiscard]] jfa::ReachRect reach(int, int, const jfa::Cell& c) const {
        return penumbraReachRect(light, reachBound, {c.x, c.y, c.z});
    }

    [[nodiscard]] bool empty(const jfa::Cell& c) const { return c.w == 0.0f; }
    [[nodiscard]] bool accepts(int px, int py, const jfa::Cell& c) const;
    [[nodiscard]] bool better(int px, int py, const jfa::Cell& a, const jfa::Cell& b) const;
};
/// The GL kernel's hook (argument-dependent lookup): the eye cells (EyeCells::bind) and reach
/// bounds in the run's `scope`, uniforms.
void setCriterionUniforms(gl::BindScope& scope, const gl::Program& program,
                          const EyeSoftCriterion& criterion);
/// Binds the uniforms setCriterionUniforms sets on a kernel program (the pointer only chooses
/// the overload).
void bindCriterionUniforms(gl::Program& program, const EyeSoftCriterion*);

/// A JFA-E grid as the GL kernels store it (R32F, packed cells: the seed pixel's index + 1, 0
/// empty; EyeSoftCriterion::packedCells) turned back into cells, each occluder read from
/// `occluders` (phase 2's, jfa::readGrid of EyeImage::occluders) at its seed pixel: jfaLoad's
/// CPU twin.
jfa::Grid readEyeGrid(const gl::Texture& packed, const jfa::Grid& occluders);

/// What phase 5 reads for the occluders' edges (--occluder-points edge): the shadow map, each
/// pixel's receiver plane (surfacePlane) and its eye cell (EyeCells::words), in EyeImage's
/// layout.
struct CompositeEdges {
    const LineMap& map;
    const std::vector<glm::vec3>& planes;
    const std::vector<std::uint32_t>& cells;
};

/// CPU reference of phase 5 (shaders/jfae_composite.frag.glsl): one visibility per pixel; with
/// `edges`, from the occluders' edges (occluder_lines.glsl), else the thesis' points. Uses
/// std::acos, so equal to the GL result only to float rounding (~1e-6) with points; with edges
/// the fits' atan, cos and sin differ more, and the map's tests may decide otherwise at a
/// rounding boundary.
FloatImage eyeSoftVisibility(const EyeImage& image, const jfa::Grid& flooded,
                             const DiskLight& light, const CompositeEdges* edges = nullptr);

/// The technique's phases 2-5 on the GPU, inside frame step 3. Phase 1 (the shadow map with
/// receiver positions) is the caller's frame step 1; the result is the method's visibility.
class EyeSoftShadowPass {
  public:
    explicit EyeSoftShadowPass(const gl::ShaderLibrary& shaders);
    ~EyeSoftShadowPass();
    EyeSoftShadowPass(const EyeSoftShadowPass&) = delete;
    EyeSoftShadowPass& operator=(const EyeSoftShadowPass&) = delete;

    struct Inputs {
        const GpuScene& scene; // drawn from the light for the object ids
        const CameraView& camera;
        SurfacePositions positions;           // the frame's surfaces (SurfacesPass)
        const gl::Texture& normals;           // their normals (SurfacesPass; surfacePlane)
        const gl::Texture& lift;              // their lift (SurfacesPass; surface_lookup.glsl)
        const ShadowMapPass::Outputs& shadow; // phase 1 (frame step 1), made with writeReceivers
        const ShadowMapSettings& shadowSettings;
        const DiskLight& light;
        const EyeSoftSettings& settings;
        int passes;            // PenumbraSettings::passes (capped at eyeSoftMaxPasses); 0: auto
        bool standardFlooding; // flood-E
        int width, height;     // frame size
        jfa::FloodRegion region = jfa::FloodRegion::Band; // jfa/Band.h: the same result
        PenumbraReach reach = {}; // the image's penumbra bound (band and auto passes)
        int bandTile = jfa::kDefaultBandTile;
    };
    struct Outputs {
        const EyeCells& eye;           // phase 2, packed cells (R32UI, EyeDecode.h)
        const gl::Texture& seeds;      // phase 3, packed cells (R32F, readEyeGrid)
        const gl::Texture& flooded;    // phase 4, packed cells (R32F, readEyeGrid)
        const gl::Texture& visibility; // phase 5, R32F
        int passes;                    // flood passes run
        int jfaPasses;                 // the JFA pass count used (auto resolved)
        /// Auto only: the geometric bound's count, and the measured one (-1 when not measured).
        int geometricPasses = -1, measuredPasses = -1;
    };
    /// Runs phases 2-5; `timer` (optional) times them as "occluder ids", "eye hard shadows",
    /// "boundaries", "pass count" (measured auto only), "band", "flood" and "composite".
    Outputs execute(const Inputs& in, gl::PassTimer* timer = nullptr);

    /// The last frame's eye cells decoded on the GPU into EyeImage layout (points, occluders;
    /// RGBA32F): EyeCells::decoded(). Made on the first call after each frame.
    [[nodiscard]] std::pair<const gl::Texture&, const gl::Texture&> decodedEyeImage() const;

  private:
    void prepare(const Inputs& in); // checks the map size, sizes the targets, sets eye_
    void resize(int width, int height, int shadowSize);
    void drawOccluderIds(const Inputs& in);                           // phase 2a
    void drawEyeHardShadows(const Inputs& in);                        // phase 2
    void drawBoundaries(const Inputs& in, BoundaryThreshold th);      // phase 3
    void drawComposite(const Inputs& in, const gl::Texture& flooded); // phase 5
    /// The measured auto count (EyeFloodReach.h) at most maxPasses; -1 for a frame too small.
    int measurePasses(const Inputs& in, BoundaryThreshold threshold, int maxPasses);

    // composite_ gives every pixel its thesis value and marks where the edges recompute it
    // (mask_); compositeEdges_ runs there (shaders/jfae_composite.frag.glsl).
    gl::Program lightIds_, eyePass_, boundary_, composite_, compositeEdges_, unpack_;
    gl::VertexArray emptyVao_;
    gl::Texture ids_, cells_, seeds_, seedOccluders_, visibility_, mask_;
    gl::Framebuffer eyeFbo_, seedsFbo_, visibilityFbo_;
    EyeCells eye_; // the last frame's, for the phases and the Outputs
    // decodedEyeImage()'s: made on demand, outside the frame.
    mutable gl::Texture decodedPoints_, decodedOccluders_;
    mutable gl::Framebuffer decodedFbo_;
    mutable bool decodedStale_ = true;
    jfa::GlFloodKernel<EyeSoftCriterion> kernel_;
    ReceiverBoundsPyramid bounds_; // tightens the band's bound (PenumbraReach)
    const gl::ShaderLibrary& shaders_;
    std::unique_ptr<EyeFloodEstimator> estimator_; // built at the first measured auto count

  public:
    /// The flood's kernel (its region and the last run's active share).
    [[nodiscard]] const jfa::GlFloodKernelBase& kernel() const { return kernel_; }
};

} // namespace fl
