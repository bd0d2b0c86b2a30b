#version 450 core
#include "bindings.glsl"
// Shows the linear colour target in a window, sRGB-encoded.
#include "color.glsl"

in vec2 vUv;
layout(location = 0) out vec4 oColor;
layout(binding = FL_TEX_PRESENT_COLOR) uniform sampler2D uColor;

void main() { oColor = vec4(linearToSrgb(texture(uColor, vUv).rgb), 1.0); }
