// The normal offset of a shadow-map lookup (Holbert's normal offset shadows; Filament's and
// Godot's normal bias), shared by every map method: the point moved off its surface (plane
// normal n, on the seen side) by a quarter of the map's texel there times the sine of the angle
// to the light. A point lies anywhere in its texel but the map holds its surface's depth at the
// texel's centre; where the surface curves or is grazed the map's slope bias falls short of that
// and the surface shadows itself (acne in the lit band before a terminator). A quarter texel:
// on the real-model benchmark 0 leaves that acne, a whole texel detaches contact shadows (peter-
// panning in creases; docs/history/soft-shadows.md, "Real models"). Nothing for a surface facing
// away from the light. CPU twin: surface::normalOffset (renderer/passes/TerminatorLift.h); keep
// kNormalOffsetTexels equal to its.
const float kNormalOffsetTexels = 0.25;

// The world size of a texel of a `size`-texel map made with `mapViewProj` (world -> map clip)
// at `world`: the larger of its sides (TSM's texels vary over the map).
float mapTexelWorld(vec3 world, mat4 mapViewProj, float size) {
    mat4 m = mapViewProj;
    vec4 c = m * vec4(world, 1.0);
    vec3 rowX = vec3(m[0][0], m[1][0], m[2][0]), rowY = vec3(m[0][1], m[1][1], m[2][1]);
    vec3 rowW = vec3(m[0][3], m[1][3], m[2][3]);
    vec3 gx = (rowX * c.w - c.x * rowW) / (c.w * c.w); // d(ndc x) / d(world)
    vec3 gy = (rowY * c.w - c.y * rowW) / (c.w * c.w);
    float perUnit = min(length(gx), length(gy)) * 0.5 * size;
    return perUnit > 0.0 ? 1.0 / perUnit : 0.0;
}

// `world` moved by the normal offset; `toLight` unit, towards the light.
vec3 normalOffset(vec3 world, vec3 n, vec3 toLight, mat4 mapViewProj, float size) {
    float c = dot(n, toLight);
    if (!(c > 0.0)) return world;
    float s = sqrt(max(1.0 - c * c, 0.0));
    return world + n * (kNormalOffsetTexels * s * mapTexelWorld(world, mapViewProj, size));
}
