// The shading model of step 4, shared by the opaque surfaces (shading.frag.glsl) and the blended
// ones drawn over them (blended.frag.glsl): Lambert from the scene light scaled by a visibility,
// plus hemispheric ambient.
#include "light.glsl"

uniform vec3 uLightColor;

const vec3 kSkyAmbient = vec3(0.20, 0.23, 0.28);
const vec3 kGroundAmbient = vec3(0.08, 0.07, 0.06);

/// Linear colour of a surface point of colour `base` and unit normal `n` facing the eye.
vec3 shade(vec3 base, vec3 n, vec3 world, float visibility) {
    float lambert = max(dot(n, toLight(world)), 0.0);
    vec3 ambient = mix(kGroundAmbient, kSkyAmbient, 0.5 + 0.5 * n.y);
    return base * (ambient + uLightColor * lambert * visibility);
}
