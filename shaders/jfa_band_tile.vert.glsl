#version 450 core
// Band-limited flooding, fragment kernel: instance i draws tile tiles[i] of the stage grid as two
// triangles whose edges lie on texel boundaries, so every band texel is shaded exactly once by
// jfa_pass.frag.glsl (the same fragment shader as the full-grid pass).

layout(std430, binding = 4) readonly buffer TileList { uint tiles[]; };
uniform int uTile;
uniform ivec2 uSize; // the stage grid

void main() {
    uint entry = tiles[gl_InstanceID];
    ivec2 tile = ivec2(int(entry & 0xffffu), int(entry >> 16));
    int v = gl_VertexID; // (0,0) (1,0) (1,1) / (0,0) (1,1) (0,1)
    ivec2 corner = ivec2(v == 1 || v == 2 || v == 4 ? 1 : 0, v == 2 || v == 4 || v == 5 ? 1 : 0);
    vec2 texel = vec2(min((tile + corner) * uTile, uSize));
    gl_Position = vec4(texel / vec2(uSize) * 2.0 - 1.0, 0.0, 1.0);
}
