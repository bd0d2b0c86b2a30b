#version 450 core
// Step 2's geometry stage: passes each triangle through unchanged and hands its fragments the
// triangle's corners and vertex normals (flat) and their barycentric weights, so that the
// fragment stage can place the smooth surface the vertex normals describe over the flat
// triangle (terminator.glsl), as the ray-traced truth starts its rays there.
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
flat out vec3 fCorner[3];
flat out vec3 fCornerNormal[3];

void main() {
    for (int i = 0; i < 3; ++i) {
        for (int k = 0; k < 3; ++k) {
            fCorner[k] = vWorld[k];
            fCornerNormal[k] = vNormal[k];
        }
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
