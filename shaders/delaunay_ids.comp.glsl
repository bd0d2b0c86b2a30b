#version 450 core
#include "bindings.glsl"
// End of step G2: the flood's cells (z = site id, -1 empty) as a site-id texture, as
// floodVoronoi converts its grid.
#include "delaunay_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = FL_TEX_DELAUNAY_CELLS) uniform sampler2D uCells;
layout(binding = FL_IMG_DELAUNAY_OUT, r32ui) uniform writeonly uimage2D uIds;
uniform ivec2 uSize;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, uSize))) return;
    float z = texelFetch(uCells, p, 0).z;
    imageStore(uIds, p, uvec4(z < 0.0 ? kNoSite : uint(z)));
}
