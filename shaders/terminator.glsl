// The shadow terminator of smooth-shaded low-poly surfaces, for the shadow maps' lookups: where a
// triangle is grazed by the light, every map method looks its shadow up from the smooth surface
// its vertex normals describe, not from the flat triangle, by the rule the ray-traced truth uses
// (raytrace/Terminator.h: Hanika's offset, "Hacking the Shadow Terminator", Ray Tracing Gems II
// ch. 4, applied as Blender Cycles applies its geometry offset). Without it the map sees the
// facets, and a point of a triangle turned slightly from the light lies behind its neighbour's
// edge: curved bodies get dark teeth along the terminator that the rays do not show.
// CPU twin: renderer/passes/TerminatorLift.h, operation for operation.

// Cycles' geometry offset (intern/cycles/kernel/light/sample.h, its default 0.1): the range of
// cos(angle to the light) over which the offset fades in. Keep equal to rt::kGeometryOffset
// (raytrace/Terminator.h), the truth's.
const float kTerminatorOffset = 0.1;

// Per triangle (the geometry stage): each unit vertex normal as the plane through its vertex,
// (n, dot(n, a)), turned to the side of the triangle's plane the normals face; that plane
// (returned). All zero for a degenerate triangle, a zero normal or a flat triangle (every normal
// within 1e-6 of the plane's, 1 - cos): there the lift is 0, as the rays start on the triangle.
vec3 terminatorPlanes(vec3 corner[3], vec3 normals[3], out vec4 planes[3]) {
    planes = vec4[3](vec4(0.0), vec4(0.0), vec4(0.0));
    vec3 c = cross(corner[1] - corner[0], corner[2] - corner[0]);
    float area = length(c);
    if (!(area > 0.0)) return vec3(0.0);
    vec3 front = c / area;
    vec3 n[3];
    vec3 sum = vec3(0.0);
    for (int i = 0; i < 3; ++i) {
        float len = length(normals[i]);
        if (!(len > 0.0)) return vec3(0.0);
        n[i] = normals[i] / len;
        sum += n[i];
    }
    if (dot(sum, front) < 0.0) front = -front;
    bool flatTriangle = true;
    for (int i = 0; i < 3; ++i) flatTriangle = flatTriangle && dot(n[i], front) >= 1.0 - 1e-6;
    if (flatTriangle) return vec3(0.0);
    for (int i = 0; i < 3; ++i) planes[i] = vec4(n[i], dot(n[i], corner[i]));
    return front;
}

// Hanika's move of point p (barycentric weights w) onto the smooth surface, seen from the side
// `side` faces: p projected onto each vertex's tangent plane where that moves it outward, the
// projections blended by the weights. Seen from the back of the triangle (a double-sided
// surface), the normals turn with it. Zero where the move would go below the seen plane.
vec3 terminatorMove(vec3 p, vec3 w, vec4 planes[3], vec3 front, vec3 side) {
    float s = dot(front, side) < 0.0 ? -1.0 : 1.0;
    vec3 move = vec3(0.0);
    for (int i = 0; i < 3; ++i) {
        float e = s * (dot(planes[i].xyz, p) - planes[i].w); // above the tangent plane: > 0
        move -= w[i] * min(e, 0.0) * s * planes[i].xyz;
    }
    return dot(move, s * front) < 0.0 ? vec3(0.0) : move;
}

// How much of the move applies (Cycles' rule): all of it where the triangle turns from the light
// (its plane's cos to the light ngl <= 0), none where it faces the light by more than the
// offset, and a ramp between; where the smooth surface itself is grazed (nl < offset) the ramp
// follows both. `nl`, `ngl`: the shading normal's and the plane's cos to the light.
float terminatorAmount(float nl, float ngl) {
    return nl < kTerminatorOffset ? clamp(2.0 - (ngl + nl) / kTerminatorOffset, 0.0, 1.0)
                                  : clamp(1.0 - ngl / kTerminatorOffset, 0.0, 1.0);
}
