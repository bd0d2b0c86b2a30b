#version 450 core
#include "bindings.glsl"
// Step G1 (thesis §6.3.2): sites into the texture. The host snaps every site to its pixel (the
// double-precision mapping of geometry/DiscreteVoronoi.h); here the sites claim their pixels.
// Mode 0: every site does imageAtomicMin on its pixel's owner, so the lowest index keeps it
// whatever order the invocations run in (as snapSites). Mode 1 (after a barrier): every site
// reads its pixel's owner (its keeper; itself if it kept the pixel) and the keepers write the
// jfa seed cell (xy = pixel, z = id) that the G2 flood starts from.
#include "delaunay_common.glsl"

layout(local_size_x = 64) in;

layout(binding = FL_IMG_DELAUNAY_OWNER, r32ui) uniform uimage2D uOwner;
layout(binding = FL_IMG_DELAUNAY_SEEDS, rgba32f) uniform writeonly image2D uSeeds;
layout(std430, binding = FL_SSBO_DELAUNAY_PIXELS) readonly buffer Pixels { ivec2 pixels[]; };
layout(std430, binding = FL_SSBO_DELAUNAY_KEEPERS) writeonly buffer Keepers { uint keepers[]; };
uniform int uCount;
uniform int uMode;

void main() {
    uint i = dispatchIndex(64u);
    if (i >= uint(uCount)) return;
    ivec2 p = pixels[i];
    if (uMode == 0) {
        imageAtomicMin(uOwner, p, i);
        return;
    }
    uint keeper = imageLoad(uOwner, p).r;
    keepers[i] = keeper;
    if (keeper == i) imageStore(uSeeds, p, vec4(vec2(p), float(i), 0.0));
}
