#version 450 core
// JFA-E, for the object-ID fix (thesis §5.4.2): the object id of the surface the light's centre
// sees at each shadow-map texel. Drawn over the finished shadow map with depth test LEQUAL and
// no depth writes, so only the fragment that won the shadow pass (or an exact tie) writes. For
// that the depth below must be bit-identical to shaders/shadow_depth.frag.glsl's: same inputs
// (shadow_depth.vert.glsl), same operations.
in vec2 vLightZW;
in vec3 vWorld;

layout(location = 0) out float oObjectId;

uniform float uSlopeBias;
uniform float uConstantBias;
uniform int uObjectId;

void main() {
    float z = vLightZW.x / vLightZW.y * 0.5 + 0.5;
    float slope = max(abs(dFdx(z)), abs(dFdy(z)));
    int e;
    frexp(max(z, 1e-30), e);
    gl_FragDepth = z + uSlopeBias * slope + uConstantBias * ldexp(1.0, e - 24);
    oObjectId = float(uObjectId);
}
