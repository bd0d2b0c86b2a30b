#version 450 core
#include "bindings.glsl"
// VSM step 1: the shadow map's depths as moments (d, d^2) of the light-view depth d (distance
// along the light's axis, linear, so the blur averages depths and not their projective warp).
// the shadow map through a non-comparing sampler
layout(binding = FL_TEX_VSM_DEPTH) uniform sampler2D uDepth;
uniform mat4 uInvLightProj;

layout(location = 0) out vec2 oMoments;

void main() {
    float z = texelFetch(uDepth, ivec2(gl_FragCoord.xy), 0).r;
    vec4 v = uInvLightProj * vec4(0.0, 0.0, 2.0 * z - 1.0, 1.0);
    float d = -v.z / v.w;
    oMoments = vec2(d, d * d);
}
