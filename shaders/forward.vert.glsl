#version 450 core
// World-space position, normal, texture coordinate and vertex colour for the eye's passes, posed
// (pose.glsl), and with FL_MOTION where the point was in the previous frame (the surfaces pass's
// motion target; without it, the previous pose is not evaluated at all).
#include "pose.glsl"

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aTexcoord;
layout(location = 3) in vec4 aColor; // COLOR_0 (white where the mesh has none)

uniform mat4 uViewProj;
uniform mat3 uNormalMatrix;     // the instance's (unskinned); skinned normals use the blend

out vec3 vWorld;
out vec3 vNormal;
out vec2 vTexcoord;
out vec4 vColor;
#ifdef FL_MOTION
uniform mat4 uPreviousViewProj; // the previous frame's camera
out vec4 vPreviousClip;
#endif

void main() {
    vec4 world = poseWorld(aPosition, false);
    vWorld = world.xyz;
    vec3 normal = morphed(aNormal, 1, false);
    // Skinned: the blend's upper 3x3 (exact for rigid joints, the usual case; glTF does not
    // require more).
    vNormal = uJointBase < 0 ? uNormalMatrix * normal : mat3(poseModel(false)) * normal;
    vTexcoord = aTexcoord;
    vColor = aColor;
#ifdef FL_MOTION
    vPreviousClip = uPreviousViewProj * poseWorld(aPosition, true);
#endif
    gl_Position = uViewProj * world;
}
