#version 450 core
// Ground truth, eye pass: the world position of the visible surface per pixel (w = 1; the clear
// value w = 0 marks background). The N accumulation passes read it.
in vec3 vWorld;
in vec3 vNormal;
in vec2 vTexcoord;

layout(location = 0) out vec4 oPoint;

void main() { oPoint = vec4(vWorld, 1.0); }
