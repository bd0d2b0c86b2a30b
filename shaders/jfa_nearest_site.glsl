#version 450 core
// Voronoi criterion (jfa/NearestSite.h on the CPU, which this must match bit for bit): the
// nearest site wins; ties go to the smaller id, then the smaller y, then the smaller x.
// Cell: xy = site position in full-resolution grid coordinates, z = id (-1 empty).

uniform int uJfaIntegerSites; // 1: exact integer squared distances (grids up to 16384 wide)

bool jfaEmpty(vec4 c) { return c.z < 0.0; }

// Every site is a candidate everywhere.
bool jfaAccept(ivec2 p, vec4 c) { return true; }

// So only the plan bounds how far a site spreads (band-limited flooding, jfa/Band.h).
ivec4 jfaSeedRect(ivec2 p, vec4 c) { return ivec4(-0x3fffffff, -0x3fffffff, 0x3fffffff, 0x3fffffff); }

// The full-resolution pixel the site was seeded at, floor(v + 0.5) per coordinate, computed
// exactly (NearestSite::seedPixel on the CPU).
ivec2 jfaSeedPixel(vec4 c) {
    precise vec2 f = floor(c.xy);
    precise vec2 frac = c.xy - f;
    return ivec2(f) + ivec2(greaterThanEqual(frac, vec2(0.5)));
}

bool jfaBetter(ivec2 p, vec4 a, vec4 b) {
    bool closer, same;
    if (uJfaIntegerSites != 0) {
        ivec2 da = ivec2(a.xy) - p;
        ivec2 db = ivec2(b.xy) - p;
        int la = da.x * da.x + da.y * da.y;
        int lb = db.x * db.x + db.y * db.y;
        closer = la < lb;
        same = la == lb;
    } else {
        // `precise`: no fused multiply-add, as on the CPU (built with -ffp-contract=off).
        precise vec2 da = a.xy - vec2(p);
        precise vec2 db = b.xy - vec2(p);
        precise float la = da.x * da.x + da.y * da.y;
        precise float lb = db.x * db.x + db.y * db.y;
        closer = la < lb;
        same = la == lb;
    }
    // Written without early returns: branch-light code runs faster on SIMD rasterisers.
    bool tieWins = a.z < b.z || (a.z == b.z && (a.y < b.y || (a.y == b.y && a.x < b.x)));
    return closer || (same && tieWins);
}

// Cells are stored as they are (RGBA32F).
vec4 jfaLoad(sampler2D grid, ivec2 q) { return texelFetch(grid, q, 0); }
vec4 jfaStore(vec4 c) { return c; }
