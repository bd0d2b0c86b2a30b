#version 450 core
#include "bindings.glsl"
// Band-limited flooding, the view limit (jfa/Band.h, FloodRegion::View), between steps B and C:
// one invocation per full-resolution tile. A band tile off the view's tiles widened by the
// plan's reach (GlTileDilation, tile_dilate.comp.glsl) leaves the band: no texel the reader reads
// depends on it. Same as fl::jfa::limitToView on the CPU.

layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = FL_SSBO_BAND_FLAGS) buffer Flags { uint flags[]; };
layout(std430, binding = FL_SSBO_BAND_NEAR_VIEW) readonly buffer NearView { uint nearView[]; };
uniform ivec2 uTiles; // tiles per axis

void main() {
    ivec2 t = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(t, uTiles))) return;
    int i = t.y * uTiles.x + t.x;
    if (nearView[i] == 0u) flags[i] = 0u;
}
