#version 450 core
// HUD colours are display values (already what the window shows), blended with straight alpha.
in vec4 vColor;
layout(location = 0) out vec4 oColor;

void main() { oColor = vColor; }
