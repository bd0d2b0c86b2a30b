// JFA-L phase 4 (thesis §5.3.1, "Generating Final Image"): hard-shadowed points get 0 (with
// --penumbra both, the inner half: the part of the disk their texel's occluder leaves); a point
// whose penumbra-map texel holds an occluder gets the intensity recomputed here, at the point
// itself (not the value at the texel, which would make the penumbra blocky where the shadow map
// is coarse); everything else is lit. Needs shadow_lookup.glsl. The map's cells are packed
// (jfa_penumbra.glsl): the occluder comes back from the shadow map's receiver target. CPU twin
// of --penumbra both (both passes): renderer/soft/PenumbraLookup.h.
#include "bindings.glsl"
#include "disk_light.glsl"
#include "shadow_map_decode.glsl"
#ifdef SOFT_PENUMBRA_BOTH
#include "occluder_edge.glsl"
#define OCCLUDER_LINES_FUSE 1
#include "occluder_lines.glsl"
#endif

layout(binding = FL_TEX_PENUMBRA_MAP) uniform sampler2D uPenumbraMap;
// MapPositions::bind
layout(binding = FL_TEX_PENUMBRA_RECEIVERS) uniform sampler2D uPenumbraReceivers;
// --penumbra both (SOFT_PENUMBRA_BOTH): a hard-shadowed point sees the part of the disk past its
// texel's occluder (the inner half, from 0 deep in the umbra to 0.5 at the hard edge); without it
// (outer) 0 there, the thesis' lookup unchanged.
#ifndef SOFT_PENUMBRA_BOTH
float penumbraMapVisibility(vec3 world, vec3 tested, vec3 plane) {
    vec3 uvz;
    if (!shadowCoord(world, uvz)) return 1.0;
    if (hardShadow(tested) < 0.5) return 0.0;
    ivec2 size = textureSize(uPenumbraMap, 0);
    ivec2 t = clamp(ivec2(uvz.xy * vec2(size)), ivec2(0), size - 1);
    vec4 o = mapSeedCell(uPenumbraReceivers, texelFetch(uPenumbraMap, t, 0).r);
    if (o.w == 0.0) return 1.0;
    float intensity = occluderIntensity(world, o.xyz, false);
    return intensity < 0.0 ? 1.0 : intensity;
}
#else
uniform float uSilhouetteThreshold; // the silhouette pass's (occluderEdgePoint)
// SurfacesPass: normals (surfacePlane)
layout(binding = FL_TEX_PENUMBRA_NORMALS) uniform sampler2D uPenumbraNormals;

// `plane`: the point's triangle normal, turned to the eye (surfacePlane). A hard-shadowed point
// whose surface faces away from the light's centre, or whose ray to the occluder enters its own
// surface, is shadowed by that surface whatever the occluder's edge leaves (the back of a post,
// a trunk, a cap's underside under their own silhouettes), so it stays 0: such a plane sees at
// most the sliver of the disk in front of it, nothing once it turns r / distance past grazing.
// Two passes (LightLookup::execute): the first (without PENUMBRA_EDGES) gives every point the
// value of the occluder's point and `edges` true where the edges recompute it (the texel or an
// axis neighbour holds an occluder); the second (PENUMBRA_EDGES) runs only at those points.
// The point's penumbra-map texel t, whether the hard test (at `tested`) shadows it, and the tag
// the map holds there; false off the map (lit).
bool penumbraTexel(vec3 world, vec3 tested, out ivec2 t, out bool inside, out float tag) {
    t = ivec2(0);
    inside = false;
    tag = 0.0;
    vec3 uvz;
    if (!shadowCoord(world, uvz)) return false;
    inside = hardShadow(tested) < 0.5;
    ivec2 size = textureSize(uPenumbraMap, 0);
    t = clamp(ivec2(uvz.xy * vec2(size)), ivec2(0), size - 1);
    tag = texelFetch(uPenumbraMap, t, 0).r;
    return true;
}

// The tag of the first axis neighbour of texel t that holds one, 0 for none.
float neighbourTag(ivec2 t) {
    ivec2 size = textureSize(uPenumbraMap, 0);
    float tag = 0.0;
    for (int k = 0; k < 4 && tag == 0.0; ++k) {
        ivec2 q = clamp(t + ivec2(k == 0 ? 1 : k == 1 ? -1 : 0, k == 2 ? 1 : k == 3 ? -1 : 0),
                        ivec2(0), size - 1);
        tag = texelFetch(uPenumbraMap, q, 0).r;
    }
    return tag;
}

#ifndef PENUMBRA_EDGES
float penumbraMapVisibility(vec3 world, vec3 tested, vec3 plane, out bool edges) {
    edges = false;
    ivec2 t;
    bool inside;
    float tag;
    if (!penumbraTexel(world, tested, t, inside, tag)) return 1.0;
    edges = uDiskRadius > 0.0 && (tag != 0.0 || neighbourTag(t) != 0.0);
    vec4 o = mapSeedCell(uPenumbraReceivers, tag);
    float lit = inside ? 0.0 : 1.0; // no occluder, or its ray misses the disk
    if (o.w == 0.0) return lit;
    // The occluder's point at the silhouette's edge, not its texel's centre half a texel inside
    // (occluder_edge.glsl says why; the flood ranks the centres).
    o.xyz = occluderEdgePoint(uPenumbraReceivers,
                              mapSeedTexel(o.w, textureSize(uPenumbraReceivers, 0).x),
                              uSilhouetteThreshold);
    if (inside && (dot(plane, uDiskCenter - world) <= 0.0 || dot(plane, o.xyz - world) <= 0.0))
        return 0.0;
    float intensity = occluderIntensity(world, o.xyz, inside);
    return intensity < 0.0 ? lit : intensity;
}
#else
float penumbraMapVisibility(vec3 world, vec3 tested, vec3 plane) {
    ivec2 t;
    bool inside;
    float tag;
    if (!penumbraTexel(world, tested, t, inside, tag)) return 1.0;
    // A texel the flood left empty next to one it reached borrows its neighbour's occluder:
    // the flood takes an occluder where the ray through its point reaches the disk, but the
    // point lies up to a texel off the edge, so a penumbra's outermost ring can be missed.
    bool borrowed = false;
    if (tag == 0.0) {
        tag = neighbourTag(t);
        borrowed = tag != 0.0;
    }
    vec4 o = mapSeedCell(uPenumbraReceivers, tag);
    float lit = inside ? 0.0 : 1.0; // no occluder, or its ray misses the disk
    if (o.w == 0.0) return lit;
    // The occluder's edges at sub-texel precision (occluder_lines.glsl says why) around its
    // silhouette texel (a seed: an edge always lies in its window); without them, its point at
    // the silhouette's edge, not its texel's centre half a texel inside (occluder_edge.glsl; the
    // flood ranks the centres), fused.
    ivec2 ot = mapSeedTexel(o.w, textureSize(uPenumbraReceivers, 0).x);
    OccluderLines lines = occluderLines(uPenumbraReceivers, ot, world, plane);
    o.xyz = lines.count > 0 ? lines.point[0]
                            : occluderEdgePoint(uPenumbraReceivers, ot, uSilhouetteThreshold);
    if (inside && (dot(plane, uDiskCenter - world) <= 0.0 || dot(plane, o.xyz - world) <= 0.0))
        return 0.0;
    float intensity = borrowed ? -1.0 : occluderIntensity(world, o.xyz, inside);
    // The edges give the share where the occluder's point does shade p (its ray reaches the
    // disk; or borrowed): an edge of p's own surface, or one not between p and the light,
    // shades nothing.
    if (intensity >= 0.0 || borrowed) {
        float l = occluderShareFused(uPenumbraReceivers, t, world, plane, lines, o.xyz, inside,
                                     borrowed);
        intensity = l < 0.0 ? intensity : l;
    }
    return intensity < 0.0 ? lit : intensity;
}
#endif
#endif
