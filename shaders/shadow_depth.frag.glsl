#version 450 core
// Writes the light's post-perspective depth (window range [0, 1]) plus the depth bias. The bias
// is glPolygonOffset's, computed here because fixed-function polygon offset acts on the warped
// depth, which TSM does not use: slope = the larger depth change per shadow-map texel, unit = the
// smallest float32 depth step at this depth (2^(exponent - 23)).
in vec2 vLightZW;
in vec3 vWorld;

// Receiver positions (only when the pass binds that target; otherwise discarded).
layout(location = 0) out vec4 oReceiver;

uniform float uSlopeBias;
uniform float uConstantBias;

void main() {
    float z = vLightZW.x / vLightZW.y * 0.5 + 0.5;
    float slope = max(abs(dFdx(z)), abs(dFdy(z)));
    int e;
    frexp(max(z, 1e-30), e); // z = m * 2^e, m in [0.5, 1): float32 step is 2^(e - 24)
    gl_FragDepth = z + uSlopeBias * slope + uConstantBias * ldexp(1.0, e - 24);
    oReceiver = vec4(vWorld, 1.0);
}
