#version 450 core
// Step 4 of a frame: shading, shared by every shadow method. Lambert from the scene light
// scaled by the method's visibility, plus hemispheric ambient, from the surfaces of step 2.
#include "light.glsl"

layout(binding = 0) uniform sampler2D uPosition;
layout(binding = 1) uniform sampler2D uNormal;
layout(binding = 2) uniform sampler2D uBaseColor;
layout(binding = 3) uniform sampler2D uVisibility; // the method's, R32F

layout(location = 0) out vec4 oColor;      // linear; alpha 0 where nothing was drawn
layout(location = 1) out float oVisibility; // the method's visibility; 1 for background

uniform vec3 uLightColor;

const vec3 kSky = vec3(0.50, 0.64, 0.82);
const vec3 kSkyAmbient = vec3(0.20, 0.23, 0.28);
const vec3 kGroundAmbient = vec3(0.08, 0.07, 0.06);

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
    float lambert = max(dot(n, toLight(world.xyz)), 0.0);
    vec3 ambient = mix(kGroundAmbient, kSkyAmbient, 0.5 + 0.5 * n.y);
    vec3 color = base.rgb * (ambient + uLightColor * lambert * visibility);
    oColor = vec4(color, 1.0);
    oVisibility = visibility;
}
