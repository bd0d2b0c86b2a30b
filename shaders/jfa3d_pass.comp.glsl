#version 450 core
#include "bindings.glsl"
// One pass of 3D jump flooding (jfa/GlJfa3d.h), the GL twin of jfa/Jfa3d.cpp's CPU passes: voxel
// p reads the 27 cells p + (i, j, l) * uStep, i, j, l in {-1, 0, 1}, that lie inside the grid
// (uSlices = 0, 3D JFA), or only the 9 of its own slice, l = 0 (uSlices = 1: the slice-by-slice
// variant of thesis §4.6.2, every slice in the same dispatch). A cell is an index into the site
// buffer, -1 for none. The nearest site wins by its exact integer squared distance (sides of at
// most 4096: 3 * 4095^2 < 2^31), equal distances go to the smaller id, then the smaller index:
// the CPU's rule in integers, so GL and CPU agree voxel for voxel on any driver.

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(binding = FL_IMG_FLOOD3D_IN, r32i) uniform readonly iimage3D uSrc;
layout(binding = FL_IMG_FLOOD3D_OUT, r32i) uniform writeonly iimage3D uDst;
// x, y, z, id
layout(std430, binding = FL_SSBO_FLOOD3D_SITES) readonly buffer Sites { ivec4 sites[]; };

uniform ivec3 uSize;
uniform int uStep;
uniform int uSlices;

void main() {
    ivec3 p = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(p, uSize))) return;
    int best = -1;
    int bestDistance = 0;
    int bestId = 0;
    int reachZ = uSlices != 0 ? 0 : 1;
    // Clamped reads and an "inside" flag rather than skipping outside or empty cells: branch-light
    // code ran 1.5x faster on llvmpipe (docs/history/jump-flooding.md, 3D Voronoi), with the
    // same result.
    ivec3 hi = uSize - 1;
    for (int l = -reachZ; l <= reachZ; ++l) {
        for (int j = -1; j <= 1; ++j) {
            for (int i = -1; i <= 1; ++i) {
                ivec3 q = p + ivec3(i, j, l) * uStep;
                ivec3 qc = clamp(q, ivec3(0), hi);
                int c = imageLoad(uSrc, qc).r;
                bool inside = q == qc && c >= 0;
                ivec4 s = sites[max(c, 0)];
                ivec3 d = s.xyz - p;
                int distance = d.x * d.x + d.y * d.y + d.z * d.z;
                bool take = inside && (best < 0 || distance < bestDistance ||
                                       (distance == bestDistance &&
                                        (s.w < bestId || (s.w == bestId && c < best))));
                best = take ? c : best;
                bestDistance = take ? distance : bestDistance;
                bestId = take ? s.w : bestId;
            }
        }
    }
    imageStore(uDst, p, ivec4(best, 0, 0, 0));
}
