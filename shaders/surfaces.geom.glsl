#version 450 core
// Step 2's geometry stage: passes each triangle through unchanged and hands its fragments what
// the smooth surface over it needs (terminator.glsl), worked out once per triangle: each vertex
// normal as a plane through its vertex, (n, n . a), and the barycentric weights, so that the
// fragment stage's lift (Hanika's terminator offset) is three dot products.
#include "terminator.glsl"

layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

in vec3 vWorld[];
in vec3 vNormal[];
in vec2 vTexcoord[];
in vec4 vColor[];
#ifdef FL_MOTION
in vec4 vPreviousClip[];
out vec4 fPreviousClip;
#endif

out vec3 fWorld;
out vec3 fNormal;
out vec2 fTexcoord;
out vec4 fColor;
out vec3 fBarycentric;
flat out vec4 fTangentPlane[3];
flat out vec3 fFront; // the triangle's plane, on its vertex normals' side

void main() {
    vec3 corner[3] = vec3[3](vWorld[0], vWorld[1], vWorld[2]);
    vec3 normals[3] = vec3[3](vNormal[0], vNormal[1], vNormal[2]);
    vec4 planes[3];
    vec3 front = terminatorPlanes(corner, normals, planes);
    for (int i = 0; i < 3; ++i) {
        fTangentPlane[0] = planes[0];
        fTangentPlane[1] = planes[1];
        fTangentPlane[2] = planes[2];
        fFront = front;
        fWorld = vWorld[i];
        fNormal = vNormal[i];
        fTexcoord = vTexcoord[i];
        fColor = vColor[i];
#ifdef FL_MOTION
        fPreviousClip = vPreviousClip[i];
#endif
        fBarycentric = vec3(i == 0 ? 1.0 : 0.0, i == 1 ? 1.0 : 0.0, i == 2 ? 1.0 : 0.0);
        gl_Position = gl_in[i].gl_Position;
        EmitVertex();
    }
    EndPrimitive();
}
