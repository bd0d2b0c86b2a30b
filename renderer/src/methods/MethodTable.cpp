// The method table: one row per shadow method. Everything that lists, parses, pairs, cycles or
// times methods reads these rows (renderer/methods/ShadowMethod.h).

#include <renderer/methods/OptionStructs.h>
#include <renderer/methods/ShadowMethod.h>
#include <renderer/passes/Phases.h>
#include <renderer/soft/EyeSoftShadow.h>
#include <renderer/soft/FilteredShadow.h>
#include <renderer/soft/PenumbraMap.h>

#include <raytrace/ShadowRays.h>

#include <base/Text.h>

#include <array>
#include <stdexcept>

namespace fl {

using gl::ShaderLibrary;

// Each method's factory, defined in its own file (renderer/src/methods/NAME.cpp).
std::unique_ptr<ShadowMethod> makeHard(const ShaderLibrary&);
std::unique_ptr<ShadowMethod> makeJfaL(const ShaderLibrary&);
std::unique_ptr<ShadowMethod> makeFloodL(const ShaderLibrary&);
std::unique_ptr<ShadowMethod> makeJfaE(const ShaderLibrary&);
std::unique_ptr<ShadowMethod> makeFloodE(const ShaderLibrary&);
std::unique_ptr<ShadowMethod> makePcf(const ShaderLibrary&);
std::unique_ptr<ShadowMethod> makePcss(const ShaderLibrary&);
std::unique_ptr<ShadowMethod> makeGroundTruth(const ShaderLibrary&);
std::unique_ptr<ShadowMethod> makeVsm(const ShaderLibrary&);

// The options of a method that declares them in its own file (its options struct, each option's
// flag, key, range, default and help, and the fields binding them): a new method with options of
// its own is its file and its row below.
extern const MethodOptionSet kVsmOptions;
std::unique_ptr<ShadowMethod> makeRayTrace(const ShaderLibrary&);

namespace {

// --- Options (each declared once; rows list the ones they take) ---------------------------------

constexpr MethodOption kPasses{
    "--jfa-passes",
    "passes",
    OptionKind::Int,
    "auto",
    "Flooding passes: penumbrae up to 2^N - 1 shadow-map texels (-l) or pixels (-e) wide; 1 to "
    "log2(size), or auto: the fewest that cover the widest penumbra the frame's occluders can "
    "cast (jfa-e, flood-e: how far they travel, --auto-passes)",
    1,
    13,
    {},
    "auto"};
constexpr MethodOption kFloodRegion{
    "--flood-region",
    "floodRegion",
    OptionKind::Choice,
    "view",
    "view: jfa-l, flood-l find silhouettes and flood only around what the eye's pixels read "
    "(the picture of full at the same passes, pixel for pixel; the penumbra map is exact only "
    "there, so the overlays that show the map flood the band; auto counts only the penumbrae "
    "that can reach the view, so it may take fewer passes than band); jfa-e, flood-e flood the "
    "band; band: flood only the tiles the occluders' penumbrae can reach (the same result as "
    "full, texel for texel); full: every texel of the grid",
    0,
    0,
    "view|band|full"};
constexpr MethodOption kFullJfa{
    "--full-jfa", "fullJfa", OptionKind::Flag, "false",
    "Full JFA: as many passes as the grid allows (log2 of the shadow-map size for -l, of the "
    "frame for -e), instead of --jfa-passes"};
constexpr MethodOption kBandTile{
    "--band-tile",
    "bandTile",
    OptionKind::Int,
    "8",
    "Tile side of --flood-region band, in texels (a multiple of 8); the band is the tiles the "
    "penumbrae can reach",
    jfa::kMinBandTile,
    jfa::kMaxBandTile,
    {},
    {},
    8};
constexpr MethodOption kPenumbraSides{
    "--penumbra",
    "penumbra",
    OptionKind::Choice,
    "both",
    "Which half of each penumbra the penumbra map holds: both = the lit side and the umbra side "
    "(a point just inside the hard shadow sees part of the disk, 0.5 at the hard edge); outer = "
    "the lit side only, as in the thesis (section 5.3: the shadow is dark right from the hard "
    "edge)",
    0,
    0,
    "outer|both"};
constexpr MethodOption kNoObjectIdFix{
    "--no-object-id-fix", "noObjectIdFix", OptionKind::Flag, "false",
    "Let occluders flood into the hard shadows of other objects (thesis 5.4.2, first "
    "jump-too-far fix off)"};
constexpr MethodOption kNoMidpointFix{
    "--no-midpoint-fix", "noMidpointFix", OptionKind::Flag, "false",
    "No midpoint continuity check (thesis 5.4.2, second jump-too-far fix off)"};
constexpr MethodOption kBoundaryThreshold{
    "--boundary-threshold",
    "boundaryThreshold",
    OptionKind::Float,
    "0",
    "Largest 3D distance from a shadowed boundary pixel to its lit neighbour, in scene units; "
    "0 = 6 pixel footprints",
    0.0,
    1e6};
constexpr MethodOption kOccluderPoints{
    "--occluder-points",
    "occluderPoints",
    OptionKind::Choice,
    "edge",
    "Where a shadowed pixel's occluder point lies: edge = moved half a shadow-map texel toward "
    "the silhouette's edge (halves the lit-side bias on straight edges); centre = the occluder "
    "texel's centre (the thesis; penumbrae come out about 0.04 too bright)",
    0,
    0,
    "edge|centre"};
constexpr MethodOption kAutoPassRule{
    "--auto-passes",
    "autoPasses",
    OptionKind::Choice,
    "measured",
    "How --jfa-passes auto chooses jfa-e's and flood-e's count: measured = the fewest that cover "
    "how far the occluders travel in a quarter-resolution flood of the frame, capped by "
    "geometric; geometric = the fewest that cover the widest penumbra any boundary seed's "
    "occluder can cast (an upper bound: 9-10 passes at 512^2 where 6 give the same "
    "picture)",
    0,
    0,
    "measured|geometric"};
constexpr MethodOption kPcfKernel{
    "--pcf-kernel",
    "kernel",
    OptionKind::Int,
    "3",
    "Taps per side of the kernel (N x N depth comparisons one uniform-map texel apart, in the "
    "light's unwarped plane)",
    1,
    kMaxPcfKernel,
    {},
    {},
    0,
    "3x3=3|5x5=5"};
constexpr MethodOption kPcssPreset{"--pcss-preset",
                                   "preset",
                                   OptionKind::Choice,
                                   "16/24",
                                   "Blocker-search/filter samples",
                                   0,
                                   0,
                                   "16/16|16/24|32/64",
                                   {},
                                   0,
                                   "*"};
constexpr MethodOption kReferenceSamples{"--reference-samples",
                                         "samples",
                                         OptionKind::Int,
                                         "256",
                                         "Point lights (shadow maps) over the disk light",
                                         1,
                                         65536};
constexpr MethodOption kReferenceMapSize{"--reference-map-size",
                                         "mapSize",
                                         OptionKind::Int,
                                         "2048",
                                         "Texels per side of each point light's shadow map",
                                         16,
                                         8192};
constexpr MethodOption kReferencePattern{
    "--reference-pattern",
    "pattern",
    OptionKind::Choice,
    "spiral",
    "Where the point lights sit on the disk: spiral = Vogel's golden-angle spiral (every straight "
    "edge splits it evenly); grid = the stratified grid's cell centres (bands along edges parallel "
    "to its rows); jittered = one fixed random point per cell",
    0,
    0,
    "spiral|grid|jittered"};

constexpr MethodOption kRaySamples{"--raytrace-samples",
                                   "samples",
                                   OptionKind::Int,
                                   "256",
                                   "Shadow rays per pixel to stratified points of the disk light",
                                   rt::kMinSamples,
                                   rt::kMaxSamples};
constexpr MethodOption kRayGrid{
    "--raytrace-grid", "grid", OptionKind::Flag, "false",
    "Rays to the strata's centres, the same points for every pixel (as the shadow-map reference "
    "places its lights with --reference-pattern grid; bands along straight edges), instead of one "
    "random point per stratum"};
constexpr MethodOption kTerminatorOffset{
    "--terminator-offset",
    "terminatorOffset",
    OptionKind::Choice,
    "on",
    "on: the smooth surface the vertex normals describe decides which light a pixel faces, and "
    "a ray that grazes its triangle or that surface starts on the smooth surface (Hanika 2021, "
    "by Cycles' Geometry Offset amount: the shadow terminator of low-poly objects); off: the "
    "flat triangle decides and every ray starts on it (dark wherever a triangle faces away from "
    "the light). Flat triangles are the same either way",
    0,
    0,
    "on|off"};
// --- Each method's options struct, field by field (OptionStructs.h) ----------------------------

// Choices as their types; the text is validated before it gets here.
jfa::FloodRegion floodRegionNamed(std::string_view text) {
    return *jfa::parseFloodRegion(text);
}
bool penumbraIsBoth(std::string_view text) {
    return text == "both";
}
bool terminatorOffsetOn(std::string_view text) {
    return text == "on";
}
OccluderPoints occluderPointsNamed(std::string_view text) {
    return text == "centre" ? OccluderPoints::TexelCentre : OccluderPoints::Edge;
}
EyeAutoPasses autoPassRuleNamed(std::string_view text) {
    return text == "geometric" ? EyeAutoPasses::Geometric : EyeAutoPasses::Measured;
}
PcssPreset pcssPresetNamed(std::string_view text) {
    return parsePcssPreset(text).value_or(PcssPreset{});
}

// The flooding methods' shared fields, at `S::flood`.
template <class S>
constexpr std::array<OptionField, 4> floodFields() {
    return {field<&S::flood, &FloodOptions::passes>(kPasses),
            field<&S::flood, &FloodOptions::fullJfa>(kFullJfa),
            parsedField<floodRegionNamed, &S::flood, &FloodOptions::region>(kFloodRegion),
            field<&S::flood, &FloodOptions::bandTile>(kBandTile)};
}
template <std::size_t N, std::size_t M>
constexpr std::array<OptionField, N + M> joinFields(const std::array<OptionField, N>& a,
                                                    const std::array<OptionField, M>& b) {
    std::array<OptionField, N + M> out{};
    for (std::size_t i = 0; i < N; ++i) out[i] = a[i];
    for (std::size_t i = 0; i < M; ++i) out[N + i] = b[i];
    return out;
}

using LightFlood = LightFloodOptions; // short names for the two field lists below
using EyeFlood = EyeFloodOptions;
constexpr auto kLightFloodFields =
    joinFields(floodFields<LightFlood>(),
               std::array{parsedField<penumbraIsBoth, &LightFlood::bothSides>(kPenumbraSides)});
constexpr auto kEyeFloodFields = joinFields(
    floodFields<EyeFlood>(),
    std::array{field<&EyeFlood::noObjectIdFix>(kNoObjectIdFix),
               field<&EyeFlood::noMidpointFix>(kNoMidpointFix),
               field<&EyeFlood::boundaryThreshold>(kBoundaryThreshold),
               parsedField<occluderPointsNamed, &EyeFlood::occluderPoints>(kOccluderPoints),
               parsedField<autoPassRuleNamed, &EyeFlood::autoPasses>(kAutoPassRule)});
constexpr OptionField kPcfFields[] = {field<&PcfOptions::kernel>(kPcfKernel)};
constexpr OptionField kPcssFields[] = {
    parsedField<pcssPresetNamed, &PcssOptions::preset>(kPcssPreset)};
constexpr OptionField kGroundTruthFields[] = {
    field<&GroundTruthOptions::samples>(kReferenceSamples),
    field<&GroundTruthOptions::mapSize>(kReferenceMapSize),
    parsedField<geom::diskPatternNamed, &GroundTruthOptions::pattern>(kReferencePattern)};
constexpr OptionField kRayTraceFields[] = {
    field<&RayTraceOptions::samples>(kRaySamples), field<&RayTraceOptions::grid>(kRayGrid),
    parsedField<terminatorOffsetOn, &RayTraceOptions::terminatorOffset>(kTerminatorOffset)};

// --- Timed phases (step 3's parts, as PassTimer names them) ------------------------------------

constexpr std::string_view kHardPhases[] = {phase::kHardShadows};
constexpr std::string_view kLightFloodPhases[] = {phase::kView, phase::kSilhouettes, phase::kBand,
                                                  phase::kFlood, phase::kPenumbraLookup};
constexpr std::string_view kEyeFloodPhases[] = {
    phase::kOccluderIds, phase::kEyeHardShadows, phase::kBoundaries, phase::kPassCount,
    phase::kBand,        phase::kFlood,          phase::kComposite};
constexpr std::string_view kPcfPhases[] = {phase::kPcfFilter};
constexpr std::string_view kPcssPhases[] = {phase::kBlockerSearchFilter};
constexpr std::string_view kGroundTruthPhases[] = {phase::kReferenceMaps, phase::kReferenceResolve};
constexpr std::string_view kVsmPhases[] = {phase::kVsmMoments, phase::kVsmBlur, phase::kVsmLookup};
constexpr std::string_view kRayTracePhases[] = {phase::kRaytraceBvh, phase::kRaytraceRays};

// --- The ground truths in words (capture's log and report) ------------------------------------

std::string describeGroundTruth(const MethodOptions& o) {
    return cat(o.integer(kReferenceSamples), " point-light shadow maps of ",
               o.integer(kReferenceMapSize), "^2 (", o.text(kReferencePattern), ")");
}
std::string describeRayTrace(const MethodOptions& o) {
    return cat(o.integer(kRaySamples), " shadow rays per pixel",
               o.flag(kRayGrid) ? " to the strata's centres" : "", " (Embree)");
}

// --- Checks before rendering --------------------------------------------------------------------

void checkLightFlood(const MethodOptions& o, const MethodDescriptor& m, int mapSize, int w, int h) {
    PenumbraSettings ps;
    ps.passes = requestedPasses(m, o, mapSize, w, h);
    if (ps.passes == kAutoPasses) return; // chosen per frame within the range
    try {
        (void)penumbraPlan(ps, mapSize);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(cat(kPasses.flag, ": ", e.what()));
    }
}

void checkEyeFlood(const MethodOptions& o, const MethodDescriptor& m, int mapSize, int w, int h) {
    if (o.flag(kFullJfa)) return; // capped at the frame
    if (requestedPasses(m, o, mapSize, w, h) == kAutoPasses) return;
    try {
        (void)eyeSoftPlan(requestedPasses(m, o, mapSize, w, h), false, w, h);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(cat(kPasses.flag, ": ", e.what()));
    }
}

// --- The table ----------------------------------------------------------------------------------

// The rows, made on first use (a function-local static): a row may take what another file
// defines (its options), which is then sure to be initialised, whichever file's static
// initialisers run first and ask for the table.
std::span<const MethodDescriptor> rows() {
    static const MethodDescriptor table[] = {
        {.name = "hard",
         .help = "one shadow-map test at the light's centre",
         .phases = kHardPhases,
         .make = makeHard,
         .cheapest = true},
        {.name = "jfa-l",
         .help = "JFA penumbra map in light space (thesis 5.3)",
         .reference = "flood-l",
         .options = optionSet<LightFloodOptions>(kLightFloodFields),
         .phases = kLightFloodPhases,
         .shadowMapPositions = true,
         .floods = true,
         .make = makeJfaL,
         .check = checkLightFlood},
        {.name = "flood-l",
         .help = "jfa-l's standard-flooding reference",
         .options = optionSet<LightFloodOptions>(kLightFloodFields),
         .phases = kLightFloodPhases,
         .shadowMapPositions = true,
         .floods = true,
         .make = makeFloodL,
         .check = checkLightFlood},
        {.name = "jfa-e",
         .help = "JFA soft shadows in eye space (thesis 5.4)",
         .reference = "flood-e",
         .space = MethodSpace::Eye,
         .options = optionSet<EyeFloodOptions>(kEyeFloodFields),
         .phases = kEyeFloodPhases,
         .shadowMapPositions = true,
         .floods = true,
         .make = makeJfaE,
         .check = checkEyeFlood},
        {.name = "flood-e",
         .help = "jfa-e's standard-flooding reference",
         .space = MethodSpace::Eye,
         .options = optionSet<EyeFloodOptions>(kEyeFloodFields),
         .phases = kEyeFloodPhases,
         .shadowMapPositions = true,
         .floods = true,
         .make = makeFloodE,
         .check = checkEyeFlood},
        {.name = "pcf",
         .help = "baseline: percentage-closer filtering, a k x k kernel",
         .options = optionSet<PcfOptions>(kPcfFields),
         .phases = kPcfPhases,
         .make = makePcf},
        {.name = "pcss",
         .help = "baseline: percentage-closer soft shadows (Fernando 2005)",
         .options = optionSet<PcssOptions>(kPcssFields),
         .phases = kPcssPhases,
         .make = makePcss},
        {.name = "vsm",
         .help = "baseline: variance shadow maps, blur sized from the light radius",
         .options = kVsmOptions,
         .phases = kVsmPhases,
         .make = makeVsm},
        {.name = "reference",
         .help = "ground truth: N point-light shadow maps over the disk, averaged",
         .options = optionSet<GroundTruthOptions>(kGroundTruthFields),
         .phases = kGroundTruthPhases,
         .make = makeGroundTruth,
         .truth = "maps",
         .describe = describeGroundTruth},
        {.name = "raytrace",
         .help = "exact ground truth: N shadow rays per pixel to the disk light (Embree, CPU)",
         .space = MethodSpace::Eye,
         .options = optionSet<RayTraceOptions>(kRayTraceFields),
         .phases = kRayTracePhases,
         .cycles = false,
         .make = makeRayTrace,
         .truth = "raytrace",
         .describe = describeRayTrace},
    };
    return table;
}

} // namespace

const MethodDescriptor& cheapestMethod() {
    for (const MethodDescriptor& m : rows())
        if (m.cheapest) return m;
    throw std::logic_error("the method table marks no method cheapest");
}

std::span<const MethodDescriptor> methodTable() {
    return rows();
}

const MethodDescriptor* findMethod(std::string_view name) {
    for (const MethodDescriptor& m : rows())
        if (m.name == name) return &m;
    return nullptr;
}

std::string methodNames(std::string_view separator) {
    std::string out;
    for (const MethodDescriptor& m : rows()) {
        if (!out.empty()) out += separator;
        out += m.name;
    }
    return out;
}

std::string methodNamesWhere(const std::function<bool(const MethodDescriptor&)>& pred) {
    std::string out;
    for (const MethodDescriptor& m : rows())
        if (pred(m)) out += (out.empty() ? "" : ", ") + std::string(m.name);
    return out;
}

const MethodDescriptor& methodOrThrow(std::string_view name) {
    if (const MethodDescriptor* m = findMethod(name)) return *m;
    throw std::invalid_argument(
        cat("unknown shadow method '", name, "' (valid: ", methodNames(), ")"));
}

const MethodDescriptor& groundTruth(std::string_view kind) {
    for (const MethodDescriptor& m : rows())
        if (!m.truth.empty() && m.truth == kind) return m;
    throw std::invalid_argument(
        cat("unknown ground truth '", kind, "' (valid: ", groundTruthKinds(), ")"));
}

std::string groundTruthKinds() {
    std::string out;
    for (const MethodDescriptor& m : rows())
        if (!m.truth.empty()) {
            if (!out.empty()) out += '|';
            out += m.truth;
        }
    return out;
}

std::vector<const MethodOption*> allMethodOptions() {
    std::vector<const MethodOption*> out;
    for (const MethodDescriptor& m : rows())
        for (const MethodOption* o : m.options) {
            bool seen = false;
            for (const MethodOption* s : out) seen = seen || s->flag == o->flag;
            if (!seen) out.push_back(o);
        }
    return out;
}

const MethodOption& floodPassesOption() {
    return kPasses;
}

const MethodOption& floodRegionOption() {
    return kFloodRegion;
}

const MethodOption& penumbraSidesOption() {
    return kPenumbraSides;
}

bool penumbraBothSides(const MethodOptions& options) {
    return options.text(kPenumbraSides) == "both";
}

int requestedPasses(const MethodDescriptor& m, const MethodOptions& options, int mapSize, int width,
                    int height) {
    if (!m.floods) return 0;
    FloodOptions flood{};
    flood.fullJfa = options.flag(kFullJfa);
    if (!flood.fullJfa) flood.passes = options.integer(kPasses); // read only when it counts
    return requestedPasses(m.space, flood, mapSize, width, height);
}

int requestedPasses(MethodSpace space, const FloodOptions& flood, int mapSize, int width,
                    int height) {
    if (flood.fullJfa) {
        if (space == MethodSpace::Eye) return eyeSoftMaxPasses(width, height);
        int full = 0;
        while ((2 << full) <= mapSize) ++full; // steps down from half the grid
        return full;
    }
    return flood.passes;
}

} // namespace fl
