// The point every shadow-map lookup of a pixel starts from: its surface position lifted along the
// shading normal by the surfaces pass's lift target (terminator.glsl: the smooth surface, where a
// smooth-shaded triangle is grazed by the light; the flat triangle everywhere else). Bind with
// SurfacesPass::Outputs::bindLookup. CPU twin: surface::lookupPoint (SurfaceDecode.h). Needs
// surface_decode.glsl.
#include "bindings.glsl"
layout(binding = FL_TEX_SURFACES_LIFT) uniform sampler2D uSurfaceLift;
layout(binding = FL_TEX_LOOKUP_NORMALS) uniform sampler2D uLookupNormals;

// The receiver's plane the lookups test against (hardShadowOnPlane, PCF, PCSS): the triangle's,
// or where the point was lifted onto the smooth surface, its tangent plane (the triangle's,
// extended a few texels at a grazing angle, would pass above the facets curving towards the
// light and shadow the point by its own body).
vec3 surfaceLookupPlane(ivec2 p) {
    return texelFetch(uSurfaceLift, p, 0).r > 0.0 ? surfaceNormal(uLookupNormals, p)
                                                  : surfacePlane(uLookupNormals, p);
}

vec3 surfaceLookupPoint(vec3 world, ivec2 p) {
    float lift = texelFetch(uSurfaceLift, p, 0).r;
    return lift > 0.0 ? world + lift * surfaceNormal(uLookupNormals, p) : world;
}
