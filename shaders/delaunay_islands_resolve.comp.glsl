#version 450 core
#include "bindings.glsl"
// End of step G3 (thesis §6.3.2): the host queued its passes without knowing how many would run,
// so it cannot know which ping-pong texture holds the result. Pass j read the texture pass j - 1
// wrote and wrote islands[j % 2]; the passes that recoloured something are a prefix 0..m-1 of the
// queue (the loop stops at the first that does not), so the result is islands[(m - 1) % 2], or
// the flood's texture if m = 0. This pass copies it into `cleaned`, which G4-G6 read, and puts
// the loop's IslandStats into the result header.
#include "delaunay_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

// G2's texture, the first pass' input
layout(binding = FL_TEX_DELAUNAY_ISLANDS_IN) uniform usampler2D uIn;
layout(binding = FL_TEX_DELAUNAY_PING) uniform usampler2D uPing; // islands[0]
layout(binding = FL_TEX_DELAUNAY_PONG) uniform usampler2D uPong; // islands[1]
layout(binding = FL_IMG_DELAUNAY_OUT, r32ui) uniform writeonly uimage2D uCleaned;
layout(std430, binding = FL_SSBO_DELAUNAY_CONTROL) readonly buffer Control { uint control[]; };
layout(std430, binding = FL_SSBO_DELAUNAY_HEADER) buffer Header { uint header[]; };
uniform ivec2 uSize;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, uSize))) return;
    uint m = control[kCtlChanging];
    if (p == ivec2(0)) {
        header[kHeadPasses] = control[kCtlPasses];
        header[kHeadReassignedLo] = control[kCtlReassignedLo];
        header[kHeadReassignedHi] = control[kCtlReassignedHi];
        header[kHeadConverged] = control[kCtlConverged];
        header[kHeadUnfinished] = control[kCtlActive];
    }
    uint id;
    if (m == 0u)
        id = texelFetch(uIn, p, 0).r;
    else if ((m - 1u) % 2u == 0u)
        id = texelFetch(uPing, p, 0).r;
    else
        id = texelFetch(uPong, p, 0).r;
    imageStore(uCleaned, p, uvec4(id));
}
