#version 450 core
// Forward shading: Lambert from the scene light with a hard shadow, hemispheric ambient.
#include "shadow_lookup.glsl"
#include "light.glsl"
#ifdef SOFT_PENUMBRA_MAP
#include "soft_penumbra.glsl"
#endif
#ifdef SOFT_EYE_VISIBILITY
// JFA-E / flood-E: visibility computed in eye space for exactly these pixels.
layout(binding = 3) uniform sampler2D uEyeVisibility;
#endif

in vec3 vWorld;
in vec3 vNormal;
in vec2 vTexcoord;

layout(location = 0) out vec4 oColor;
layout(location = 1) out float oVisibility;
// 1 where the visible surface faces the light (Lambert > 0): the pixels whose visibility changes
// the image. Error metrics are measured over these only (renderer/Metrics.h).
layout(location = 2) out float oReceiver;

layout(binding = 0) uniform sampler2D uBaseColorTexture;
uniform vec4 uBaseColor;
uniform int uHasTexture;
uniform int uObjectId;
uniform vec3 uEye;
uniform vec3 uLightColor;

const vec3 kSkyAmbient = vec3(0.20, 0.23, 0.28);
const vec3 kGroundAmbient = vec3(0.08, 0.07, 0.06);

void main() {
    vec4 base = uBaseColor;
    if (uHasTexture != 0) base *= texture(uBaseColorTexture, vTexcoord);
    vec3 n = normalize(vNormal);
    // Two-sided shading: the visible side of a surface faces the eye.
    if (!gl_FrontFacing) n = -n;
    vec3 l = toLight(vWorld);
    float lambert = max(dot(n, l), 0.0);
#if defined(SOFT_EYE_VISIBILITY)
    float visibility = texelFetch(uEyeVisibility, ivec2(gl_FragCoord.xy), 0).r;
#elif defined(SOFT_PENUMBRA_MAP)
    float visibility = penumbraMapVisibility(vWorld);
#else
    float visibility = hardShadow(vWorld);
#endif
    vec3 ambient = mix(kGroundAmbient, kSkyAmbient, 0.5 + 0.5 * n.y);
    vec3 color = base.rgb * (ambient + uLightColor * lambert * visibility);
    oColor = vec4(color, 1.0);
    oVisibility = visibility;
    oReceiver = lambert > 0.0 ? 1.0 : 0.0;
}
