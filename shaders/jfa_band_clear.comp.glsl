#version 450 core
#include "bindings.glsl"
// Band-limited flooding: writes the empty cell over the tiles of a stage's tile list (the
// list and indirect dispatch of jfa_band_compact.comp.glsl, as the band passes run it).
// The band's passes write only those tiles, so clearing them again leaves a ping-pong texture
// empty everywhere at the cost of the band, not of the grid (GlFloodKernelBase::buildBand).

#include "jfa_band_tiles.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

// JFA_CELL_FORMAT: rgba32f, or r32f for packed cells (jfa::detail::cellFormatDefine).
layout(binding = FL_IMG_FLOOD_OUT, JFA_CELL_FORMAT) uniform writeonly image2D uDst;
uniform ivec2 uSize;

void main() {
    ivec2 t = jfaBandTexel();
    if (any(greaterThanEqual(t, uSize))) return;
    imageStore(uDst, t, vec4(0.0, 0.0, -1.0, 0.0)); // kJfaEmptyCell
}
