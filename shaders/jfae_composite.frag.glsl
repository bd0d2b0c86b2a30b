#version 450 core
#include "bindings.glsl"
// JFA-E phase 5 (thesis §5.4.1, "Generating Final Image"): a pixel that holds an occluder after
// the flood is in penumbra; its intensity is recomputed at its own world position with the
// inside flag (inner penumbrae see the part of the light away from the centre). Otherwise the
// hard shadow decides: 0 inside, 1 lit (and 1 for background). Same as fl::eyeSoftVisibility.
// Points decode from phase 2's packed cells, seeds' occluders are phase 3's (eye_decode.glsl).
//
// With uOccluderEdges (--occluder-points edge, the default) the share is the one the occluder's
// edges leave (occluder_lines.glsl, from the seed's occluder texel at sub-texel precision, what
// another occluder covers past them fused in), where the flood's occluder point shades the
// pixel: a smooth ramp where the penumbra is a few map texels wide, and no light through an
// occluder one or two texels wide. Off, the thesis' point.
#include "shadow_lookup.glsl"
#include "disk_light.glsl"
#include "shadow_map_decode.glsl"
#include "occluder_edge.glsl"
#define OCCLUDER_LINES_FUSE 1
#include "occluder_lines.glsl"
#include "surface_decode.glsl"
#include "eye_decode.glsl"

// packed cells: the seed pixel's index + 1
layout(binding = FL_TEX_EYE_FLOODED) uniform sampler2D uFlooded;
// SurfacesPass: normals (surfacePlane, the receiver's plane for the fused test)
layout(binding = FL_TEX_EYE_NORMALS) uniform sampler2D uEyeNormals;
uniform int uOccluderEdges;

layout(location = 0) out float oVisibility;

// A pixel the flood left empty next to one it reached borrows its neighbour's occluder (edges
// only): the flood takes an occluder where the ray through its point reaches the disk, but the
// point lies up to a texel off the edge, so the outermost ring of a penumbra can be missed.
// Only from a neighbour on the pixel's own surface (within 30 degrees of its plane): across a
// depth jump the neighbour's occluder belongs to another surface's shadow.
float borrowedCell(ivec2 t, vec3 p, vec3 plane) {
    const ivec2 kAxis[4] = ivec2[4](ivec2(1, 0), ivec2(-1, 0), ivec2(0, 1), ivec2(0, -1));
    for (int k = 0; k < 4; ++k) {
        ivec2 q = t + kAxis[k];
        if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, textureSize(uFlooded, 0))))
            continue;
        float w = texelFetch(uFlooded, q, 0).r;
        if (w == 0.0) continue;
        vec4 n = eyeSurface(q);
        vec3 d = n.xyz - p;
        if (n.w != 0.0 && abs(dot(d, plane)) <= 0.5 * length(d)) return w;
    }
    return 0.0;
}

// Two passes (EyeSoftShadowPass::drawComposite): the first gives every pixel its thesis value
// (the hard result, or its occluder point's share) and marks in the depth target the pixels
// the edges will recompute (flooded, or next to a flooded pixel); the second, with
// COMPOSITE_EDGES, runs only there (an early depth test), so that the edges' fits cost only
// around the penumbrae: a software rasteriser runs every fragment of a block through both sides
// of a branch.
// Pixel t's receiver (eyePoint), its flood cell `w` and its hard value (0 in the hard shadow,
// else 1; what the thesis leaves where the flood brought no occluder).
vec4 compositePixel(ivec2 t, out float w, out float hard) {
    vec4 r = eyePoint(t);
    w = texelFetch(uFlooded, t, 0).r;
    hard = r.w == 1.0 ? 0.0 : 1.0;
    return r;
}

// Where the edges' window centres when the pixel's own texel has none (a wide penumbra): on the
// seed's occluder o, which phase 3 walked to the silhouette, moved a quarter of the way back to
// the seed's own texel's centre, so that it lies inside the occluder and off any texel's border
// (o itself is half a texel out from a centre, on a border). CPU twin: seedWindowTexel
// (EyeSoftShadow.cpp).
ivec2 seedWindowTexel(ivec2 seed, vec3 o) {
    ivec2 own = eyeCellTexel(texelFetch(uEyeCells, seed, 0).r);
    precise vec3 q = o + 0.25 * (mapReceiver(uEyeReceivers, own).xyz - o);
    vec3 uvz;
    ivec2 size = textureSize(uEyeReceivers, 0);
    if (!shadowCoord(q, uvz)) return own;
    return clamp(ivec2(uvz.xy * vec2(size)), ivec2(0), size - 1);
}

#ifndef COMPOSITE_EDGES
bool nextToFlooded(ivec2 t) {
    bool any = false;
    for (int k = 0; k < 4; ++k) {
        ivec2 q = t + ivec2(k == 0 ? 1 : k == 1 ? -1 : 0, k == 2 ? 1 : k == 3 ? -1 : 0);
        ivec2 c = clamp(q, ivec2(0), textureSize(uFlooded, 0) - 1);
        any = any || texelFetch(uFlooded, c, 0).r != 0.0;
    }
    return any;
}

void main() {
    ivec2 t = ivec2(gl_FragCoord.xy);
    float w, v;
    vec4 r = compositePixel(t, w, v);
    bool inside = r.w == 1.0;
    if (r.w >= 0.0 && w != 0.0) {
        float intensity = occluderIntensity(r.xyz, eyeSeedOccluder(eyeSeedPixel(w)).xyz, inside);
        v = intensity < 0.0 ? v : intensity;
    }
    oVisibility = v;
    bool edges = uOccluderEdges != 0 && r.w >= 0.0 && uDiskRadius > 0.0;
    gl_FragDepth = edges && (w != 0.0 || nextToFlooded(t)) ? 0.0 : 1.0;
}
#else
void main() {
    ivec2 t = ivec2(gl_FragCoord.xy);
    float w, v;
    vec4 r = compositePixel(t, w, v);
    bool inside = r.w == 1.0;
    bool borrowed = false;
    vec3 plane = surfacePlane(uEyeNormals, t);
    if (w == 0.0) {
        w = borrowedCell(t, r.xyz, plane);
        borrowed = w != 0.0;
    }
    if (w != 0.0) {
        vec3 o = eyeSeedOccluder(eyeSeedPixel(w)).xyz;
        float intensity = borrowed ? -1.0 : occluderIntensity(r.xyz, o, inside);
        if (intensity >= 0.0 || borrowed) {
            // The edges around the pixel's own texel where one lies within the window (the same
            // edges whichever seed the flood brought), else around the seed's occluder (a wide
            // penumbra: the seed lies at the edge; seedWindowTexel).
            ivec2 own = eyeCellTexel(texelFetch(uEyeCells, eyeFramePixel(t), 0).r);
            OccluderLines lines = occluderLines(uEyeReceivers, own, r.xyz, plane);
            if (lines.count == 0)
                lines = occluderLines(uEyeReceivers,
                                      seedWindowTexel(eyeFramePixel(eyeSeedPixel(w)), o), r.xyz,
                                      plane);
            float l = occluderShareFused(uEyeReceivers, own, r.xyz, plane, lines, o, inside,
                                         borrowed);
            intensity = l < 0.0 ? intensity : l;
        }
        v = intensity < 0.0 ? v : intensity;
    }
    oVisibility = v;
}
#endif
