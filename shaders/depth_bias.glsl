// The light's post-perspective depth (window range [0, 1]) of a fragment plus the depth bias,
// shared by the shadow pass and the passes that must reproduce its depths bit for bit (JFA-E's
// occluder ids draw over the finished map with LEQUAL). The bias is glPolygonOffset's, computed
// here because fixed-function polygon offset acts on the warped depth, which TSM does not use:
// slope = the larger depth change per shadow-map texel, unit = the smallest float32 depth step at
// this depth (2^(exponent - 23)). `lightZW`: the light clip-space z and w (shadow_depth.vert.glsl).
uniform float uSlopeBias;
uniform float uConstantBias;

float biasedLightDepth(vec2 lightZW) {
    float z = lightZW.x / lightZW.y * 0.5 + 0.5;
    float slope = max(abs(dFdx(z)), abs(dFdy(z)));
    int e;
    frexp(max(z, 1e-30), e); // z = m * 2^e, m in [0.5, 1): float32 step is 2^(e - 24)
    return z + uSlopeBias * slope + uConstantBias * ldexp(1.0, e - 24);
}
