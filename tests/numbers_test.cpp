// base/Numbers.h: the one rule for numbers users give (options, method options, scripts).

#include <base/Numbers.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace fl {
namespace {

TEST(Numbers, ParseNeedsTheWholeText) {
    double v = 0.0;
    EXPECT_TRUE(parseNumber("2.5", v));
    EXPECT_EQ(v, 2.5);
    EXPECT_TRUE(parseNumber("-1e3", v));
    EXPECT_EQ(v, -1000.0);
    EXPECT_FALSE(parseNumber("", v));
    EXPECT_FALSE(parseNumber("2.5x", v));
    EXPECT_FALSE(parseNumber(" 2", v));
    EXPECT_FALSE(parseNumber("1e400", v)); // beyond a double
}

TEST(Numbers, EveryRuleHasItsMessage) {
    EXPECT_EQ(numberProblem("3", 1, 8, true), "");
    EXPECT_EQ(numberProblem("0", 1, 8, true), "must be an integer in [1, 8], got '0'");
    EXPECT_EQ(numberProblem("2.5", 1, 8, true), "must be an integer in [1, 8], got '2.5'");
    EXPECT_EQ(numberProblem("abc", 1, 8, true), "must be an integer in [1, 8], got 'abc'");
    EXPECT_EQ(numberProblem("nan", -kUnbounded, kUnbounded, false),
              "must be a finite number, got 'nan'");
    EXPECT_EQ(numberProblem("inf", 0, kUnbounded, false),
              "must be a finite number >= 0, got 'inf'");
    EXPECT_EQ(numberProblem("-inf", -kUnbounded, 5, false),
              "must be a finite number <= 5, got '-inf'");
    EXPECT_EQ(numberProblem("0.95", 0, 0.95, false), "");
    EXPECT_EQ(numberProblem("0.96", 0, 0.95, false),
              "must be a finite number in [0, 0.95], got '0.96'");
    EXPECT_EQ(numberProblem(std::nan(""), 0, 1, false),
              "must be a finite number in [0, 1], got nan");
    EXPECT_EQ(numberProblem(1e6, 1, 100000, true),
              "must be an integer in [1, 100000], got 1000000");
    EXPECT_EQ(numberProblem(std::numeric_limits<double>::infinity(), 0, 1, false),
              "must be a finite number in [0, 1], got inf");
}

} // namespace
} // namespace fl
