// Reading the surfaces pass's packed targets (renderer/passes/SurfacesPass.h lists them). The
// CPU twin is renderer/passes/SurfaceDecode.h: keep the two in step. Every reader goes through
// these helpers, so the packing is written down in exactly two places.
#include "color.glsl"

// The inverse of the reversed-Z view-projection the depth was written with
// (fl::surface::inverseReversedViewProj; bind it with SurfacePositions::bind).
uniform mat4 uSurfaceInverseViewProj;

const float kSurfaceBackgroundDepth = 0.0; // reversed Z: the cleared far plane

// World position of pixel `p` from the depth target: (xyz, 1), or vec4(0) for background.
// `precise`: JFA-E decodes a pixel in several shaders (boundaries, flood, composite) whose
// comparisons need the same bits everywhere, as phase 2's stored points gave them.
vec4 surfacePosition(sampler2D depth, ivec2 p) {
    float d = texelFetch(depth, p, 0).r;
    if (d == kSurfaceBackgroundDepth) return vec4(0.0);
    precise vec2 ndc = (vec2(p) + 0.5) / vec2(textureSize(depth, 0)) * 2.0 - 1.0;
    precise vec4 w = uSurfaceInverseViewProj * vec4(ndc, d, 1.0);
    precise vec3 world = w.xyz / w.w;
    return vec4(world, 1.0);
}

float surfaceSignNotZero(float v) { return v >= 0.0 ? 1.0 : -1.0; }

// A unit vector as two numbers in [-1, 1] (octahedral map, Cigolle et al. 2014).
vec2 octEncode(vec3 n) {
    n /= abs(n.x) + abs(n.y) + abs(n.z);
    if (n.z >= 0.0) return n.xy;
    return vec2((1.0 - abs(n.y)) * surfaceSignNotZero(n.x),
                (1.0 - abs(n.x)) * surfaceSignNotZero(n.y));
}
vec3 octDecode(vec2 e) {
    vec3 n = vec3(e, 1.0 - abs(e.x) - abs(e.y));
    if (n.z < 0.0)
        n.xy = vec2((1.0 - abs(e.y)) * surfaceSignNotZero(e.x),
                    (1.0 - abs(e.x)) * surfaceSignNotZero(e.y));
    return normalize(n);
}

// The normals target (RGBA16_SNORM): xy the shading normal facing the eye, zw the geometric
// (triangle) normal, both octahedral.
vec3 surfaceNormal(sampler2D normals, ivec2 p) { return octDecode(texelFetch(normals, p, 0).xy); }
vec3 surfacePlane(sampler2D normals, ivec2 p) { return octDecode(texelFetch(normals, p, 0).zw); }

// The base colour target (RGBA8): sRGB-encoded, so 8 bits keep the darks.
vec3 srgbToLinear(vec3 c) {
    return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), step(0.04045, c));
}
vec3 surfaceBaseColor(sampler2D baseColor, ivec2 p) {
    return srgbToLinear(texelFetch(baseColor, p, 0).rgb);
}
