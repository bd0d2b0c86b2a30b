#version 450 core
// JFA-E's measured pass count (fl::EyeFloodEstimator): phase 2's images point-sampled at
// 1/uFactor resolution, for a coarse flood that measures how far occluders travel. Coarse pixel
// (X, Y) copies frame pixel min(uFactor * (X, Y) + uFactor / 2, size - 1): a copy, not a filter,
// since positions, shadow flags and object ids do not average. Same as fl::coarseEyeImage.

layout(binding = 0) uniform sampler2D uEyePoints;
layout(binding = 1) uniform sampler2D uEyeOccluders;
uniform int uFactor;

layout(location = 0) out vec4 oPoint;
layout(location = 1) out vec4 oOccluder;

void main() {
    ivec2 size = textureSize(uEyePoints, 0);
    ivec2 t = min(ivec2(gl_FragCoord.xy) * uFactor + uFactor / 2, size - 1);
    oPoint = texelFetch(uEyePoints, t, 0);
    oOccluder = texelFetch(uEyeOccluders, t, 0);
}
