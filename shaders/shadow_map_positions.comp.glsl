#version 450 core
#include "bindings.glsl"
// The shadow map's receiver positions decoded into an RGBA32F image (ShadowMapPass::
// decodedReceivers): the overlays draw them and the tests hand them to the CPU kernels, which
// then see exactly the bits every other shader's mapReceiver() computes.
#include "shadow_map_decode.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = FL_TEX_MAP_RECEIVER_DEPTH) uniform sampler2D uReceiverDepth;
layout(binding = FL_IMG_MAP_POSITIONS, rgba32f) uniform writeonly image2D uDst;

void main() {
    ivec2 t = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(t, textureSize(uReceiverDepth, 0)))) return;
    imageStore(uDst, t, mapReceiver(uReceiverDepth, t));
}
