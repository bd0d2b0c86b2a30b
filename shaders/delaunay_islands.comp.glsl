#version 450 core
#include "bindings.glsl"
// One pass of step G3 (thesis §6.3.2), removeIslands in geometry/DiscreteVoronoi.h: a pixel
// whose neighbours towards its own site (three in the site's quadrant, one on an axis) all have
// another colour is in an island and takes the nearest of those neighbours' sites (squared
// integer distance, then the smaller id). It reads only the previous pass' texture; the host
// repeats passes until the counter of changed pixels stays 0.
#include "delaunay_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = FL_TEX_DELAUNAY_ISLANDS_IN) uniform usampler2D uSrc;
layout(binding = FL_IMG_DELAUNAY_OUT, r32ui) uniform writeonly uimage2D uDst;
layout(std430, binding = FL_SSBO_DELAUNAY_PIXELS) readonly buffer Pixels { ivec2 pixels[]; };
layout(binding = FL_ATOMIC_CHANGED, offset = 0) uniform atomic_uint uChanged;
uniform ivec2 uSize;

// Pixel coordinates stay below 2^13 (kMaxDiscreteSize), so squares fit in 32 bits.
int squaredDistance(ivec2 a, ivec2 b) {
    ivec2 d = a - b;
    return d.x * d.x + d.y * d.y;
}

uint colourAt(ivec2 q) { return texelFetch(uSrc, q, 0).r; }

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, uSize))) return;
    uint c = colourAt(p);
    uint result = c;
    if (c != kNoSite) {
        ivec2 d = sign(pixels[c] - p);
        // The neighbours between the pixel and its site (so inside the texture).
        ivec2 nb[3];
        int count = 0;
        if (d.x != 0 && d.y != 0) {
            nb[0] = p + ivec2(d.x, 0);
            nb[1] = p + d;
            nb[2] = p + ivec2(0, d.y);
            count = 3;
        } else if (d != ivec2(0)) {
            nb[0] = p + d;
            count = 1;
        }
        uint colours[3];
        bool island = count > 0;
        for (int k = 0; k < count; ++k) {
            colours[k] = colourAt(nb[k]);
            island = island && colours[k] != c;
        }
        if (island) {
            uint best = colours[0];
            int bestD = squaredDistance(p, pixels[best]);
            for (int k = 1; k < count; ++k) {
                uint o = colours[k];
                int dist = squaredDistance(p, pixels[o]);
                if (dist < bestD || (dist == bestD && o < best)) {
                    best = o;
                    bestD = dist;
                }
            }
            result = best;
            atomicCounterIncrement(uChanged);
        }
    }
    imageStore(uDst, p, uvec4(result));
}
