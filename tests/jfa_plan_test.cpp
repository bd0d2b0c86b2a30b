// Flood plans (thesis ch. 3, §4.3.2): exact step lists of every variant, stage sizes, parsing and
// the printed form. Pure data, no GL.
#include <jfa/Plan.h>

#include <gtest/gtest.h>

#include <initializer_list>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace fl::jfa {
namespace {

using Steps = std::vector<int>;

const Steps kJfa512{256, 128, 64, 32, 16, 8, 4, 2, 1};

Steps concat(std::initializer_list<Steps> parts) {
    Steps all;
    for (const Steps& part : parts) all.insert(all.end(), part.begin(), part.end());
    return all;
}

// The message of the std::invalid_argument `f` throws ("" if it throws none).
template <typename F>
std::string invalidArgumentMessage(F f) {
    try {
        f();
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return {};
}

// ---- first-step rule ----------------------------------------------------------------------------

// floor(log2 n): the one rule the penumbra map's and the eye's pass limits and the window read;
// the loops it replaced (ViewerActions, PenumbraMap, EyeSoftShadow) gave these values.
TEST(JfaStepRule, MaxPassesIsFloorLog2) {
    // n, floor(log2 n) (0 below 2), up to the top of int without overflow.
    const std::pair<int, int> cases[] = {{0, 0},        {1, 0},          {2, 1},     {3, 1},
                                         {512, 9},      {1023, 9},       {1024, 10}, {8192, 13},
                                         {1 << 30, 30}, {2147483647, 30}};
    for (const auto& [n, passes] : cases) EXPECT_EQ(jfaMaxPasses(n), passes) << n;
}

TEST(JfaStepRule, FirstStepIsLargestPowerOfTwoBelowExtent) {
    EXPECT_EQ(jfaFirstStep(1), 0); // nothing to propagate on a single texel
    EXPECT_EQ(jfaFirstStep(2), 1);
    EXPECT_EQ(jfaFirstStep(3), 2);
    EXPECT_EQ(jfaFirstStep(4), 2);
    EXPECT_EQ(jfaFirstStep(5), 4);
    EXPECT_EQ(jfaFirstStep(300), 256);
    EXPECT_EQ(jfaFirstStep(512), 256); // the thesis' n/2 for n a power of two
    EXPECT_EQ(jfaFirstStep(513), 512);
    EXPECT_EQ(jfaFirstStep(kMaxGridExtent), kMaxGridExtent / 2);
    EXPECT_THROW(jfaFirstStep(0), std::invalid_argument);
}

TEST(JfaStepRule, StepsReachEveryOffsetAndNoStepIsWasted) {
    // Steps 2^(m-1)..1 reach offsets 0..2^m-1 (Property 3.1): enough for n-1, and dropping the
    // first step would not be.
    for (int n = 1; n <= 2049; ++n) {
        const Steps steps = jfaSteps(n);
        const int sum = std::accumulate(steps.begin(), steps.end(), 0);
        EXPECT_GE(sum, n - 1) << "n = " << n;
        if (!steps.empty()) {
            EXPECT_LT(sum - steps.front(), n - 1) << "n = " << n;
            EXPECT_LT(steps.front(), n) << "n = " << n;
            EXPECT_EQ(steps.back(), 1);
        }
    }
    EXPECT_EQ(jfaSteps(1), Steps{});
    EXPECT_EQ(jfaSteps(2), Steps{1});
    EXPECT_EQ(jfaSteps(3), (Steps{2, 1}));
    EXPECT_EQ(jfaSteps(5), (Steps{4, 2, 1}));
    EXPECT_EQ(jfaSteps(512), kJfa512);
    EXPECT_EQ(jfaSteps(513), concat({{512}, kJfa512}));
}

TEST(JfaStepRule, ExtraPasses) {
    EXPECT_EQ(extraPasses(1), Steps{1});
    EXPECT_EQ(extraPasses(2), (Steps{2, 1}));
    EXPECT_EQ(extraPasses(4), (Steps{8, 4, 2, 1}));
    EXPECT_THROW(extraPasses(0), std::invalid_argument);
    EXPECT_THROW(extraPasses(31), std::invalid_argument);
}

// ---- factories on 512x512 -----------------------------------------------------------------------

TEST(PlanFactories, ExactStepLists512) {
    EXPECT_EQ(Plan::jfa(512, 512).steps(), kJfa512);
    EXPECT_EQ(Plan::jfaPlus(1, 512, 512).steps(), concat({kJfa512, {1}}));
    EXPECT_EQ(Plan::jfaPlus(2, 512, 512).steps(), concat({kJfa512, {2, 1}}));
    EXPECT_EQ(Plan::jfaSquared(512, 512).steps(), concat({kJfa512, kJfa512}));
    EXPECT_EQ(Plan::onePlusJfa(512, 512).steps(), concat({{1}, kJfa512}));
    EXPECT_EQ(Plan::doubling(512, 512).steps(), (Steps{1, 2, 4, 8, 16, 32, 64, 128, 256}));
    EXPECT_EQ(Plan::flood(63, 512, 512).steps(), Steps(63, 1));
}

TEST(PlanFactories, PassCountsAndNames512) {
    EXPECT_EQ(Plan::jfa(512, 512).passCount(), 9);
    EXPECT_EQ(Plan::jfaPlus(1, 512, 512).passCount(), 10);
    EXPECT_EQ(Plan::jfaPlus(2, 512, 512).passCount(), 11);
    EXPECT_EQ(Plan::jfaSquared(512, 512).passCount(), 18);
    EXPECT_EQ(Plan::onePlusJfa(512, 512).passCount(), 10);
    EXPECT_EQ(Plan::doubling(512, 512).passCount(), 9);
    EXPECT_EQ(Plan::flood(63, 512, 512).passCount(), 63);
    EXPECT_EQ(Plan::halfResolution(512, 512).passCount(), 9);

    EXPECT_EQ(Plan::jfa(512, 512).name(), "JFA");
    EXPECT_EQ(Plan::jfaPlus(1, 512, 512).name(), "JFA+1");
    EXPECT_EQ(Plan::jfaPlus(2, 512, 512).name(), "JFA+2");
    EXPECT_EQ(Plan::jfaSquared(512, 512).name(), "JFA^2");
    EXPECT_EQ(Plan::onePlusJfa(512, 512).name(), "1+JFA");
    EXPECT_EQ(Plan::doubling(512, 512).name(), "doubling");
    EXPECT_EQ(Plan::flood(63, 512, 512).name(), "flood:63");
    EXPECT_EQ(Plan::floodUntilUnchanged(512, 512).name(), "flood");
    EXPECT_EQ(Plan::halfResolution(512, 512).name(), "half-res JFA");
}

TEST(PlanFactories, SingleStageAtFullResolution) {
    const Plan plan = Plan::jfaPlus(2, 512, 512);
    ASSERT_EQ(plan.stages().size(), 1u);
    EXPECT_EQ(plan.stages()[0].width, 512);
    EXPECT_EQ(plan.stages()[0].height, 512);
    EXPECT_FALSE(plan.stages()[0].untilUnchanged);
    EXPECT_EQ(plan.width(), 512);
    EXPECT_EQ(plan.height(), 512);
    EXPECT_FALSE(plan.untilUnchanged());
}

TEST(PlanFactories, FloodUntilUnchanged) {
    const Plan plan = Plan::floodUntilUnchanged(300, 200);
    EXPECT_TRUE(plan.untilUnchanged());
    ASSERT_EQ(plan.stages().size(), 1u);
    EXPECT_TRUE(plan.stages()[0].untilUnchanged);
    EXPECT_EQ(plan.steps(), Steps(500, 1)); // the safety cap: W + H passes
    EXPECT_EQ(plan.passCount(), 500);
    for (const Pass& pass : plan.passes()) {
        EXPECT_EQ(pass, (Pass{1, 300, 200, false, true}));
    }
    EXPECT_EQ(plan.describe(), "flood on 300x200: 1 until unchanged (at most 500 passes)");
}

// ---- non-power-of-two grids ---------------------------------------------------------------------

TEST(PlanGrids, NonPowerOfTwoUsesTheLargerSide) {
    EXPECT_EQ(Plan::jfa(300, 200).steps(), (Steps{256, 128, 64, 32, 16, 8, 4, 2, 1}));
    EXPECT_EQ(Plan::jfa(200, 300).steps(), Plan::jfa(300, 200).steps());
    EXPECT_EQ(Plan::jfa(513, 7).steps(), concat({{512}, kJfa512}));
    EXPECT_EQ(Plan::jfa(7, 513).passCount(), 10);
    EXPECT_EQ(Plan::doubling(513, 7).steps(), (Steps{1, 2, 4, 8, 16, 32, 64, 128, 256, 512}));
    EXPECT_EQ(Plan::jfaPlus(2, 300, 200).passCount(), 11);
}

TEST(PlanGrids, TinyGrids) {
    // 1x1: nothing to propagate, JFA has no passes.
    EXPECT_EQ(Plan::jfa(1, 1).steps(), Steps{});
    EXPECT_EQ(Plan::jfa(1, 1).passCount(), 0);
    EXPECT_EQ(Plan::jfaPlus(1, 1, 1).steps(), Steps{1});
    EXPECT_EQ(Plan::onePlusJfa(1, 1).steps(), Steps{1});
    EXPECT_EQ(Plan::doubling(1, 1).steps(), Steps{});
    EXPECT_EQ(Plan::jfaSquared(1, 1).steps(), Steps{});
    EXPECT_EQ(Plan::floodUntilUnchanged(1, 1).passCount(), 2);
    EXPECT_EQ(Plan::jfa(1, 1).describe(), "JFA on 1x1: none (0 passes)");
    // 2x1: one step-1 pass suffices.
    EXPECT_EQ(Plan::jfa(2, 1).steps(), Steps{1});
    EXPECT_EQ(Plan::jfa(1, 2).steps(), Steps{1});
    EXPECT_EQ(Plan::jfaSquared(2, 1).steps(), (Steps{1, 1}));
    EXPECT_EQ(Plan::jfa(2, 1).describe(), "JFA on 2x1: 1 (1 pass)");
}

TEST(PlanGrids, InvalidSizesThrow) {
    EXPECT_THROW(Plan::jfa(0, 5), std::invalid_argument);
    EXPECT_THROW(Plan::jfa(5, -1), std::invalid_argument);
    EXPECT_THROW(Plan::jfa(kMaxGridExtent + 1, 1), std::invalid_argument);
    EXPECT_THROW(Plan::flood(0, 8, 8), std::invalid_argument);
    EXPECT_THROW(Plan::jfaPlus(0, 8, 8), std::invalid_argument);
    EXPECT_NE(invalidArgumentMessage([] { Plan::jfa(0, 5); }).find("0x5"), std::string::npos);
}

// ---- half resolution ----------------------------------------------------------------------------

TEST(PlanHalfResolution, StagesAndSizes) {
    const Plan plan = Plan::halfResolution(512, 512);
    ASSERT_EQ(plan.stages().size(), 2u);
    EXPECT_EQ(plan.stages()[0], (Stage{256, 256, {128, 64, 32, 16, 8, 4, 2, 1}, false}));
    EXPECT_EQ(plan.stages()[1], (Stage{512, 512, {1}, false}));
    EXPECT_EQ(plan.width(), 512);
    EXPECT_EQ(plan.height(), 512);

    const std::vector<Pass> passes = plan.passes();
    ASSERT_EQ(passes.size(), 9u);
    EXPECT_EQ(passes.front(), (Pass{128, 256, 256, false, false}));
    EXPECT_EQ(passes[7], (Pass{1, 256, 256, false, false}));
    EXPECT_EQ(passes.back(), (Pass{1, 512, 512, true, false}));
}

TEST(PlanHalfResolution, OddSizesRoundUp) {
    const Plan plan = Plan::halfResolution(513, 7);
    ASSERT_EQ(plan.stages().size(), 2u);
    EXPECT_EQ(plan.stages()[0].width, 257);
    EXPECT_EQ(plan.stages()[0].height, 4);
    EXPECT_EQ(plan.stages()[0].steps, (Steps{256, 128, 64, 32, 16, 8, 4, 2, 1}));
    EXPECT_EQ(plan.stages()[1], (Stage{513, 7, {1}, false}));

    const Plan tiny = Plan::halfResolution(1, 1);
    EXPECT_EQ(tiny.stages()[0], (Stage{1, 1, {}, false}));
    EXPECT_EQ(tiny.passes(), (std::vector<Pass>{{1, 1, 1, true, false}}));

    const Plan small = Plan::halfResolution(3, 2);
    EXPECT_EQ(small.stages()[0], (Stage{2, 1, {1}, false}));
}

TEST(PlanHalfResolution, Describe) {
    EXPECT_EQ(Plan::halfResolution(512, 512).describe(),
              "half-res JFA on 512x512: [256x256] 128 64 32 16 8 4 2 1 | expand | [512x512] 1 "
              "(9 passes)");
    EXPECT_EQ(Plan::halfResolution(1, 1).describe(),
              "half-res JFA on 1x1: [1x1] none | expand | [1x1] 1 (1 pass)");
}

// ---- combinations -------------------------------------------------------------------------------

TEST(PlanCompose, OnePlusJfaPlusOne) {
    const Plan plan = Plan::compose({{1}, Body::Jfa, 0, {1}}, 512, 512);
    EXPECT_EQ(plan.steps(), concat({{1}, kJfa512, {1}}));
    EXPECT_EQ(plan.name(), "1+JFA+1");
    EXPECT_EQ(plan.spec(), "1+jfa+1");
}

TEST(PlanCompose, HalfResolutionJfaPlusTwo) {
    Recipe recipe;
    recipe.after = extraPasses(2);
    recipe.halfResolution = true;
    const Plan plan = Plan::compose(recipe, 512, 512);
    ASSERT_EQ(plan.stages().size(), 2u);
    EXPECT_EQ(plan.stages()[0].steps, (Steps{128, 64, 32, 16, 8, 4, 2, 1, 2, 1}));
    EXPECT_EQ(plan.stages()[1], (Stage{512, 512, {1}, false}));
    EXPECT_EQ(plan.name(), "half-res JFA+2");
    EXPECT_EQ(plan.spec(), "half:jfa+2");
    EXPECT_EQ(plan.passCount(), 11);
}

TEST(PlanCompose, FactoriesAreCompositions) {
    EXPECT_EQ(Plan::jfa(300, 200), Plan::compose({}, 300, 200));
    EXPECT_EQ(Plan::jfaPlus(2, 300, 200), Plan::compose({{}, Body::Jfa, 0, {2, 1}}, 300, 200));
    EXPECT_EQ(Plan::onePlusJfa(300, 200), Plan::compose({{1}, Body::Jfa, 0, {}}, 300, 200));
    EXPECT_EQ(Plan::halfResolution(300, 200),
              Plan::compose({{}, Body::Jfa, 0, {}, true}, 300, 200));
    // JFA^2 is JFA+log n.
    EXPECT_EQ(Plan::jfaSquared(512, 512).steps(), Plan::jfaPlus(9, 512, 512).steps());
}

TEST(PlanCompose, ExplicitStepListsAndHalfFlood) {
    const Plan plan = Plan::compose({{4, 2}, Body::Doubling, 0, {1, 1}}, 16, 16);
    EXPECT_EQ(plan.steps(), (Steps{4, 2, 1, 2, 4, 8, 1, 1}));
    EXPECT_EQ(plan.name(), "(4,2)+doubling+(1,1)");
    EXPECT_EQ(plan.spec(), "(4,2)+doubling+(1,1)");

    const Plan half = Plan::compose({{}, Body::FloodUntilUnchanged, 0, {}, true}, 64, 63);
    ASSERT_EQ(half.stages().size(), 2u);
    EXPECT_TRUE(half.stages()[0].untilUnchanged);
    EXPECT_EQ(half.stages()[0].steps, Steps(64, 1));
    EXPECT_FALSE(half.stages()[1].untilUnchanged);
    EXPECT_EQ(half.passCount(), 65);
    EXPECT_EQ(half.describe(), "half-res flood on 64x63: [32x32] 1 until unchanged | expand | "
                               "[64x63] 1 (at most 65 passes)");
}

TEST(PlanCompose, InvalidRecipesThrow) {
    EXPECT_THROW(Plan::compose({{0}, Body::Jfa, 0, {}}, 8, 8), std::invalid_argument);
    EXPECT_THROW(Plan::compose({{}, Body::Jfa, 0, {-2}}, 8, 8), std::invalid_argument);
    EXPECT_THROW(Plan::compose({{1}, Body::FloodUntilUnchanged, 0, {}}, 8, 8),
                 std::invalid_argument);
    EXPECT_THROW(Plan::compose({{}, Body::Flood, 0, {}}, 8, 8), std::invalid_argument);
}

// ---- passes and reach ---------------------------------------------------------------------------

TEST(PlanPasses, ExecutionOrderWithGridSizes) {
    const Plan plan = Plan::onePlusJfa(5, 3);
    const std::vector<Pass> expected{{1, 5, 3, false, false},
                                     {4, 5, 3, false, false},
                                     {2, 5, 3, false, false},
                                     {1, 5, 3, false, false}};
    EXPECT_EQ(plan.passes(), expected);
}

TEST(PlanPasses, MaxReach) {
    // Sum of steps; JFA reaches exactly 2^m - 1 >= n - 1.
    EXPECT_EQ(Plan::jfa(512, 512).maxReach(), 511);
    EXPECT_EQ(Plan::jfa(513, 7).maxReach(), 1023);
    EXPECT_EQ(Plan::jfa(1, 1).maxReach(), 0);
    EXPECT_EQ(Plan::jfaPlus(2, 512, 512).maxReach(), 514);
    EXPECT_EQ(Plan::flood(63, 512, 512).maxReach(), 63);
    EXPECT_EQ(Plan::doubling(512, 512).maxReach(), 511);
    // Half resolution: 2 * (128 + ... + 1) + 1 (the 2x2 expansion) + 1 (the final pass).
    EXPECT_EQ(Plan::halfResolution(512, 512).maxReach(), 2 * 255 + 1 + 1);
    for (int n : {1, 2, 3, 5, 300, 512, 513}) {
        EXPECT_GE(Plan::jfa(n, 1).maxReach(), n - 1) << n;
        EXPECT_GE(Plan::halfResolution(n, n).maxReach(), n - 1) << n;
    }
}

// ---- custom plans -------------------------------------------------------------------------------

TEST(PlanCustom, ValidatesStages) {
    const Plan plan("mine", {Stage{3, 2, {2, 1}}, Stage{5, 4, {1, 1}}});
    EXPECT_EQ(plan.passCount(), 4);
    EXPECT_EQ(plan.spec(), "");
    EXPECT_EQ(plan.describe(), "mine on 5x4: [3x2] 2 1 | expand | [5x4] 1 1 (4 passes)");

    EXPECT_THROW(Plan("none", {}), std::invalid_argument);
    EXPECT_THROW(Plan("size", {Stage{0, 2, {1}}}), std::invalid_argument);
    EXPECT_THROW(Plan("step", {Stage{4, 4, {2, 0}}}), std::invalid_argument);
    EXPECT_THROW(Plan("expand", {Stage{2, 2, {1}}, Stage{8, 8, {1}}}), std::invalid_argument);
    EXPECT_THROW(Plan("empty", {Stage{2, 2, {1}}, Stage{4, 4, {}}}), std::invalid_argument);
    EXPECT_THROW(Plan("until", {Stage{4, 4, {2, 1}, true}}), std::invalid_argument);
}

// ---- describe -----------------------------------------------------------------------------------

TEST(PlanDescribe, Strings) {
    EXPECT_EQ(Plan::jfaPlus(2, 300, 200).describe(),
              "JFA+2 on 300x200: 256 128 64 32 16 8 4 2 1 2 1 (11 passes)");
    EXPECT_EQ(Plan::jfa(512, 512).describe(),
              "JFA on 512x512: 256 128 64 32 16 8 4 2 1 (9 passes)");
    EXPECT_EQ(Plan::onePlusJfa(64, 64).describe(), "1+JFA on 64x64: 1 32 16 8 4 2 1 (7 passes)");
    EXPECT_EQ(Plan::jfaSquared(8, 8).describe(), "JFA^2 on 8x8: 4 2 1 4 2 1 (6 passes)");
    EXPECT_EQ(Plan::doubling(8, 8).describe(), "doubling on 8x8: 1 2 4 (3 passes)");
    // Runs of four or more equal steps are written step*count.
    EXPECT_EQ(Plan::flood(63, 512, 512).describe(), "flood:63 on 512x512: 1*63 (63 passes)");
    EXPECT_EQ(Plan::flood(3, 8, 8).describe(), "flood:3 on 8x8: 1 1 1 (3 passes)");

    std::ostringstream os;
    os << Plan::jfaPlus(1, 4, 4);
    EXPECT_EQ(os.str(), "JFA+1 on 4x4: 2 1 1 (3 passes)");
}

// ---- parsing ------------------------------------------------------------------------------------

TEST(PlanParse, Names) {
    EXPECT_EQ(parsePlan("jfa", 512, 512), Plan::jfa(512, 512));
    EXPECT_EQ(parsePlan("jfa+1", 512, 512), Plan::jfaPlus(1, 512, 512));
    EXPECT_EQ(parsePlan("jfa+2", 512, 512), Plan::jfaPlus(2, 512, 512));
    EXPECT_EQ(parsePlan("jfa2", 512, 512), Plan::jfaSquared(512, 512));
    EXPECT_EQ(parsePlan("jfa^2", 512, 512), Plan::jfaSquared(512, 512));
    EXPECT_EQ(parsePlan("1+jfa", 512, 512), Plan::onePlusJfa(512, 512));
    EXPECT_EQ(parsePlan("doubling", 512, 512), Plan::doubling(512, 512));
    EXPECT_EQ(parsePlan("flood", 512, 512), Plan::floodUntilUnchanged(512, 512));
    EXPECT_EQ(parsePlan("flood:63", 512, 512), Plan::flood(63, 512, 512));
    EXPECT_EQ(parsePlan("half:jfa", 512, 512), Plan::halfResolution(512, 512));
    EXPECT_EQ(parsePlan("1+jfa+1", 512, 512).steps(), concat({{1}, kJfa512, {1}}));
    EXPECT_EQ(parsePlan("half:jfa+2", 512, 512).stages()[0].steps,
              (Steps{128, 64, 32, 16, 8, 4, 2, 1, 2, 1}));
    EXPECT_EQ(parsePlan("jfa+3", 16, 16).steps(), (Steps{8, 4, 2, 1, 4, 2, 1}));
    EXPECT_EQ(parsePlan("(2,1)+jfa+(1,1)", 8, 8).steps(), (Steps{2, 1, 4, 2, 1, 1, 1}));
}

TEST(PlanParse, CaseAndSpaceInsensitive) {
    EXPECT_EQ(parsePlan("JFA+2", 300, 200), Plan::jfaPlus(2, 300, 200));
    EXPECT_EQ(parsePlan("Half:JFA", 300, 200), Plan::halfResolution(300, 200));
    EXPECT_EQ(parsePlan("  Doubling\n", 300, 200), Plan::doubling(300, 200));
    EXPECT_EQ(parsePlan("JFA^2", 300, 200), Plan::jfaSquared(300, 200));
}

TEST(PlanParse, RoundTrips) {
    const char* specs[] = {"jfa",
                           "jfa+1",
                           "jfa+2",
                           "jfa2",
                           "1+jfa",
                           "1+jfa+1",
                           "doubling",
                           "flood",
                           "flood:63",
                           "half:jfa",
                           "half:jfa+2",
                           "half:1+jfa+1",
                           "jfa+5",
                           "half:flood",
                           "half:flood:7",
                           "jfa2+1",
                           "(4,2)+doubling+(1,1)",
                           "1+jfa+(3)"};
    for (const char* spec : specs) {
        for (auto [w, h] : std::initializer_list<std::pair<int, int>>{
                 {512, 512}, {300, 200}, {513, 7}, {1, 1}, {2, 1}}) {
            const Plan plan = parsePlan(spec, w, h);
            EXPECT_EQ(parsePlan(plan.spec(), w, h), plan) << spec << " " << w << "x" << h;
            EXPECT_EQ(parsePlan(plan.name().starts_with("half-res ")
                                    ? "half:" + plan.name().substr(9)
                                    : plan.name(),
                                w, h),
                      plan)
                << spec;
        }
    }
    EXPECT_EQ(parsePlan("jfa^2", 8, 8).spec(), "jfa2");
    EXPECT_EQ(parsePlan("JFA+2", 8, 8).spec(), "jfa+2");
    EXPECT_EQ(parsePlan("(1)+jfa+(2,1)", 8, 8).spec(), "1+jfa+2");
    // Every factory's spec parses back to it.
    for (const Plan& plan :
         {Plan::jfa(300, 200), Plan::jfaPlus(2, 300, 200), Plan::jfaSquared(300, 200),
          Plan::onePlusJfa(300, 200), Plan::doubling(300, 200), Plan::flood(9, 300, 200),
          Plan::floodUntilUnchanged(300, 200), Plan::halfResolution(300, 200)}) {
        EXPECT_EQ(parsePlan(plan.spec(), 300, 200), plan) << plan;
    }
}

TEST(PlanParse, ErrorsListValidNames) {
    for (const char* bad :
         {"",         "   ",           "jfa3x",    "jfa+",    "jfa+0",    "jfa+31",
          "flood:",   "flood:0",       "flood:-3", "flood:x", "1+flood",  "flood+1",
          "half:",    "half:half:jfa", "2+jfa",    "jfa+1+1", "(2,)+jfa", "()+jfa",
          "(2,1+jfa", "(2,1)jfa",      "voronoi",  "jfa 2",   "jfa+(0)"}) {
        const std::string message = invalidArgumentMessage([&] { parsePlan(bad, 64, 64); });
        ASSERT_FALSE(message.empty()) << "accepted \"" << bad << "\"";
        EXPECT_NE(message.find(std::string("\"") + bad + "\""), std::string::npos) << message;
        EXPECT_NE(message.find("jfa+2"), std::string::npos) << message;
        EXPECT_NE(message.find("half:"), std::string::npos) << message;
    }
    EXPECT_THROW(parsePlan("jfa", 0, 64), std::invalid_argument);
}

} // namespace
} // namespace fl::jfa
