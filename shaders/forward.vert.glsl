#version 450 core
// World-space position, normal, texture coordinate and vertex colour for the eye's passes.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aTexcoord;
layout(location = 3) in vec4 aColor; // COLOR_0 (white where the mesh has none)

uniform mat4 uViewProj;
uniform mat4 uModel;
uniform mat3 uNormalMatrix;
// The previous frame's camera (the surfaces pass's motion target). The scene is static, so the
// point's previous world position is its current one.
uniform mat4 uPreviousViewProj;

out vec3 vWorld;
out vec3 vNormal;
out vec2 vTexcoord;
out vec4 vColor;
out vec4 vPreviousClip;

void main() {
    vec4 world = uModel * vec4(aPosition, 1.0);
    vWorld = world.xyz;
    vNormal = uNormalMatrix * aNormal;
    vTexcoord = aTexcoord;
    vColor = aColor;
    vPreviousClip = uPreviousViewProj * world;
    gl_Position = uViewProj * world;
}
