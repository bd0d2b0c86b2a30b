#version 450 core
// Light-space depth of the scene (shadow map). The texel position goes through the provider's
// warp (identity for the uniform map, N_T for TSM); the depth stays the light's own
// post-perspective depth, interpolated as clip z and w (both linear in the vertex, so
// perspective-correct interpolation in the warped space gives them exactly); the receiver
// target stores their ratio unbiased (shadow_map_decode.glsl). The texture coordinate and
// vertex alpha are passed on for the alpha cut-out (alpha_coverage.glsl). Vertices are posed
// as in the eye's passes (pose.glsl).
#include "pose.glsl"

layout(location = 0) in vec3 aPosition;
layout(location = 2) in vec2 aTexcoord;
layout(location = 3) in vec4 aColor;

uniform mat4 uLightViewProj;
uniform mat4 uShadowWarp;

out vec2 vLightZW;
out vec2 vTexcoord;
out float vAlpha;

void main() {
    vec4 world = poseWorld(aPosition, false);
    vTexcoord = aTexcoord;
    vAlpha = aColor.a;
    vec4 light = uLightViewProj * world;
    vLightZW = light.zw;
    gl_Position = uShadowWarp * light;
}
