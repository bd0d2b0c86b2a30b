#pragma once
// The one binding layout (shaders/bindings.glsl) as typed constants: every texture unit, image
// unit and buffer binding point a shader declares has one name here, its number comes from the
// shared file, and its type says which kind of binding point it is, so a texture unit cannot be
// handed to a buffer binding. Bind through gl::BindScope (gpu/BindScope.h), never with a number.
// tests/binding_layout_test.cpp checks that this list and bindings.glsl name the same entries.

#include <epoxy/gl.h>

#include "bindings.glsl" // on floodlight_gpu's public include path (the shaders/ folder)

namespace fl::gl {

/// A texture unit (glBindTextureUnit, glBindSampler): `layout(binding = FL_TEX_*)` samplers.
struct TextureUnit {
    GLuint index;
};
/// An image unit (glBindImageTexture): `layout(binding = FL_IMG_*)` images.
struct ImageUnit {
    GLuint index;
};
/// A shader storage binding point: `layout(std430, binding = FL_SSBO_*)` blocks.
struct StorageBinding {
    GLuint index;
};
/// An atomic counter binding point: `layout(binding = FL_ATOMIC_*)` counters.
struct CounterBinding {
    GLuint index;
};

namespace bind {
// Texture units
inline constexpr TextureUnit MaterialBaseColor{FL_TEX_MATERIAL_BASE_COLOR};
inline constexpr TextureUnit SurfacesDepth{FL_TEX_SURFACES_DEPTH};
inline constexpr TextureUnit SurfacesNormals{FL_TEX_SURFACES_NORMALS};
inline constexpr TextureUnit SurfacesBaseColor{FL_TEX_SURFACES_BASE_COLOR};
inline constexpr TextureUnit SurfacesLift{FL_TEX_SURFACES_LIFT};
inline constexpr TextureUnit LookupNormals{FL_TEX_LOOKUP_NORMALS};
inline constexpr TextureUnit Visibility{FL_TEX_VISIBILITY};
inline constexpr TextureUnit PresentColor{FL_TEX_PRESENT_COLOR};
inline constexpr TextureUnit ShadowMap{FL_TEX_SHADOW_MAP};
inline constexpr TextureUnit ShadowDepth{FL_TEX_SHADOW_DEPTH};
inline constexpr TextureUnit PreviousShadowMap{FL_TEX_PREVIOUS_SHADOW_MAP};
inline constexpr TextureUnit DiagnosticsSurfacesDepth{FL_TEX_DIAGNOSTICS_SURFACES_DEPTH};
inline constexpr TextureUnit DiagnosticsSurfacesNormals{FL_TEX_DIAGNOSTICS_SURFACES_NORMALS};
inline constexpr TextureUnit VsmDepth{FL_TEX_VSM_DEPTH};
inline constexpr TextureUnit VsmBlurIn{FL_TEX_VSM_BLUR_IN};
inline constexpr TextureUnit VsmMoments{FL_TEX_VSM_MOMENTS};
inline constexpr TextureUnit PenumbraSurfacesDepth{FL_TEX_PENUMBRA_SURFACES_DEPTH};
inline constexpr TextureUnit PenumbraMap{FL_TEX_PENUMBRA_MAP};
inline constexpr TextureUnit PenumbraReceivers{FL_TEX_PENUMBRA_RECEIVERS};
inline constexpr TextureUnit PenumbraNormals{FL_TEX_PENUMBRA_NORMALS};
inline constexpr TextureUnit PenumbraPositions{FL_TEX_PENUMBRA_POSITIONS};
inline constexpr TextureUnit ReachLo{FL_TEX_REACH_LO};
inline constexpr TextureUnit ReachHi{FL_TEX_REACH_HI};
inline constexpr TextureUnit ReachPositions{FL_TEX_REACH_POSITIONS};
inline constexpr TextureUnit SilhouetteReceivers{FL_TEX_SILHOUETTE_RECEIVERS};
inline constexpr TextureUnit EyeFlooded{FL_TEX_EYE_FLOODED};
inline constexpr TextureUnit EyeNormals{FL_TEX_EYE_NORMALS};
inline constexpr TextureUnit EyeCells{FL_TEX_EYE_CELLS};
inline constexpr TextureUnit EyeDepth{FL_TEX_EYE_DEPTH};
inline constexpr TextureUnit EyeReceivers{FL_TEX_EYE_RECEIVERS};
inline constexpr TextureUnit EyeIds{FL_TEX_EYE_IDS};
inline constexpr TextureUnit SeedOccluders{FL_TEX_SEED_OCCLUDERS};
inline constexpr TextureUnit Flooded{FL_TEX_FLOODED};
inline constexpr TextureUnit ReferenceSum{FL_TEX_REFERENCE_SUM};
inline constexpr TextureUnit ReferenceSurfacesDepth{FL_TEX_REFERENCE_SURFACES_DEPTH};
inline constexpr TextureUnit MapReceiverDepth{FL_TEX_MAP_RECEIVER_DEPTH};
inline constexpr TextureUnit FloodIn{FL_TEX_FLOOD_IN};
inline constexpr TextureUnit FloodSeeds{FL_TEX_FLOOD_SEEDS};
inline constexpr TextureUnit OverlayA{FL_TEX_OVERLAY_A};
inline constexpr TextureUnit OverlayB{FL_TEX_OVERLAY_B};
inline constexpr TextureUnit OverlayC{FL_TEX_OVERLAY_C};
inline constexpr TextureUnit DelaunayCells{FL_TEX_DELAUNAY_CELLS};
inline constexpr TextureUnit DelaunayIslandsIn{FL_TEX_DELAUNAY_ISLANDS_IN};
inline constexpr TextureUnit DelaunayPing{FL_TEX_DELAUNAY_PING};
inline constexpr TextureUnit DelaunayPong{FL_TEX_DELAUNAY_PONG};
inline constexpr TextureUnit DelaunayIds{FL_TEX_DELAUNAY_IDS};
inline constexpr TextureUnit DelaunayChainIn{FL_TEX_DELAUNAY_CHAIN_IN};
inline constexpr TextureUnit DelaunayCorners{FL_TEX_DELAUNAY_CORNERS};
inline constexpr TextureUnit DelaunayChain{FL_TEX_DELAUNAY_CHAIN};

// Image units
inline constexpr ImageUnit FloodOut{FL_IMG_FLOOD_OUT};
inline constexpr ImageUnit RepairOut{FL_IMG_REPAIR_OUT};
inline constexpr ImageUnit Flood3dIn{FL_IMG_FLOOD3D_IN};
inline constexpr ImageUnit Flood3dOut{FL_IMG_FLOOD3D_OUT};
inline constexpr ImageUnit MapPositions{FL_IMG_MAP_POSITIONS};
inline constexpr ImageUnit ReachLoOut{FL_IMG_REACH_LO_OUT};
inline constexpr ImageUnit ReachHiOut{FL_IMG_REACH_HI_OUT};
inline constexpr ImageUnit ReachLoIn{FL_IMG_REACH_LO_IN};
inline constexpr ImageUnit ReachHiIn{FL_IMG_REACH_HI_IN};
inline constexpr ImageUnit DelaunayOwner{FL_IMG_DELAUNAY_OWNER};
inline constexpr ImageUnit DelaunaySeeds{FL_IMG_DELAUNAY_SEEDS};
inline constexpr ImageUnit DelaunayOut{FL_IMG_DELAUNAY_OUT};

// Shader storage blocks
inline constexpr StorageBinding BandTileRects{FL_SSBO_BAND_TILE_RECTS};
inline constexpr StorageBinding BandMaxReach{FL_SSBO_BAND_MAX_REACH};
inline constexpr StorageBinding BandFlags{FL_SSBO_BAND_FLAGS};
inline constexpr StorageBinding BandTiles{FL_SSBO_BAND_TILES};
inline constexpr StorageBinding BandCommands{FL_SSBO_BAND_COMMANDS};
inline constexpr StorageBinding SeedList{FL_SSBO_SEED_LIST};
inline constexpr StorageBinding BandNearView{FL_SSBO_BAND_NEAR_VIEW};
inline constexpr StorageBinding FloodFront{FL_SSBO_FLOOD_FRONT};
inline constexpr StorageBinding DilateIn{FL_SSBO_DILATE_IN};
inline constexpr StorageBinding DilateOut{FL_SSBO_DILATE_OUT};
inline constexpr StorageBinding RowSpans{FL_SSBO_ROW_SPANS};
inline constexpr StorageBinding OwnSpans{FL_SSBO_OWN_SPANS};
inline constexpr StorageBinding PoseJoints{FL_SSBO_POSE_JOINTS};
inline constexpr StorageBinding PoseMorphs{FL_SSBO_POSE_MORPHS};
inline constexpr StorageBinding SeedRegion{FL_SSBO_SEED_REGION};
inline constexpr StorageBinding ViewTiles{FL_SSBO_VIEW_TILES};
inline constexpr StorageBinding Flood3dSites{FL_SSBO_FLOOD3D_SITES};
inline constexpr StorageBinding RepairVertices{FL_SSBO_REPAIR_VERTICES};
inline constexpr StorageBinding RepairOffsets{FL_SSBO_REPAIR_OFFSETS};
inline constexpr StorageBinding RepairNeighbours{FL_SSBO_REPAIR_NEIGHBOURS};
inline constexpr StorageBinding TravelBins{FL_SSBO_TRAVEL_BINS};
inline constexpr StorageBinding DelaunayPixels{FL_SSBO_DELAUNAY_PIXELS};
inline constexpr StorageBinding DelaunayKeepers{FL_SSBO_DELAUNAY_KEEPERS};
inline constexpr StorageBinding DelaunayHeader{FL_SSBO_DELAUNAY_HEADER};
inline constexpr StorageBinding DelaunayControl{FL_SSBO_DELAUNAY_CONTROL};
inline constexpr StorageBinding DelaunayRows{FL_SSBO_DELAUNAY_ROWS};
inline constexpr StorageBinding DelaunayVertices{FL_SSBO_DELAUNAY_VERTICES};
inline constexpr StorageBinding DelaunayTriangles{FL_SSBO_DELAUNAY_TRIANGLES};
inline constexpr StorageBinding DelaunayTriangleVertex{FL_SSBO_DELAUNAY_TRIANGLE_VERTEX};

// Atomic counters
inline constexpr CounterBinding ChangedCounter{FL_ATOMIC_CHANGED};
} // namespace bind

} // namespace fl::gl
