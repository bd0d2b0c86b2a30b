// Alpha cut-outs (glTF alphaMode MASK, and BLEND in the light's passes) in every pass that draws
// the scene: a fragment whose alpha is below uAlphaCutoff is not there. The alpha is the
// material's base-colour alpha x the texture's x the vertex colour's (COLOR_0); GpuScene::draw sets
// the uniforms per instance. The CPU twin is renderer/scene/AlphaCoverage.
//
// Coverage reads the texture's level 0, not the mip level the derivatives pick: averaged alpha in
// the small mips shrinks cut-outs with distance (foliage thins out far away), and the light's
// passes see the surface at another scale than the eye, so mip-picked coverage would give the
// shadow a different shape from the surface that casts it, and from the CPU truth.
#include "bindings.glsl"

layout(binding = FL_TEX_MATERIAL_BASE_COLOR) uniform sampler2D uBaseColorTexture;
uniform vec4 uBaseColor;
uniform int uHasTexture;
uniform float uAlphaCutoff; // < 0: the material is opaque and alpha is ignored

/// The surface's alpha for the cut-out test.
float coverageAlpha(vec2 uv, float vertexAlpha) {
    float alpha = uBaseColor.a * vertexAlpha;
    if (uHasTexture != 0) alpha *= textureLod(uBaseColorTexture, uv, 0.0).a;
    return alpha;
}

/// Discards the fragment where the material cuts the surface out. Uniform control flow for
/// opaque materials: their fragments skip the texture read.
void discardCutOut(vec2 uv, float vertexAlpha) {
    if (uAlphaCutoff >= 0.0 && coverageAlpha(uv, vertexAlpha) < uAlphaCutoff) discard;
}

/// The material's base colour at the fragment (mip-mapped texture, as shading wants it).
vec4 baseColour(vec2 uv, vec4 vertexColour) {
    vec4 base = uBaseColor * vertexColour;
    if (uHasTexture != 0) base *= texture(uBaseColorTexture, uv);
    return base;
}
