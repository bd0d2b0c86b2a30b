#version 450 core
// JFA-L phase 2 (thesis §5.3.1, "Locating Occluders"): a shadow-map texel is a silhouette
// pixel, and so a seed carrying its world position, if one of its 8 neighbours sees nothing, or
// lies deeper from the light (along its normal) by more than uSilhouetteThreshold plus
// kSilhouetteSlope times their distance across the light's axis. The slope term keeps a
// continuous surface tilted up to atan(3) = 72 degrees away from the light from counting as a
// depth jump at any shadow-map resolution. Same as fl::silhouetteSeeds on the CPU.
#include "disk_light.glsl"

layout(binding = 0) uniform sampler2D uReceivers;
uniform float uSilhouetteThreshold;
const float kSilhouetteSlope = 3.0;

layout(location = 0) out vec4 oSeed;

float lightDepth(vec3 p) {
    precise float d = (p.x - uDiskCenter.x) * uDiskNormal.x + (p.y - uDiskCenter.y) * uDiskNormal.y +
                      (p.z - uDiskCenter.z) * uDiskNormal.z;
    return d;
}

void main() {
    ivec2 t = ivec2(gl_FragCoord.xy);
    ivec2 size = textureSize(uReceivers, 0);
    vec4 self = texelFetch(uReceivers, t, 0);
    float d = lightDepth(self.xyz);
    bool silhouette = false;
    for (int j = -1; j <= 1; ++j) {
        for (int i = -1; i <= 1; ++i) {
            ivec2 q = t + ivec2(i, j);
            bool inside = all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, size));
            vec4 n = texelFetch(uReceivers, clamp(q, ivec2(0), size - 1), 0);
            precise float deeper = lightDepth(n.xyz) - d;
            precise vec3 delta = n.xyz - self.xyz;
            precise vec3 across = delta - deeper * uDiskNormal;
            precise float lateral2 = across.x * across.x + across.y * across.y + across.z * across.z;
            precise float allowed = uSilhouetteThreshold + kSilhouetteSlope * sqrt(lateral2);
            bool edge = n.w == 0.0 || deeper > allowed;
            silhouette = silhouette || (inside && (i != 0 || j != 0) && edge);
        }
    }
    oSeed = self.w != 0.0 && silhouette ? vec4(self.xyz, 1.0) : vec4(0.0, 0.0, -1.0, 0.0);
}
