#version 450 core
#include "bindings.glsl"
// Step 4 of a frame: shading, shared by every shadow method. The surfaces of step 2 shaded with
// the method's visibility (shade.glsl).
#include "shade.glsl"
#include "surface_decode.glsl"

// SurfacesPass: positions (surfacePosition)
layout(binding = FL_TEX_SURFACES_DEPTH) uniform sampler2D uDepth;
// SurfacesPass: octahedral normals
layout(binding = FL_TEX_SURFACES_NORMALS) uniform sampler2D uNormals;
// SurfacesPass: sRGB base colour
layout(binding = FL_TEX_SURFACES_BASE_COLOR) uniform sampler2D uBaseColor;
layout(binding = FL_TEX_VISIBILITY) uniform sampler2D uVisibility; // the method's, R32F

layout(location = 0) out vec4 oColor; // linear; alpha 0 where nothing was drawn

const vec3 kSky = vec3(0.50, 0.64, 0.82);

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 world = surfacePosition(uDepth, p);
    if (world.w == 0.0) {
        oColor = vec4(kSky, 0.0);
        return;
    }
    vec3 n = surfaceNormal(uNormals, p);
    vec3 base = surfaceBaseColor(uBaseColor, p);
    float visibility = texelFetch(uVisibility, p, 0).r;
    oColor = vec4(shade(base, n, world.xyz, visibility), 1.0);
}
