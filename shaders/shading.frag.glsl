#version 450 core
// Step 4 of a frame: shading, shared by every shadow method. The surfaces of step 2 shaded with
// the method's visibility (shade.glsl).
#include "shade.glsl"

layout(binding = 0) uniform sampler2D uPosition;
layout(binding = 1) uniform sampler2D uNormal;
layout(binding = 2) uniform sampler2D uBaseColor;
layout(binding = 3) uniform sampler2D uVisibility; // the method's, R32F

layout(location = 0) out vec4 oColor;      // linear; alpha 0 where nothing was drawn
layout(location = 1) out float oVisibility; // the method's visibility; 1 for background

const vec3 kSky = vec3(0.50, 0.64, 0.82);

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 world = texelFetch(uPosition, p, 0);
    if (world.w == 0.0) {
        oColor = vec4(kSky, 0.0);
        oVisibility = 1.0;
        return;
    }
    vec3 n = texelFetch(uNormal, p, 0).xyz;
    vec4 base = texelFetch(uBaseColor, p, 0);
    float visibility = texelFetch(uVisibility, p, 0).r;
    oColor = vec4(shade(base.rgb, n, world.xyz, visibility), 1.0);
    oVisibility = visibility;
}
