#pragma once
// The names of a frame's timed phases, as gl::PassTimer records them and the benchmarks, the HUD
// and the capture report print them: one home, read by the method table (each method's phases,
// in order: MethodDescriptor::phases), by framePhases (the frame's own steps) and by the passes
// that time them.

namespace fl::phase {

// The frame's own steps (Renderer::renderFrame, numbered there).
inline constexpr char kShadowMap[] = "shadow map";
inline constexpr char kSurfaces[] = "surfaces";
inline constexpr char kShading[] = "shading";
inline constexpr char kDiagnostics[] = "diagnostics";

// Step 3, per method.
inline constexpr char kHardShadows[] = "hard shadows";
// JFA-L and flood-L (PenumbraMapPass, PenumbraMethod).
inline constexpr char kView[] = "view";
inline constexpr char kSilhouettes[] = "silhouettes";
inline constexpr char kBand[] = "band";   // JFA-E's too
inline constexpr char kFlood[] = "flood"; // JFA-E's too
inline constexpr char kPenumbraLookup[] = "penumbra lookup";
// JFA-E and flood-E (EyeSoftShadowPass).
inline constexpr char kOccluderIds[] = "occluder ids";
inline constexpr char kEyeHardShadows[] = "eye hard shadows";
inline constexpr char kBoundaries[] = "boundaries";
inline constexpr char kPassCount[] = "pass count";
inline constexpr char kComposite[] = "composite";
// PCF, PCSS (FilteredShadowPass).
inline constexpr char kPcfFilter[] = "pcf filter";
inline constexpr char kBlockerSearchFilter[] = "blocker search+filter";
// The maps truth (ReferenceShadowPass).
inline constexpr char kReferenceMaps[] = "reference maps";
inline constexpr char kReferenceResolve[] = "reference resolve";
// VSM.
inline constexpr char kVsmMoments[] = "vsm moments";
inline constexpr char kVsmBlur[] = "vsm blur";
inline constexpr char kVsmLookup[] = "vsm lookup";
// The ray-traced truth.
inline constexpr char kRaytraceBvh[] = "raytrace bvh";
inline constexpr char kRaytraceRays[] = "raytrace rays";

} // namespace fl::phase
