#version 450 core
#include "bindings.glsl"
// JFA-L's view limit (--flood-region view; jfa/Band.h): the penumbra-map tiles the lookup
// (soft_penumbra.glsl) may read, one fragment per eye pixel (a framebuffer without attachments):
// the tile of the texel its surface point projects to. The map's extent is tested with a margin of
// 1e-4 of the map, since the lookup's own rounding may differ from this pass's. Same as
// fl::penumbraViewTiles on the CPU. A fragment pass: llvmpipe runs it about five times faster
// than the same work as a compute pass.
#include "surface_decode.glsl"

// SurfacesPass: positions (surfacePosition)
layout(binding = FL_TEX_PENUMBRA_SURFACES_DEPTH) uniform sampler2D uDepth;
layout(std430, binding = FL_SSBO_VIEW_TILES) writeonly buffer ViewTiles { uint viewTiles[]; };
uniform mat4 uLightViewProj;
uniform mat4 uShadowWarp;
uniform int uMapSize;
uniform int uTile;

void main() {
    vec4 world = surfacePosition(uDepth, ivec2(gl_FragCoord.xy));
    if (world.w == 0.0) return;
    vec4 light = uLightViewProj * vec4(world.xyz, 1.0);
    vec4 map = uShadowWarp * light;
    if (light.w <= 0.0 || map.w <= 0.0) return;
    vec3 uvz = vec3(map.xy / map.w, light.z / light.w) * 0.5 + 0.5;
    const float kMargin = 1e-4;
    if (any(lessThan(uvz, vec3(-kMargin))) || any(greaterThan(uvz, vec3(1.0 + kMargin)))) return;
    ivec2 t = clamp(ivec2(uvz.xy * float(uMapSize)), ivec2(0), ivec2(uMapSize - 1));
    int tiles = (uMapSize + uTile - 1) / uTile;
    viewTiles[(t.y / uTile) * tiles + t.x / uTile] = 1u;
}
