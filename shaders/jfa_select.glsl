// The heart of one jump-flooding pass, shared by the fragment and compute kernels: texel `t`
// reads the 9 cells t + (i, j) * step, i, j in {-1, 0, 1}, that lie inside the grid, and keeps
// the best non-empty one under the criterion (linked in from its own shader object).

bool jfaEmpty(vec4 c);
bool jfaBetter(ivec2 p, vec4 a, vec4 b);
// Whether non-empty `c` may be taken at grid point p (false: treated as empty there).
bool jfaAccept(ivec2 p, vec4 c);
// Full-resolution pixel a cell was seeded at; any negative coordinate = unknown (copy verbatim).
ivec2 jfaSeedPixel(vec4 c);
// How the criterion's cells are stored: jfaLoad reads the cell at q of a grid texture (seeds or
// a pass's output), jfaStore gives the texel to write for cell c. The identity for RGBA32F
// cells; a criterion with packed cells (a seed's texel in 32 bits, JFA_CELL_FORMAT r32f)
// rebuilds the cell from what the seed's texel holds elsewhere.
vec4 jfaLoad(sampler2D grid, ivec2 q);
vec4 jfaStore(vec4 c);

const vec4 kJfaEmptyCell = vec4(0.0, 0.0, -1.0, 0.0);

#ifdef JFA_KEYED
// Keyed criteria (the kernel defines JFA_KEYED for them) rank by a key computed once per
// candidate instead of twice per comparison: jfaKey(p, ctx, c) < 0 where jfaAccept(p, c) is
// false, else the ranking key, smaller better, equal keys to jfaTieWins. It must hold that
// jfaBetter(p, a, b) == (key(a) < key(b) || (key(a) == key(b) && jfaTieWins(a, b))), so the
// pass selects exactly what the accept/better form (and the CPU kernel) selects. `ctx` is what
// the criterion reads at p itself (jfaContext), fetched once per texel rather than per call.
vec4 jfaContext(ivec2 p);
float jfaKey(ivec2 p, vec4 ctx, vec4 c);
bool jfaTieWins(vec4 a, vec4 b);
#endif

// `scale`: 1 at full resolution, 2 in the half-resolution stage (texel t stands for grid
// point t * 2, whose distances are measured in full-resolution coordinates).
// Expansion (thesis §4.3.2): full-resolution texel q takes the half-resolution cell r = q / 2,
// refined among the full-resolution seeds of the 2x2 block holding r's seed pixel (the sites r
// stands for), judged at q. Same as expandStage() in jfa/CpuKernel.h.
vec4 jfaExpandedCell(sampler2D coarse, sampler2D seeds, ivec2 q, ivec2 fullSize) {
    vec4 best = jfaLoad(coarse, q / 2);
    if (jfaEmpty(best)) return best;
    ivec2 sp = jfaSeedPixel(best);
    if (any(lessThan(sp, ivec2(0)))) return best;
    ivec2 b = (sp / 2) * 2;
    for (int j = 0; j <= 1; ++j) {
        for (int i = 0; i <= 1; ++i) {
            ivec2 c = b + ivec2(i, j);
            ivec2 cc = min(c, fullSize - 1);
            vec4 s = jfaLoad(seeds, cc);
            bool take = c == cc && !jfaEmpty(s) && jfaAccept(q, s) && jfaBetter(q, s, best);
            best = take ? s : best;
        }
    }
    return best;
}

// Compiled twice: normally a candidate is the cell src[q]; with JFA_EXPAND defined (the pass
// right after the half-resolution stage) it is jfaExpandedCell(src, seeds, q), the expansion
// fused into the pass. Two programs rather than a run-time switch: a SIMD rasteriser
// (llvmpipe) would otherwise pay for the expansion's reads in every pass.
vec4 jfaCandidate(sampler2D src, sampler2D seeds, ivec2 q, ivec2 size) {
#ifdef JFA_EXPAND
    return jfaExpandedCell(src, seeds, q, size);
#else
    return jfaLoad(src, q);
#endif
}

vec4 jfaSelect(sampler2D src, sampler2D seeds, ivec2 t, ivec2 size, int step, int scale) {
    ivec2 p = t * scale;
    vec4 best = kJfaEmptyCell;
    bool have = false;
    // Clamped reads plus an "inside" flag instead of skipping: branch-light code runs much
    // faster on SIMD rasterisers (llvmpipe), and an outside candidate still never wins.
    ivec2 hi = size - 1;
#ifdef JFA_KEYED
    vec4 ctx = jfaContext(p);
    float bestKey = 0.0;
    for (int j = -1; j <= 1; ++j) {
        for (int i = -1; i <= 1; ++i) {
            ivec2 q = t + ivec2(i, j) * step;
            ivec2 qc = clamp(q, ivec2(0), hi);
            vec4 c = jfaCandidate(src, seeds, qc, size);
            float k = q == qc && !jfaEmpty(c) ? jfaKey(p, ctx, c) : -1.0;
            bool take = k >= 0.0 && (!have || k < bestKey || (k == bestKey && jfaTieWins(c, best)));
            best = take ? c : best;
            bestKey = take ? k : bestKey;
            have = have || take;
        }
    }
    return best;
#endif
    for (int j = -1; j <= 1; ++j) {
        for (int i = -1; i <= 1; ++i) {
            ivec2 q = t + ivec2(i, j) * step;
            ivec2 qc = clamp(q, ivec2(0), hi);
            vec4 c = jfaCandidate(src, seeds, qc, size);
            bool take = q == qc && !jfaEmpty(c) && jfaAccept(p, c) && (!have || jfaBetter(p, c, best));
            best = take ? c : best;
            have = have || take;
        }
    }
    return best;
}

// Half-resolution seeding: half-res texel t takes the best of full-res cells 2t .. 2t + 1.
vec4 jfaDownsample(sampler2D full, ivec2 t, ivec2 fullSize) {
    ivec2 p = t * 2;
    vec4 best = kJfaEmptyCell;
    bool have = false;
    for (int j = 0; j <= 1; ++j) {
        for (int i = 0; i <= 1; ++i) {
            ivec2 q = p + ivec2(i, j);
            ivec2 qc = min(q, fullSize - 1);
            vec4 c = jfaLoad(full, qc);
            bool take = q == qc && !jfaEmpty(c) && jfaAccept(p, c) && (!have || jfaBetter(p, c, best));
            best = take ? c : best;
            have = have || take;
        }
    }
    return best;
}

// One texel of a kernel dispatch. mode 0: pass (expand then pass when compiled with
// JFA_EXPAND; src is then the half-resolution grid); 2: downsample full-resolution seeds.
// `before` receives the cell the texel held before (for "until unchanged" counting).
vec4 jfaTexel(sampler2D src, sampler2D seeds, ivec2 t, ivec2 size, ivec2 srcSize, int step,
              int scale, int mode, out vec4 before) {
    if (mode == 2) {
        before = jfaDownsample(src, t, srcSize);
        return before;
    }
    before = jfaCandidate(src, seeds, t, size);
    return jfaSelect(src, seeds, t, size, step, scale);
}
