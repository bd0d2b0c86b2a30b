#version 450 core
// Step 2 of a frame: the one geometry pass from the eye. Everything a shadow method, the shading
// pass and the metrics need about the visible surface of each pixel (renderer/passes/
// SurfacesPass.h lists the targets), packed: surface_decode.glsl reads them back. The depth
// target's clear value (reversed Z: 0) marks background; the colour targets are not cleared.
#include "alpha_coverage.glsl"
#include "light.glsl"
#include "surface_decode.glsl"
#include "terminator.glsl"

// From surfaces.geom.glsl: the interpolated attributes, and the triangle's corners.
in vec3 fWorld;
in vec3 fNormal;
in vec2 fTexcoord;
in vec4 fColor;
in vec3 fBarycentric;
flat in vec4 fTangentPlane[3];
flat in vec3 fFront;
#ifdef FL_MOTION
in vec4 fPreviousClip;
#endif

// The world position is not stored: surfacePosition() rebuilds it from the depth.
layout(location = 0) out vec4 oNormals;   // octahedral: xy shading normal facing the eye, zw plane
layout(location = 1) out vec4 oBaseColor; // material base colour (texture applied), sRGB-encoded
layout(location = 2) out float oReceiver; // 1 where the surface faces the light
// How far the shadow lookups move the point along its shading normal, world units (terminator.glsl)
layout(location = 3) out float oLift;
#ifdef FL_MOTION
layout(location = 4) out vec4 oMotion; // previous pixel xy, previous clip w, clip w
#endif

uniform vec2 uViewport; // the targets' size in pixels

void main() {
    // The receiver plane from the triangle (screen derivatives, in uniform control flow, so
    // before the cut-out's discard; its orientation does not matter, only the plane).
    // Degenerate derivatives fall back to the shading normal. The filtering methods (PCF, PCSS, VSM) test against this plane.
    vec3 g = cross(dFdx(fWorld), dFdy(fWorld));
    g = length(g) > 0.0 ? normalize(g) : normalize(fNormal);
    // MASK cut-outs; blended surfaces are not drawn here (GpuScene::Surfaces::Solid).
    discardCutOut(fTexcoord, fColor.a);
    vec4 base = baseColour(fTexcoord, fColor);
    vec3 n = normalize(fNormal);
    // Two-sided shading: the visible side of a surface faces the eye.
    if (!gl_FrontFacing) n = -n;
    oNormals = vec4(octEncode(n), octEncode(g));
    oBaseColor = vec4(linearToSrgb(base.rgb), 1.0);
    // Lambert > 0: the pixels whose visibility changes the image; the error metrics count only
    // these (renderer/metrics/Metrics.h).
    vec3 l = toLight(fWorld);
    oReceiver = dot(n, l) > 0.0 ? 1.0 : 0.0;
    // The plane on the seen side, as the shading normal is.
    vec3 plane = dot(g, n) < 0.0 ? -g : g;
    vec3 move = terminatorMove(fWorld, fBarycentric, fTangentPlane, fFront, plane);
    oLift = max(dot(move, n), 0.0) * terminatorAmount(dot(n, l), dot(plane, l));
#ifdef FL_MOTION
    // Where this point was a frame ago: window coordinates (as gl_FragCoord.xy) and depth. A
    // point behind the previous camera gets a position off every frame. Only the frames whose
    // flicker is scored write it (SurfacesPass::Inputs::previousCamera).
    vec2 previous = fPreviousClip.w > 0.0
                        ? (fPreviousClip.xy / fPreviousClip.w * 0.5 + 0.5) * uViewport
                        : vec2(-1.0e9);
    oMotion = vec4(previous, fPreviousClip.w, 1.0 / gl_FragCoord.w);
#endif
}
