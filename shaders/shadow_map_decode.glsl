// Reading the shadow map's receiver target (renderer/passes/ShadowMapPass.h): per texel the
// light's unbiased post-perspective depth (NDC z, R32F), or kMapNoReceiver where the light sees
// nothing. The world position of texel t comes back through the map's own matrices: the texel
// centre is unwarped into the light's clip plane (uMapUnwarp, the inverse of the provider's warp
// on x, y and w; the identity for the uniform map) and unprojected at the stored depth
// (uMapInverseLightViewProj). The CPU twin is renderer/passes/ShadowMapDecode.h: keep the two in
// step. `precise` keeps every shader that decodes a texel (silhouettes, the flood's criterion,
// the reach bounds, JFA-E's occluder points) at the same bits, which the criterion's "a seed is
// its own texel's receiver" test needs.
uniform mat3 uMapUnwarp;
uniform mat4 uMapInverseLightViewProj;

const float kMapNoReceiver = -4.0;

// The light's clip-space ray through map coordinate `tc` (texels; texel t's centre is t + 0.5)
// of a `size` map: (x, y, w) of its light clip coordinates, z free (the map's NDC unwarped).
vec3 mapClipRay(vec2 tc, vec2 size) {
    precise vec2 uv = tc / size * 2.0 - 1.0;
    precise vec3 l = uMapUnwarp * vec3(uv, 1.0);
    return l;
}

// The world position at map coordinate `tc` and the light's NDC depth d: mapReceiver's
// unprojection at any point of the map.
vec3 mapUnproject(vec2 tc, vec2 size, float d) {
    precise vec3 l = mapClipRay(tc, size);
    // Light clip (l.x, l.y, d l.z, l.z) is NDC (l.xy / l.z, d) unscaled: one division, not two
    // (a division is not exact in GLSL and may round differently from shader to shader).
    precise vec4 w = uMapInverseLightViewProj * vec4(l.xy, d * l.z, l.z);
    precise vec3 p = w.xyz / w.w;
    return p;
}

// (xyz, 1) the world position the map's texel t sees, or vec4(0) where it sees nothing.
vec4 mapReceiver(sampler2D receiverDepth, ivec2 t) {
    float d = texelFetch(receiverDepth, t, 0).r;
    if (d == kMapNoReceiver) return vec4(0.0);
    return vec4(mapUnproject(vec2(t) + 0.5, vec2(textureSize(receiverDepth, 0)), d), 1.0);
}

// A silhouette seed's w (JFA-L): the texel it was found at, as the bits of 1.0 plus the texel's
// row-major index, a normal float in [1, 256) for maps up to 8192², never 0 (w = 0 is an empty
// cell), kept bit for bit by every copy. The flood knows a seed at its own texel by this tag,
// not by comparing positions: two shaders decoding one texel may differ in the last bit.
float mapSeedTag(ivec2 t, int width) {
    return uintBitsToFloat(0x3f800000u + uint(t.y * width + t.x));
}

// The texel of a seed tag (mapSeedTag's inverse).
ivec2 mapSeedTexel(float tag, int width) {
    uint index = floatBitsToUint(tag) - 0x3f800000u;
    return ivec2(int(index % uint(width)), int(index / uint(width)));
}

// A packed JFA-L cell (R32F: its seed's tag, 0 empty) as the criterion's vec4: the occluder is
// the surface the seed's texel sees, decoded from the receiver target as the silhouette pass
// decoded it; w the tag. Empty: the kernel's empty cell (0, 0, -1, 0).
vec4 mapSeedCell(sampler2D receiverDepth, float tag) {
    if (tag == 0.0) return vec4(0.0, 0.0, -1.0, 0.0);
    ivec2 t = mapSeedTexel(tag, textureSize(receiverDepth, 0).x);
    return vec4(mapReceiver(receiverDepth, t).xyz, tag);
}
