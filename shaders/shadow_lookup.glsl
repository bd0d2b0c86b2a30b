// Hard shadow-map test shared by every method that needs the binary answer.
// Depth is compared in the light's post-perspective space, where the shadow map was written;
// the bias was applied when the map was drawn (slope-scaled polygon offset).
layout(binding = 1) uniform sampler2DShadow uShadowMap;
uniform mat4 uLightViewProj;

// 1 if `world` sees the light's centre, 0 if the shadow map holds something nearer.
// Points outside the light's frustum are treated as lit.
float hardShadow(vec3 world) {
    vec4 clip = uLightViewProj * vec4(world, 1.0);
    if (clip.w <= 0.0) return 1.0;
    vec3 ndc = clip.xyz / clip.w;
    vec3 uvz = ndc * 0.5 + 0.5;
    if (any(lessThan(uvz, vec3(0.0))) || any(greaterThan(uvz, vec3(1.0)))) return 1.0;
    return texture(uShadowMap, uvz);
}
