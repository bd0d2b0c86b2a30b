#pragma once
// Flood plans: the step-length sequences of jump flooding (thesis ch. 3, §4.3.2) as plain data.
//
// A Plan is an ordered list of stages. Each stage is a grid size and the step lengths run on it.
// Between two stages the grid is expanded: every texel of the smaller grid becomes the 2x2 block
// it covers in the next one (the next stage is W x H, the previous one ceil(W/2) x ceil(H/2)).
// That models the "halve resolution" variant: the low-resolution stage floods with distances
// measured in full-resolution coordinates, then expands, then a step-1 pass smooths the edges.
// A kernel (CPU or GL) executes the passes of a plan with a criterion; the plan knows no GL.
//
// First-step rule: for an extent n = max(W, H) (of the stage's grid), JFA uses the steps 2^k with
// 2^k < n, halving down to 1: the first step is the largest power of two <= n - 1 (n = 512 -> 256,
// the thesis' n/2; n = 513 -> 512; n = 5 -> 4; n = 3 -> 2; n = 2 -> 1; n = 1 -> no passes).
// Texel coordinates span 0..n-1, so a seed must travel up to n-1 texels per axis; steps
// 2^(m-1), ..., 2, 1 sum to 2^m - 1 and (Property 3.1, binary decomposition) reach every offset in
// [0, 2^m - 1], so the smallest m with 2^m - 1 >= n - 1 fills the grid. A step >= n would only
// read outside the grid and is never needed.

#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

namespace fl::jfa {

// Largest grid extent a plan accepts (per axis); keeps all step arithmetic inside int.
inline constexpr int kMaxGridExtent = 1 << 20;
// Largest pass count of a fixed standard flood (flood:N) and of a "+K"/"(a,b)" step list. A
// step-1 flood crosses the largest grid the commands take (16384 per side) in fewer passes; more
// only cost time (flood:1048576 ran for minutes on a 64 x 64 grid).
inline constexpr int kMaxFloodPasses = 16384;

// One stage: the passes run on a grid of width x height.
struct Stage {
    int width = 0;
    int height = 0;
    std::vector<int> steps;      // step lengths in execution order, in this stage's texels
    bool untilUnchanged = false; // steps are all 1 and the kernel may stop once a pass changes
                                 // no texel; steps.size() is then the safety cap (width + height)

    bool operator==(const Stage&) const = default;
};

// One pass as a kernel consumes it.
struct Pass {
    int step = 1;  // step length in texels of this pass' grid
    int width = 0; // grid the pass runs on (width x height)
    int height = 0;
    bool expandBefore = false;   // expand the previous stage's grid 2x into width x height first
    bool untilUnchanged = false; // part of an until-unchanged run: if this pass changes no texel,
                                 // skip the remaining passes of its stage

    bool operator==(const Pass&) const = default;
};

// The body of a thesis variant; see Recipe.
enum class Body {
    Jfa,                 // halving steps: first step (rule above), ..., 2, 1
    JfaSquared,          // JFA twice (JFA + log n more passes)
    Doubling,            // 1, 2, 4, ..., up to the JFA first step (Fig. 3.2a)
    Flood,               // standard flooding: Recipe::floodPasses step-1 passes
    FloodUntilUnchanged, // standard flooding repeated until no texel changes (cap W + H passes)
};

// A composition of thesis variants: `before`, then the body, then `after`, all at full resolution,
// or with halfResolution at ceil(W/2) x ceil(H/2) followed by an expansion and one step-1 pass.
// E.g. 1+JFA+1 = {{1}, Jfa, 0, {1}}, half resolution + JFA+2 = {{}, Jfa, 0, {2, 1}, true}.
struct Recipe {
    std::vector<int> before; // steps run before the body (1+JFA: {1})
    Body body = Body::Jfa;
    int floodPasses = 0;    // pass count for Body::Flood
    std::vector<int> after; // steps run after the body (JFA+1: {1}, JFA+2: {2, 1})
    bool halfResolution = false;

    bool operator==(const Recipe&) const = default;
};

class Plan {
  public:
    // Builds a custom plan from explicit stages; throws std::invalid_argument if they are invalid.
    Plan(std::string name, std::vector<Stage> stages, std::string spec = {});

    // JFA: halving steps from the first-step rule down to 1 (log n passes).
    static Plan jfa(int width, int height);
    // JFA+k: JFA followed by k passes of steps 2^(k-1), ..., 2, 1 (JFA+1: ..1 1; JFA+2: ..1 2 1).
    static Plan jfaPlus(int k, int width, int height);
    // JFA^2: JFA run twice (2 log n passes).
    static Plan jfaSquared(int width, int height);
    // 1+JFA: one step-1 pass, then JFA.
    static Plan onePlusJfa(int width, int height);
    // Doubling: 1, 2, 4, ..., the JFA first step.
    static Plan doubling(int width, int height);
    // Standard flooding with a fixed number of step-1 passes.
    static Plan flood(int passes, int width, int height);
    // Standard flooding until no texel changes, at most width + height passes.
    static Plan floodUntilUnchanged(int width, int height);
    // Halve resolution: JFA on ceil(W/2) x ceil(H/2), expand to W x H, one step-1 pass.
    static Plan halfResolution(int width, int height);
    // Any composition of the above; throws std::invalid_argument on invalid input.
    static Plan compose(const Recipe& recipe, int width, int height);

    // Display name, e.g. "JFA+2", "1+JFA+1", "half-res JFA", "flood:63".
    const std::string& name() const { return name_; }
    // Canonical spec that parsePlan() maps back to this plan (empty for custom plans).
    const std::string& spec() const { return spec_; }
    // Full-resolution grid width (the last stage's).
    int width() const { return stages_.back().width; }
    // Full-resolution grid height (the last stage's).
    int height() const { return stages_.back().height; }
    // The stages in execution order; the first one's size is where the kernel seeds the grid.
    const std::vector<Stage>& stages() const { return stages_; }
    // Every pass in execution order with its stage's grid size.
    std::vector<Pass> passes() const;
    // All step lengths in execution order (stage boundaries dropped).
    std::vector<int> steps() const;
    // Number of passes; for an until-unchanged stage its cap, so an upper bound.
    int passCount() const;
    // True if some stage repeats until no texel changes (passCount() is then an upper bound).
    bool untilUnchanged() const;
    // Largest per-axis distance in full-resolution texels that information can travel: the sum of
    // all step lengths, a step at a stage 2^j times smaller counting 2^j times, plus 1 per
    // expansion (the 2x2 block copy). A plan can fill a W x H grid from any single seed only if
    // maxReach() >= max(W, H) - 1; for halving sequences such as JFA that is also sufficient.
    long long maxReach() const;
    // One-line description, e.g. "JFA+2 on 300x200: 256 128 64 32 16 8 4 2 1 2 1 (11 passes)".
    std::string describe() const;

    bool operator==(const Plan&) const = default;

  private:
    std::string name_;
    std::vector<Stage> stages_;
    std::string spec_;
};

// Prints plan.describe().
std::ostream& operator<<(std::ostream& os, const Plan& plan);

// The most halving passes a grid extent n allows: the largest k with 2^k <= n (floor(log2 n)),
// 0 for n < 2. The one home of that rule: the penumbra map's and the eye's pass limits, the
// window's -/= keys and --full-jfa all read it.
int jfaMaxPasses(int n);
// The JFA first step for a grid extent n >= 1: largest power of two <= n - 1, or 0 for n = 1.
int jfaFirstStep(int n);
// JFA's halving steps for a grid extent n >= 1: jfaFirstStep(n), ..., 2, 1 (empty for n = 1).
std::vector<int> jfaSteps(int n);
// The k extra passes of JFA+k: 2^(k-1), ..., 2, 1.
std::vector<int> extraPasses(int k);

// Parses a plan name, case-insensitively: jfa, jfa+1, jfa+2, jfa+K, jfa2 / jfa^2, 1+jfa, 1+jfa+1,
// doubling, flood, flood:N, half:<plan>, explicit step lists "(a,b,...)+<body>+(c,...)"; throws
// std::invalid_argument listing the valid forms.
Plan parsePlan(std::string_view spec, int width, int height);

} // namespace fl::jfa
