#version 450 core
#include "bindings.glsl"
// Step G6 (thesis §6.3.2), buildTriangles in geometry/DiscreteTriangles.h: one invocation per
// corner row (the thesis' one CUDA thread per row) walks the row's G5 chain from vertex to
// vertex and makes one triangle per three-colour vertex, two per four-colour vertex. Two walks:
// mode 0 counts each row's vertices and triangles into `rows`; delaunay_rows_scan turns the
// counts into each row's first vertex and triangle; mode 1 walks again and writes the records
// there, so they lie in the CPU's order (rows bottom to top, chain order within a row) in the
// result buffer that run() reads back once. Writes past the capacities are dropped; the header's
// totals tell the host to grow the buffer and run again.
#include "delaunay_common.glsl"

layout(local_size_x = 64) in;

layout(binding = FL_TEX_DELAUNAY_IDS) uniform usampler2D uIds;     // G3's texture
layout(binding = FL_TEX_DELAUNAY_CORNERS) uniform usampler2D uCorners; // G4's cases
layout(binding = FL_TEX_DELAUNAY_CHAIN) uniform isampler2D uChain;   // G5's chain
layout(std430, binding = FL_SSBO_DELAUNAY_PIXELS) readonly buffer Pixels { ivec2 pixels[]; };
// The result header: TriangleStats (three-colour, four-colour, degenerate, clockwise).
layout(std430, binding = FL_SSBO_DELAUNAY_HEADER) buffer Header { uint header[]; };
// Per corner row: vertices, triangles (mode 0 writes); first vertex, first triangle (the scan's).
layout(std430, binding = FL_SSBO_DELAUNAY_ROWS) buffer Rows { uvec4 rows[]; };
// Per vertex: x | y << 16, case, colours of pixels 1-4.
layout(std430, binding = FL_SSBO_DELAUNAY_VERTICES) writeonly buffer Vertices {
    uint vertexData[];
};
// Per triangle: three site ids (counterclockwise).
layout(std430, binding = FL_SSBO_DELAUNAY_TRIANGLES) writeonly buffer Triangles {
    uint triangleData[];
};
// Per triangle: the index of its vertex.
layout(std430, binding = FL_SSBO_DELAUNAY_TRIANGLE_VERTEX) writeonly buffer TriangleVertex {
    uint triangleVertex[];
};
uniform ivec2 uSize;
uniform int uMode; // 0: count, 1: write
uniform int uVertexCapacity;
uniform int uTriangleCapacity;

// Twice the signed area of pixel triangle (a, b, c); coordinates below 2^13 keep it in 32 bits.
int orient(ivec2 a, ivec2 b, ivec2 c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// A 64-bit integer as two 32-bit halves (GL 4.5 has no 64-bit integers without an extension).
struct Int64 {
    int hi;
    uint lo;
};

Int64 mul64(int a, int b) {
    int hi, lo;
    imulExtended(a, b, hi, lo);
    return Int64(hi, uint(lo));
}

Int64 add64(Int64 a, Int64 b) {
    uint carry;
    uint lo = uaddCarry(a.lo, b.lo, carry);
    return Int64(a.hi + b.hi + int(carry), lo);
}

// Sign of pixelInCircle (> 0: d strictly inside the circle through counterclockwise a, b, c),
// exact: lifts and 2x2 minors stay below 2^27, products below 2^54, the sum below 2^56.
int inCircleSign(ivec2 a, ivec2 b, ivec2 c, ivec2 d) {
    ivec2 ad = a - d, bd = b - d, cd = c - d;
    int alift = ad.x * ad.x + ad.y * ad.y;
    int blift = bd.x * bd.x + bd.y * bd.y;
    int clift = cd.x * cd.x + cd.y * cd.y;
    Int64 s = mul64(alift, bd.x * cd.y - cd.x * bd.y);
    s = add64(s, mul64(blift, cd.x * ad.y - ad.x * cd.y));
    s = add64(s, mul64(clift, ad.x * bd.y - bd.x * ad.y));
    return s.hi < 0 ? -1 : (s.hi > 0 || s.lo != 0u ? 1 : 0);
}

uint gThree = 0u, gFour = 0u, gDegenerate = 0u, gClockwise = 0u;

void emit(uint slot, uint a, uint b, uint c, uint vertex) {
    int o = orient(pixels[a], pixels[b], pixels[c]);
    gDegenerate += uint(o == 0);
    gClockwise += uint(o < 0);
    if (slot < uint(uTriangleCapacity)) {
        triangleData[3u * slot] = a;
        triangleData[3u * slot + 1u] = b;
        triangleData[3u * slot + 2u] = c;
        triangleVertex[slot] = vertex;
    }
}

// Emits the vertex's triangles from `slot` on; returns how many (as the CPU's MeshBuilder).
uint vertexTriangles(uint kind, uvec4 col, uint slot, uint vertex) {
    if (kind != kCaseFour) {
        ++gThree;
        // The three colours counterclockwise around the corner, the repeated one skipped.
        uvec3 t = kind == kCaseThreeA ? col.xzw : (kind == kCaseThreeB ? col.xyw : col.xyz);
        emit(slot, t.x, t.y, t.z, vertex);
        return 1u;
    }
    ++gFour;
    // Case 3: the diagonal whose triangles are both counterclockwise; if both are, the one
    // passing the empty-circle test (a-c on ties).
    ivec2 pa = pixels[col.x], pb = pixels[col.y], pc = pixels[col.z], pd = pixels[col.w];
    bool acValid = orient(pa, pb, pc) > 0 && orient(pa, pc, pd) > 0;
    bool bdValid = orient(pa, pb, pd) > 0 && orient(pb, pc, pd) > 0;
    bool useBd = bdValid && !acValid;
    if (acValid && bdValid) useBd = inCircleSign(pa, pb, pc, pd) > 0;
    if (useBd) {
        emit(slot, col.x, col.y, col.w, vertex);
        emit(slot + 1u, col.y, col.z, col.w, vertex);
    } else {
        emit(slot, col.x, col.y, col.z, vertex);
        emit(slot + 1u, col.x, col.z, col.w, vertex);
    }
    return 2u;
}

int nextVertex(int x, int y) {
    return x + 1 < uSize.x ? texelFetch(uChain, ivec2(x + 1, y), 0).r : kNoVertex;
}

void main() {
    int y = int(dispatchIndex(64u));
    // Corner rows 0..h-2; the top row's corners lie on the border.
    if (y >= uSize.y - 1) return;
    int first = texelFetch(uChain, ivec2(0, y), 0).r;
    if (uMode == 0) {
        uint vertices = 0u, tris = 0u;
        for (int x = first; x != kNoVertex; x = nextVertex(x, y)) {
            ++vertices;
            tris += texelFetch(uCorners, ivec2(x, y), 0).r == kCaseFour ? 2u : 1u;
        }
        rows[y] = uvec4(vertices, tris, 0u, 0u);
        return;
    }
    uint v0 = rows[y].z;
    uint v = 0u, t = rows[y].w;
    for (int x = first; x != kNoVertex; x = nextVertex(x, y), ++v) {
        ivec2 p = ivec2(x, y);
        uint kind = texelFetch(uCorners, p, 0).r;
        uvec4 col = uvec4(texelFetch(uIds, p, 0).r, texelFetch(uIds, p + ivec2(1, 0), 0).r,
                          texelFetch(uIds, p + ivec2(1, 1), 0).r,
                          texelFetch(uIds, p + ivec2(0, 1), 0).r);
        uint slot = v0 + v;
        if (slot < uint(uVertexCapacity)) {
            vertexData[6u * slot] = uint(x) | uint(y) << 16;
            vertexData[6u * slot + 1u] = kind;
            vertexData[6u * slot + 2u] = col.x;
            vertexData[6u * slot + 3u] = col.y;
            vertexData[6u * slot + 4u] = col.z;
            vertexData[6u * slot + 5u] = col.w;
        }
        t += vertexTriangles(kind, col, t, slot);
    }
    atomicAdd(header[kHeadStats], gThree);
    atomicAdd(header[kHeadStats + 1u], gFour);
    atomicAdd(header[kHeadStats + 2u], gDegenerate);
    atomicAdd(header[kHeadStats + 3u], gClockwise);
}
