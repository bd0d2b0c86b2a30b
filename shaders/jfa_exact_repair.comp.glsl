#version 450 core
#include "bindings.glsl"
// The exact repair of `voronoi --exact` (jfa/ExactRepair.h, whose comment proves it): each texel
// walks from the graph vertex its flooded cell names (w; vertex 0 when empty) to the best
// neighbour under the criterion while one is strictly better. The GL twin of
// fl::jfa::walkToNearest, texel for texel; integer sites only.

bool jfaEmpty(vec4 c);
bool jfaBetter(ivec2 p, vec4 a, vec4 b);

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = FL_TEX_FLOODED) uniform sampler2D uFlooded;
layout(binding = FL_IMG_REPAIR_OUT, rgba32f) uniform writeonly image2D uDst;
layout(std430, binding = FL_SSBO_REPAIR_VERTICES) readonly buffer Vertices { vec4 vertices[]; };
layout(std430, binding = FL_SSBO_REPAIR_OFFSETS) readonly buffer Offsets { uint offsets[]; };
layout(std430, binding = FL_SSBO_REPAIR_NEIGHBOURS) readonly buffer Neighbours {
    uint neighbours[];
};
uniform ivec2 uSize;
uniform int uVertexCount;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, uSize))) return;
    vec4 start = texelFetch(uFlooded, p, 0);
    bool empty = jfaEmpty(start);
    if ((!empty && ivec2(start.xy) == p) || uVertexCount == 0) { // a site's own pixel
        imageStore(uDst, p, start);
        return;
    }
    // A w the graph does not have starts at vertex 0 (the CPU twin throws on it instead).
    uint at = empty || start.w < 0.0 || start.w >= float(uVertexCount) ? 0u : uint(start.w);
    vec4 best = vertices[at];
    for (int moves = 0; moves < uVertexCount; ++moves) {
        uint next = at;
        for (uint k = offsets[at]; k < offsets[at + 1u]; ++k) {
            uint n = neighbours[k];
            vec4 c = vertices[n];
            if (jfaBetter(p, c, best)) {
                best = c;
                next = n;
            }
        }
        if (next == at) break;
        at = next;
    }
    imageStore(uDst, p, best);
}
