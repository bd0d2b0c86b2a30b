// Reading JFA-E's packed eye cells (phase 2's one R32UI target, jfae_eye.frag.glsl writes it).
// The CPU twin is renderer/soft/EyeDecode.h: keep the two in step. Every JFA-E shader reads a
// pixel's receiver point and occluder through these helpers, so the packing is written down in
// exactly two places. Needs disk_light.glsl, shadow_map_decode.glsl, occluder_edge.glsl and
// surface_decode.glsl included before it.
//
// A cell is 32 bits: bits 0-1 the pixel's state (kEyeBackground, kEyeShadowed, kEyeLit,
// kEyeOutsideMap), bits 2-5 its occluder texel's edge code (occluderEdgeCode; 0 for lit pixels
// and texel-centre points), bits 6-18 and 19-31 the x and y of its shadow-map texel (maps up to
// 8192², fl::eyecell::kMaxMapSize; two fields, not an index, so decoding divides nothing). Nothing else is stored: the receiver's world position
// comes back from the surfaces' depth (surfacePosition), the occluder's from the map's receiver
// target (occluderEdgeApply), its object id from the light-space id pass at that texel.
//
// The textures sit on the layout's fixed units (bindings.glsl), the same in every JFA-E program
// (fl::EyeCells::bind), clear of the flood kernel's grids (FL_TEX_FLOOD_*) and the reach bounds
// (FL_TEX_REACH_*, disk_light.glsl); FL_TEX_SEED_OCCLUDERS holds phase 3's seed occluders
// (eyeSeedOccluder below).
#include "bindings.glsl"
layout(binding = FL_TEX_EYE_CELLS) uniform usampler2D uEyeCells;
// the surfaces' depth (surface_decode)
layout(binding = FL_TEX_EYE_DEPTH) uniform sampler2D uEyeDepth;
layout(binding = FL_TEX_EYE_RECEIVERS) uniform sampler2D uEyeReceivers; // the map's receiver target
layout(binding = FL_TEX_EYE_IDS) uniform sampler2D uEyeIds;       // R32F object id per map texel
uniform int uEyeObjectIds; // 0: ids unknown (the object-ID fix is off), every id reads -1
// The grid the shader works on: the frame (uEyeFactor 1), or JFA-E's coarse estimate, whose
// pixel P is frame pixel min(uEyeFactor * P + uEyeFactor / 2, frame - 1) (fl::coarseEyeImage).
uniform ivec2 uEyeGrid;
uniform int uEyeFactor;

const uint kEyeBackground = 0u;
const uint kEyeShadowed = 1u;
const uint kEyeLit = 2u;
const uint kEyeOutsideMap = 3u;

// The cell phase 2 writes for a pixel in `state` whose shadow lookup reads texel `t`.
uint eyeCellPack(uint state, ivec2 t, uint edgeCode) {
    return state | (edgeCode << 2u) | (uint(t.x) << 6u) | (uint(t.y) << 19u);
}

// The frame pixel of grid pixel p.
ivec2 eyeFramePixel(ivec2 p) {
    if (uEyeFactor == 1) return p;
    return min(p * uEyeFactor + uEyeFactor / 2, textureSize(uEyeCells, 0) - 1);
}

// The map texel a cell's occluder lies at (states kEyeShadowed and kEyeLit only).
ivec2 eyeCellTexel(uint cell) { return ivec2(int((cell >> 6u) & 8191u), int(cell >> 19u)); }

// Grid pixel p's state (kEyeBackground ... kEyeOutsideMap): one fetch, no point decoded.
uint eyeState(ivec2 p) { return texelFetch(uEyeCells, eyeFramePixel(p), 0).r & 3u; }

// Grid pixel p's receiver: xyz its world position; w = 1 in hard shadow, 0 lit, 2 lit because
// outside the shadow map, -1 no surface (xyz 0). fl::eyecell::point on the CPU.
vec4 eyePoint(ivec2 p) {
    ivec2 f = eyeFramePixel(p);
    uint state = eyeState(p);
    if (state == kEyeBackground) return vec4(0.0, 0.0, 0.0, -1.0);
    float w = state == kEyeShadowed ? 1.0 : (state == kEyeLit ? 0.0 : 2.0);
    return vec4(surfacePosition(uEyeDepth, f).xyz, w);
}

// Grid pixel p's surface: xyz its world position, w 1, or vec4(0) without one. eyePoint less
// the state: one fetch fewer, for a test that needs only "a surface, and where" (the flood's
// midpoint check, per candidate). Phase 2 writes kEyeBackground exactly where the depth is the
// background's, so w here is 0 exactly where eyePoint's w is -1.
vec4 eyeSurface(ivec2 p) { return surfacePosition(uEyeDepth, eyeFramePixel(p)); }

// Grid pixel p's occluder: xyz the point the shadow map's texel gives it (at the silhouette edge
// where phase 2 found one), w its object id; (0, 0, 0, -1) without a surface or outside the map.
vec4 eyeOccluder(ivec2 p) {
    uint cell = texelFetch(uEyeCells, eyeFramePixel(p), 0).r;
    uint state = cell & 3u;
    if (state == kEyeBackground || state == kEyeOutsideMap) return vec4(0.0, 0.0, 0.0, -1.0);
    ivec2 t = eyeCellTexel(cell);
    float id = uEyeObjectIds != 0 ? texelFetch(uEyeIds, t, 0).r : -1.0;
    return vec4(occluderEdgeApply(uEyeReceivers, t, (cell >> 2u) & 15u), id);
}

// Phase 3's occluder per seed pixel (RGBA32F, jfae_boundary.frag.glsl writes eyeOccluder(s) at
// each seed s; fl::EyeCells::seedOccluders, bound once phase 3 has run). Why a
// copy of what the cells already say: the flood reads a seed's occluder for each of its 9
// candidates in every pass, and decoding it (a cell, a map texel unprojected, up to two
// neighbours for the edge) cost the llvmpipe flood 2.8x; phase 3 decodes each seed once.
layout(binding = FL_TEX_SEED_OCCLUDERS) uniform sampler2D uSeedOccluders;

// Seed pixel s's occluder, bit for bit eyeOccluder(s) (s must be a seed of phase 3).
vec4 eyeSeedOccluder(ivec2 s) { return texelFetch(uSeedOccluders, s, 0); }

// eyeOccluder(p).w alone (the object-ID fix), without decoding the point.
float eyeOccluderId(ivec2 p) {
    uint cell = texelFetch(uEyeCells, eyeFramePixel(p), 0).r;
    uint state = cell & 3u;
    if (uEyeObjectIds == 0 || state == kEyeBackground || state == kEyeOutsideMap) return -1.0;
    return texelFetch(uEyeIds, eyeCellTexel(cell), 0).r;
}

// The grid pixel a flood cell was seeded at (w = y * width + x + 1), without an integer
// division: a SIMD rasteriser (llvmpipe) divides lane by lane, which cost 6-9% of the flood. The
// float quotient is within one row of y (the index is exact in a float below 2^24, y is below a
// texture's height, and GLSL's division is good to 2.5 ulp), and the integer checks correct it.
ivec2 eyeSeedPixel(float w) {
    int width = uEyeGrid.x;
    int index = int(w) - 1;
    int y = int(float(index) / float(width));
    y -= y * width > index ? 1 : 0;
    y += (y + 1) * width <= index ? 1 : 0;
    return ivec2(index - y * width, y);
}
