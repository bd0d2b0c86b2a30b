// Building a tile list of band-limited flooding (jfa/Band.h): the list (packed tile coordinates
// x | y << 16, in any order) and its indirect commands, which the band passes and the band clear
// read through jfa_band_tiles.glsl. Shared by step C (jfa_band_compact.comp.glsl) and the flood's
// front (jfa_band_front.comp.glsl).
#include "bindings.glsl"

layout(std430, binding = FL_SSBO_BAND_TILES) writeonly buffer TileList { uint tiles[]; };
// [0..2] DispatchIndirectCommand (x = tiles, y = 8x8 groups per tile, z = 1), [3] the texels of
// the tiles listed (clipped to the grid).
layout(std430, binding = FL_SSBO_BAND_COMMANDS) buffer Commands { uint commands[4]; };

/// Appends tile t, which holds `texels` texels of the grid, to the list.
void jfaAppendTile(ivec2 t, ivec2 texels) {
    uint index = atomicAdd(commands[0], 1u);
    atomicAdd(commands[3], uint(texels.x * texels.y));
    tiles[index] = uint(t.x) | (uint(t.y) << 16);
}
