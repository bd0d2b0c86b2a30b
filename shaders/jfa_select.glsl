// The heart of one jump-flooding pass, shared by the fragment and compute kernels: texel `t`
// reads the 9 cells t + (i, j) * step, i, j in {-1, 0, 1}, that lie inside the grid, and keeps
// the best non-empty one under the criterion (linked in from its own shader object).

bool jfaEmpty(vec4 c);
bool jfaBetter(ivec2 p, vec4 a, vec4 b);

const vec4 kJfaEmptyCell = vec4(0.0, 0.0, -1.0, 0.0);

// `scale`: 1 at full resolution, 2 in the half-resolution stage (texel t stands for grid
// point t * 2, whose distances are measured in full-resolution coordinates).
// `srcDiv`: 1 normally; 2 for the pass right after expanding the half-resolution stage, whose
// full-resolution cell q is the half-resolution cell q / 2 (the expansion is fused into it).
vec4 jfaSelect(sampler2D src, ivec2 t, ivec2 size, int step, int scale, int srcDiv) {
    ivec2 p = t * scale;
    vec4 best = kJfaEmptyCell;
    bool have = false;
    // Clamped reads plus an "inside" flag instead of skipping: branch-light code runs much
    // faster on SIMD rasterisers (llvmpipe), and an outside candidate still never wins.
    ivec2 hi = size - 1;
    for (int j = -1; j <= 1; ++j) {
        for (int i = -1; i <= 1; ++i) {
            ivec2 q = t + ivec2(i, j) * step;
            ivec2 qc = clamp(q, ivec2(0), hi);
            vec4 c = texelFetch(src, qc / srcDiv, 0);
            bool take = q == qc && !jfaEmpty(c) && (!have || jfaBetter(p, c, best));
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
            vec4 c = texelFetch(full, qc, 0);
            bool take = q == qc && !jfaEmpty(c) && (!have || jfaBetter(p, c, best));
            best = take ? c : best;
            have = have || take;
        }
    }
    return best;
}

// One texel of a kernel dispatch. mode 0: pass; 1: expand then pass (src is the
// half-resolution grid); 2: downsample full-resolution seeds. `before` receives the cell the
// texel held before (for "until unchanged" counting).
vec4 jfaTexel(sampler2D src, ivec2 t, ivec2 size, ivec2 srcSize, int step, int scale, int mode,
              out vec4 before) {
    if (mode == 2) {
        before = jfaDownsample(src, t, srcSize);
        return before;
    }
    int srcDiv = mode == 1 ? 2 : 1;
    before = texelFetch(src, t / srcDiv, 0);
    return jfaSelect(src, t, size, step, scale, srcDiv);
}
