#version 450 core
#include "bindings.glsl"
// Visibility looked up in light space per eye pixel: the hard shadow-map test (hard), or with
// SOFT_PENUMBRA_MAP the intensity from the flooded penumbra map (JFA-L, flood-L; thesis §5.3.1
// phase 4). Reads the surfaces pass's world positions; background stays 1.
#include "shadow_lookup.glsl"
#ifdef SOFT_PENUMBRA_MAP
#include "soft_penumbra.glsl"
#endif
#include "surface_decode.glsl"
#include "surface_lookup.glsl"

// SurfacesPass: positions (surfacePosition)
layout(binding = FL_TEX_PENUMBRA_SURFACES_DEPTH) uniform sampler2D uDepth;

layout(location = 0) out float oVisibility;

void main() {
    vec4 world = surfacePosition(uDepth, ivec2(gl_FragCoord.xy));
    if (world.w == 0.0) {
        oVisibility = 1.0;
#if defined(SOFT_PENUMBRA_BOTH) && !defined(PENUMBRA_EDGES)
        gl_FragDepth = 1.0;
#endif
        return;
    }
    world.xyz = surfaceLookupPoint(world.xyz, ivec2(gl_FragCoord.xy));
    // The hard test's point: off the surface by the normal offset (shadow_lookup.glsl).
    vec3 tested = shadowNormalOffset(world.xyz, surfaceLookupPlane(ivec2(gl_FragCoord.xy)));
#ifdef SOFT_PENUMBRA_MAP
#ifdef SOFT_PENUMBRA_BOTH
    vec3 plane = surfacePlane(uPenumbraNormals, ivec2(gl_FragCoord.xy));
#ifdef PENUMBRA_EDGES
    oVisibility = penumbraMapVisibility(world.xyz, tested, plane);
#else
    // The first of two passes (soft_penumbra.glsl): depth 0 marks where the second runs.
    bool edges;
    oVisibility = penumbraMapVisibility(world.xyz, tested, plane, edges);
    gl_FragDepth = edges ? 0.0 : 1.0;
#endif
#else
    oVisibility = penumbraMapVisibility(world.xyz, tested, vec3(0.0)); // outer: no plane read
#endif
#else
    oVisibility = hardShadow(tested);
#endif
}
