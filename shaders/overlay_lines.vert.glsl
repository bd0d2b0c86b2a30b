#version 450 core
// Lines and points of the overlays, given in viewport NDC with a colour per vertex.
layout(location = 0) in vec2 aPosition;
layout(location = 1) in vec4 aColor;
uniform float uPointSize;
out vec4 vColor;

void main() {
    vColor = aColor;
    gl_PointSize = uPointSize;
    gl_Position = vec4(aPosition, 0.0, 1.0);
}
