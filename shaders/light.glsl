// The scene light as the shading passes see it: a point/spot light at uLightPosition or a
// directional light travelling along uLightDirection.
uniform vec3 uLightPosition;
uniform vec3 uLightDirection;
uniform int uLightDirectional;

// Unit vector from `world` towards the light.
vec3 toLight(vec3 world) {
    return uLightDirectional != 0 ? -uLightDirection : normalize(uLightPosition - world);
}
