// The one binding layout: every texture unit, image unit and buffer binding point a shader
// declares, read by the shaders (#include "bindings.glsl") and by C++ (gpu/Bindings.h, which
// gives each a typed constant). Only `#define FL_<KIND>_<ROLE> <n>` lines and comments here.
// Kinds: TEX texture units, IMG image units, SSBO shader storage blocks, ATOMIC atomic counters.
// Roles may share a number only when no program declares both: tests/binding_layout_test.cpp
// checks that every declaration names an entry of its kind and that no shader file, with its
// includes, declares two entries of one kind and number.
#ifndef FL_BINDINGS_GLSL
#define FL_BINDINGS_GLSL

// ---- Texture units -------------------------------------------------------------------------
// Scene draws (alpha_coverage.glsl): the material's base colour texture.
#define FL_TEX_MATERIAL_BASE_COLOR 0
// SurfacesPass' targets as the shading and the light lookups read them.
#define FL_TEX_SURFACES_DEPTH 0
#define FL_TEX_SURFACES_NORMALS 1
#define FL_TEX_SURFACES_BASE_COLOR 2
// Every shadow-map lookup's point (surface_lookup.glsl): the lift and the shading normals.
#define FL_TEX_SURFACES_LIFT 11
#define FL_TEX_LOOKUP_NORMALS 12
#define FL_TEX_VISIBILITY 3 // the method's visibility, R32F (shading)
#define FL_TEX_PRESENT_COLOR 0 // the shaded frame (present)
// The shadow map: through a comparing sampler (shadow_lookup.glsl) and raw depth (filters).
#define FL_TEX_SHADOW_MAP 1
#define FL_TEX_SHADOW_DEPTH 4 // filtered_shadow: the map through a non-comparing sampler
#define FL_TEX_PREVIOUS_SHADOW_MAP 2 // shadow_diagnostics: last frame's map
#define FL_TEX_DIAGNOSTICS_SURFACES_DEPTH 3
#define FL_TEX_DIAGNOSTICS_SURFACES_NORMALS 4
// VSM: the moments from the map, the blur's input, the lookup's blurred moments.
#define FL_TEX_VSM_DEPTH 0
#define FL_TEX_VSM_BLUR_IN 0
#define FL_TEX_VSM_MOMENTS 2
// The light-space penumbra lookup (light_visibility, soft_penumbra.glsl, penumbra_view).
#define FL_TEX_PENUMBRA_SURFACES_DEPTH 2
#define FL_TEX_PENUMBRA_MAP 3
// Not 4 and 5: soft_penumbra.glsl includes disk_light.glsl, whose reach bounds hold those.
#define FL_TEX_PENUMBRA_RECEIVERS 6 // MapPositions
#define FL_TEX_PENUMBRA_NORMALS 7   // SurfacesPass' normals
#define FL_TEX_PENUMBRA_POSITIONS 2 // jfa_penumbra.glsl
// Reach bounds (disk_light.glsl) and the pyramid that builds them (reach_bounds).
#define FL_TEX_REACH_LO 4
#define FL_TEX_REACH_HI 5
#define FL_TEX_REACH_POSITIONS 0
// The silhouette seeds' receivers (silhouette): the map's receiver target.
#define FL_TEX_SILHOUETTE_RECEIVERS 0
// Eye-space floods (eye_decode.glsl, jfae_*). Not 1: the composite reads the shadow map there.
#define FL_TEX_EYE_FLOODED 9
#define FL_TEX_EYE_CELLS 2
#define FL_TEX_EYE_DEPTH 3
#define FL_TEX_EYE_RECEIVERS 6
#define FL_TEX_EYE_IDS 7
#define FL_TEX_SEED_OCCLUDERS 8
#define FL_TEX_EYE_NORMALS 10 // SurfacesPass' normals (jfae_composite: receiver planes)
// A finished flood read by a follow-up kernel (jfa_exact_repair, jfae_travel).
#define FL_TEX_FLOODED 0
// The reference shadow: the accumulated sum, then the surfaces' depth (reference_resolve).
#define FL_TEX_REFERENCE_SUM 0
#define FL_TEX_REFERENCE_SURFACES_DEPTH 1
// The shadow map's receiver depth (shadow_map_positions).
#define FL_TEX_MAP_RECEIVER_DEPTH 0
// Flood passes (jfa_pass, jfa_band_*): the previous pass' cells and the seeds.
#define FL_TEX_FLOOD_IN 0
#define FL_TEX_FLOOD_SEEDS 1
// Overlays: three channels (overlay_grid).
#define FL_TEX_OVERLAY_A 0
#define FL_TEX_OVERLAY_B 1
#define FL_TEX_OVERLAY_C 2
// Delaunay steps G2-G6 (delaunay_*).
#define FL_TEX_DELAUNAY_CELLS 0
#define FL_TEX_DELAUNAY_ISLANDS_IN 0
#define FL_TEX_DELAUNAY_PING 1
#define FL_TEX_DELAUNAY_PONG 2
#define FL_TEX_DELAUNAY_IDS 0
#define FL_TEX_DELAUNAY_CHAIN_IN 0
#define FL_TEX_DELAUNAY_CORNERS 1
#define FL_TEX_DELAUNAY_CHAIN 2

// ---- Image units ---------------------------------------------------------------------------
#define FL_IMG_FLOOD_OUT 0 // jfa_pass, jfa_band_clear
#define FL_IMG_REPAIR_OUT 0
#define FL_IMG_FLOOD3D_IN 0
#define FL_IMG_FLOOD3D_OUT 1
#define FL_IMG_MAP_POSITIONS 0
#define FL_IMG_REACH_LO_OUT 0
#define FL_IMG_REACH_HI_OUT 1
#define FL_IMG_REACH_LO_IN 2
#define FL_IMG_REACH_HI_IN 3
#define FL_IMG_DELAUNAY_OWNER 0
#define FL_IMG_DELAUNAY_SEEDS 1
#define FL_IMG_DELAUNAY_OUT 0 // each of G2-G5's one output texture

// ---- Shader storage blocks -----------------------------------------------------------------
// The flood band (jfa_band_*, jfa_pass) and the seed list its producers fill.
#define FL_SSBO_BAND_TILE_RECTS 1
#define FL_SSBO_BAND_MAX_REACH 2
#define FL_SSBO_BAND_FLAGS 3
#define FL_SSBO_BAND_TILES 4
#define FL_SSBO_BAND_COMMANDS 5
#define FL_SSBO_SEED_LIST 6
#define FL_SSBO_BAND_NEAR_VIEW 7
#define FL_SSBO_FLOOD_FRONT 8
// Tile dilation (tile_dilate, tile_rows).
#define FL_SSBO_DILATE_IN 7
#define FL_SSBO_DILATE_OUT 8
#define FL_SSBO_ROW_SPANS 9
#define FL_SSBO_OWN_SPANS 10
// Skinning and morphing (pose.glsl).
#define FL_SSBO_POSE_JOINTS 6
#define FL_SSBO_POSE_MORPHS 7
// The penumbra's seed region and view tiles (reach_bounds, silhouette, penumbra_view).
#define FL_SSBO_SEED_REGION 7
#define FL_SSBO_VIEW_TILES 7
// 3D flood, exact repair, eye-space travel.
#define FL_SSBO_FLOOD3D_SITES 0
#define FL_SSBO_REPAIR_VERTICES 0
#define FL_SSBO_REPAIR_OFFSETS 1
#define FL_SSBO_REPAIR_NEIGHBOURS 2
#define FL_SSBO_TRAVEL_BINS 0
// Delaunay steps (delaunay_*): the site pixels, the result buffer's parts, G3's loop state.
#define FL_SSBO_DELAUNAY_PIXELS 0
#define FL_SSBO_DELAUNAY_KEEPERS 1
#define FL_SSBO_DELAUNAY_HEADER 1
#define FL_SSBO_DELAUNAY_CONTROL 2
#define FL_SSBO_DELAUNAY_ROWS 2
#define FL_SSBO_DELAUNAY_VERTICES 3
#define FL_SSBO_DELAUNAY_TRIANGLES 4
#define FL_SSBO_DELAUNAY_TRIANGLE_VERTEX 5

// ---- Atomic counters -----------------------------------------------------------------------
#define FL_ATOMIC_CHANGED 0 // jfa_pass, delaunay_islands: texels a pass changed

#endif
