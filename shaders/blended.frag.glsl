#version 450 core
// Step 4b: glTF alphaMode BLEND surfaces, drawn over the shaded opaque image with their alpha
// ("over" blending, depth-tested against the eye's surfaces, no depth writes). They cast shadows
// (the light's passes cut them at alpha 0.5) but are not among the eye's surfaces that a shadow
// method shades, so they are lit without a shadow of their own.
#include "alpha_coverage.glsl"
#include "shade.glsl"

in vec3 vWorld;
in vec3 vNormal;
in vec2 vTexcoord;
in vec4 vColor;

layout(location = 0) out vec4 oColor;

void main() {
    vec4 base = baseColour(vTexcoord, vColor);
    vec3 n = normalize(vNormal);
    if (!gl_FrontFacing) n = -n;
    oColor = vec4(shade(base.rgb, n, vWorld, 1.0), clamp(base.a, 0.0, 1.0));
}
