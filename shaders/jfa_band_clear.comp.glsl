#version 450 core
// Band-limited flooding: writes the empty cell over the tiles of a stage's tile list (the
// list and indirect dispatch of jfa_band_compact.comp.glsl, laid out as in jfa_pass.comp.glsl).
// The band's passes write only those tiles, so clearing them again leaves a ping-pong texture
// empty everywhere at the cost of the band, not of the grid (GlFloodKernelBase::buildBand).

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0, rgba32f) uniform writeonly image2D uDst;
layout(std430, binding = 4) readonly buffer TileList { uint tiles[]; };
uniform ivec2 uSize;
uniform int uTile;

void main() {
    uint entry = tiles[gl_WorkGroupID.x];
    int blocks = uTile / 8;
    ivec2 block = ivec2(int(gl_WorkGroupID.y) % blocks, int(gl_WorkGroupID.y) / blocks);
    ivec2 t = ivec2(int(entry & 0xffffu), int(entry >> 16)) * uTile + block * 8 +
              ivec2(gl_LocalInvocationID.xy);
    if (any(greaterThanEqual(t, uSize))) return;
    imageStore(uDst, t, vec4(0.0, 0.0, -1.0, 0.0)); // kJfaEmptyCell
}
