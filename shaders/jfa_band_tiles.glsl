// A stage's band as a tile list (jfa_band_compact.comp.glsl: packed tile coordinates
// x | y << 16) run by an indirect dispatch: group x = the list entry, group y = the 8x8 block
// within the tile. Shared by the band passes (jfa_pass.comp.glsl) and the band clear.
#include "bindings.glsl"

layout(std430, binding = FL_SSBO_BAND_TILES) readonly buffer TileList { uint tiles[]; };
uniform int uTile;

/// The tile this invocation's group works on (tile coordinates).
ivec2 jfaBandTile() {
    uint entry = tiles[gl_WorkGroupID.x];
    return ivec2(int(entry & 0xffffu), int(entry >> 16));
}

/// The texel this invocation stands for (it may lie beyond the grid at its right or top edge).
ivec2 jfaBandTexel() {
    int blocks = uTile / 8;
    ivec2 block = ivec2(int(gl_WorkGroupID.y) % blocks, int(gl_WorkGroupID.y) / blocks);
    return jfaBandTile() * uTile + block * 8 +
           ivec2(gl_LocalInvocationID.xy);
}
