#version 450 core
// The receivers' depth pyramid of the penumbra bound (renderer/soft/PenumbraReach.h): level 0
// holds, per 8x8 block of the flooded grid, the largest distance from the light's plane of a
// receiver in it (0 where there is none); level L + 1 the max of 2x2 cells of level L (the last
// cell of an odd level: 3 cells).
// uMode 0 builds level 0 from the receiver positions, 1 one level from the one below.
#include "disk_light.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D uPositions; // xyz world position, w the receiver flag
layout(binding = 0, r32f) uniform writeonly image2D uDst;
layout(binding = 1, r32f) uniform readonly image2D uSrc;
uniform int uMode;
uniform float uValidMin; // a receiver has w >= uValidMin
uniform ivec2 uDstSize;
uniform ivec2 uSrcSize;

void main() {
    ivec2 t = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(t, uDstSize))) return;
    float d = 0.0;
    if (uMode == 0) {
        for (int j = 0; j < 8; ++j)
            for (int i = 0; i < 8; ++i) {
                ivec2 q = t * 8 + ivec2(i, j);
                if (any(greaterThanEqual(q, uSrcSize))) continue;
                vec4 p = texelFetch(uPositions, q, 0);
                if (p.w >= uValidMin) d = max(d, abs(dot(p.xyz - uDiskCenter, uDiskNormal)));
            }
    } else {
        // GL's mip sizes halve rounding down, so the last cell of a level also takes the odd
        // cell left over below it (a cell is never lost; the query clamps to the last cell).
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 3; ++i) {
                ivec2 q = t * 2 + ivec2(i, j);
                bool take = all(lessThan(q, uSrcSize)) && (i < 2 || t.x == uDstSize.x - 1) &&
                            (j < 2 || t.y == uDstSize.y - 1);
                if (take) d = max(d, imageLoad(uSrc, q).r);
            }
    }
    imageStore(uDst, t, vec4(d));
}
