#version 450 core
#include "bindings.glsl"
// Shows a grid (a flood's cells, a depth map, a mask) texel by texel in the viewport: the
// fragment at viewport pixel p reads texel floor(p * size / viewport), so a viewport of the
// grid's size shows it 1:1. Modes (OverlayCanvas::GridMode):
//  0 depth:    A.r as a ramp (1 = nothing seen, drawn dark); with uLightSpace the viewport spans
//              light NDC [-1,1]^2 and each fragment is warped by uWarp into the map first (TSM);
//  1 seeds:    non-empty cells (w != 0) in a colour per texel, others black;
//  2 occluder: the visible light fraction from occluder A.xyz at receiver B.xyz (ramp; empty
//              cells dark grey, no receiver black); uEyeSpace: B.w = 1 means "in hard shadow";
//  3 voronoi:  colour per site id (A.z), sites black, texels with C.r != 0 red (errors);
//  4 distance: distance from the texel to the site A.xy over uScale (ramp), errors red;
//  5 diff:     texels where A and B hold different cells red, equal non-empty ones grey.
#include "overlay_colour.glsl"
#include "disk_light.glsl"

layout(location = 0) out vec4 oColor;
layout(binding = FL_TEX_OVERLAY_A) uniform sampler2D uA;
layout(binding = FL_TEX_OVERLAY_B) uniform sampler2D uB;
layout(binding = FL_TEX_OVERLAY_C) uniform sampler2D uC;
uniform int uMode;
uniform ivec4 uViewport; // x, y, width, height of the viewport in framebuffer pixels
uniform float uScale;
uniform int uLightSpace;
uniform int uEyeSpace;
uniform mat4 uWarp;

const vec3 kEmpty = vec3(0.12);
const vec3 kError = vec3(1.0, 0.0, 0.0);

void main() {
    ivec2 size = textureSize(uA, 0);
    vec2 p = gl_FragCoord.xy - vec2(uViewport.xy); // pixel centre in the viewport
    ivec2 t = clamp(ivec2(floor(p * vec2(size) / vec2(uViewport.zw))), ivec2(0), size - 1);
    vec4 a = texelFetch(uA, t, 0);
    vec3 c = vec3(0.0);
    if (uMode == 0) {
        if (uLightSpace != 0) {
            vec2 ndc = p / vec2(uViewport.zw) * 2.0 - 1.0;
            vec4 q = uWarp * vec4(ndc, 0.0, 1.0);
            vec2 uv = q.xy / q.w * 0.5 + 0.5;
            if (!(q.w > 0.0) || any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0)))) {
                oColor = vec4(kEmpty, 1.0);
                return;
            }
            a = texelFetch(uA, ivec2(uv * vec2(size)), 0);
        }
        c = a.r >= 1.0 ? vec3(0.0) : overlayRamp(1.0 - a.r);
    } else if (uMode == 1) {
        c = a.w != 0.0 ? overlayIdColour(uint(t.y * size.x + t.x)) : vec3(0.0);
    } else if (uMode == 2) {
        vec4 r = texelFetch(uB, t, 0);
        bool hasReceiver = uEyeSpace != 0 ? r.w >= 0.0 : r.w != 0.0;
        if (!hasReceiver) c = vec3(0.0);
        else if (a.w == 0.0) c = kEmpty;
        else {
            float v = occluderIntensity(r.xyz, a.xyz, uEyeSpace != 0 && r.w == 1.0);
            c = v < 0.0 ? kEmpty : overlayRamp(v);
        }
    } else if (uMode == 3) {
        if (a.z < 0.0) c = kEmpty;
        else if (floor(a.xy + 0.5) == vec2(t)) c = vec3(0.0);
        else c = overlayIdColour(uint(a.z));
        if (texelFetch(uC, t, 0).r != 0.0) c = kError;
    } else if (uMode == 4) {
        if (a.z < 0.0) c = kEmpty;
        else c = overlayRamp(length(a.xy - vec2(t)) / uScale);
        if (texelFetch(uC, t, 0).r != 0.0) c = kError;
    } else {
        vec4 b = texelFetch(uB, t, 0);
        if (a != b) c = kError;
        else c = a.w != 0.0 ? vec3(0.45) : vec3(0.0);
    }
    oColor = vec4(c, 1.0);
}
