#version 450 core
// Light-space depth of the scene (shadow map). The texel position goes through the provider's
// warp (identity for the uniform map, N_T for TSM); the depth stays the light's own
// post-perspective depth, interpolated as clip z and w (both linear in the vertex, so
// perspective-correct interpolation in the warped space gives them exactly). The world position
// is passed on for the receiver-position target that JFA-L floods over.
layout(location = 0) in vec3 aPosition;

uniform mat4 uLightViewProj;
uniform mat4 uShadowWarp;
uniform mat4 uModel;

out vec2 vLightZW;
out vec3 vWorld;

void main() {
    vec4 world = uModel * vec4(aPosition, 1.0);
    vWorld = world.xyz;
    vec4 light = uLightViewProj * world;
    vLightZW = light.zw;
    gl_Position = uShadowWarp * light;
}
