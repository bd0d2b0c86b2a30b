#version 450 core
// JFA-E's packed eye cells decoded into the EyeImage layout (two RGBA32F images: points and
// occluders) for what inspects a frame after it ran: the overlays and the tests, never the
// frame itself. Decodes through eye_decode.glsl, so these are the bits the phases read.
#include "disk_light.glsl"
#include "shadow_map_decode.glsl"
#include "occluder_edge.glsl"
#include "surface_decode.glsl"
#include "eye_decode.glsl"

layout(location = 0) out vec4 oPoint;
layout(location = 1) out vec4 oOccluder;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    oPoint = eyePoint(p);
    oOccluder = eyeOccluder(p);
}
