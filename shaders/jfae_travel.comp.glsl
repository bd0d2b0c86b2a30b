#version 450 core
#include "bindings.glsl"
// JFA-E's measured pass count (fl::EyeFloodEstimator): how far each cell of the coarse flood
// travelled from its seed (cell w = seed pixel index + 1), Chebyshev distance in pixels, counted
// in a histogram whose last bin also holds every farther cell. Same as fl::floodTravel.

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = FL_TEX_FLOODED) uniform sampler2D uFlooded;
layout(std430, binding = FL_SSBO_TRAVEL_BINS) buffer Travel { uint bins[]; };

void main() {
    ivec2 size = textureSize(uFlooded, 0);
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, size))) return;
    float w = texelFetch(uFlooded, p, 0).r; // packed cells: w alone (jfae_criterion.glsl)
    if (w == 0.0) return;
    int index = int(w) - 1;
    ivec2 d = abs(p - ivec2(index % size.x, index / size.x));
    atomicAdd(bins[min(max(d.x, d.y), bins.length() - 1)], 1u);
}
