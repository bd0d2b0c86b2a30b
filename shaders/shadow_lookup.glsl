// Shadow-map lookup shared by every shadow method, for either provider (uniform or TSM).
// A point's texel comes from the warped light space (uShadowWarp * uLightViewProj; the warp is
// the identity for a uniform map and N_T for TSM); its reference depth comes from the light's
// own post-perspective space (uLightViewProj), where the shadow pass stored depths and applied
// the bias.
#include "bindings.glsl"
#include "normal_offset.glsl"
layout(binding = FL_TEX_SHADOW_MAP) uniform sampler2DShadow uShadowMap;
uniform mat4 uLightViewProj;
uniform mat4 uShadowWarp;
// inverse(uLightViewProj) * (0, 0, 1, 0): with w != 0 the light's position (xyz / w), with w = 0
// (an orthographic map) the direction it travels (xyz).
uniform vec4 uShadowLight;

// Map coordinates of `world` for a map made with `lightViewProj` and `warp`: xy in [0,1]^2 on
// the map, z the reference depth in [0,1]. False if the point is behind the light or outside
// the map.
bool shadowCoordWith(mat4 lightViewProj, mat4 warp, vec3 world, out vec3 uvz) {
    vec4 light = lightViewProj * vec4(world, 1.0);
    vec4 map = warp * light;
    uvz = vec3(0.0);
    if (light.w <= 0.0 || map.w <= 0.0) return false;
    uvz = vec3(map.xy / map.w, light.z / light.w) * 0.5 + 0.5;
    return all(greaterThanEqual(uvz, vec3(0.0))) && all(lessThanEqual(uvz, vec3(1.0)));
}

// Unit vector from `world` towards the map's light.
vec3 shadowToLight(vec3 world) {
    return abs(uShadowLight.w) > 1e-30 ? normalize(uShadowLight.xyz / uShadowLight.w - world)
                                       : -normalize(uShadowLight.xyz);
}

// The world size of this map's texel at `world` (normal_offset.glsl's mapTexelWorld).
float shadowTexelWorld(vec3 world) {
    return mapTexelWorld(world, uShadowWarp * uLightViewProj, float(textureSize(uShadowMap, 0).x));
}

// The normal offset of a lookup of this map (normal_offset.glsl).
vec3 shadowNormalOffset(vec3 world, vec3 n) {
    return normalOffset(world, n, shadowToLight(world), uShadowWarp * uLightViewProj,
                        float(textureSize(uShadowMap, 0).x));
}

bool shadowCoord(vec3 world, out vec3 uvz) {
    return shadowCoordWith(uLightViewProj, uShadowWarp, world, uvz);
}

// 1 if `world` sees the light's centre, 0 if the shadow map holds something nearer.
// Points outside the light's map are treated as lit.
float hardShadow(vec3 world) {
    vec3 uvz;
    if (!shadowCoord(world, uvz)) return 1.0;
    return texture(uShadowMap, uvz);
}
