// Exact predicates: every sign agrees with an independent exact oracle (exact_oracle.h) on
// random, nearly degenerate, exactly degenerate, huge, tiny and mixed-magnitude inputs, and each
// internal method (filter, scaled expansions, big integers) is checked on its own.

#include <geometry/Predicates.h>

#include "exact_oracle.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

namespace fl::geom {
namespace {

using glm::dvec2;
__extension__ typedef __int128 Int128; // exact for small-integer determinants

int sgn(double v) {
    return (v > 0) - (v < 0);
}

int sgn(Int128 v) {
    return (v > 0) - (v < 0);
}

// Every method must agree with the oracle; returns the oracle's sign.
int expectOrientExact(dvec2 a, dvec2 b, dvec2 c) {
    const int expected = oracle::orient(a, b, c).sign();
    EXPECT_EQ(orient2dSign(a, b, c), expected)
        << a.x << "," << a.y << " " << b.x << "," << b.y << " " << c.x << "," << c.y;
    EXPECT_EQ(sgn(orient2d(a, b, c)), expected);
    EXPECT_EQ(sgn(detail::orient2dExact(a, b, c)), expected);
    EXPECT_EQ(sgn(detail::orient2dBigInteger(a, b, c)), expected);
    return expected;
}

int expectIncircleExact(dvec2 a, dvec2 b, dvec2 c, dvec2 d) {
    const int expected = oracle::incircle(a, b, c, d).sign();
    EXPECT_EQ(incircleSign(a, b, c, d), expected)
        << a.x << "," << a.y << " " << b.x << "," << b.y << " " << c.x << "," << c.y << " " << d.x
        << "," << d.y;
    EXPECT_EQ(sgn(incircle(a, b, c, d)), expected);
    EXPECT_EQ(sgn(detail::incircleExact(a, b, c, d)), expected);
    EXPECT_EQ(sgn(detail::incircleBigInteger(a, b, c, d)), expected);
    return expected;
}

// A double with a random significand and a binary exponent in [minExp, maxExp), random sign.
double randomBinade(std::mt19937_64& rng, int minExp, int maxExp) {
    const double significand = 1.0 + std::ldexp(static_cast<double>(rng() >> 12), -52);
    const int e = std::uniform_int_distribution<int>(minExp, maxExp - 1)(rng);
    const double v = std::ldexp(significand, e);
    return (rng() & 1) ? -v : v;
}

// A random subnormal (or zero) with random sign.
double randomSubnormal(std::mt19937_64& rng) {
    const std::uint64_t bits =
        (rng() & ((std::uint64_t{1} << 52) - 1)) | (rng() & (std::uint64_t{1} << 63));
    return std::bit_cast<double>(bits);
}

TEST(ExactOracle, MatchesInt128OnSmallIntegers) {
    std::mt19937_64 rng(1);
    std::uniform_int_distribution<int> coord(-1000000, 1000000);
    for (int i = 0; i < 2000; ++i) {
        Int128 p[4][2];
        dvec2 q[4];
        for (int k = 0; k < 4; ++k) {
            p[k][0] = coord(rng);
            p[k][1] = coord(rng);
            q[k] = dvec2(static_cast<double>(p[k][0]), static_cast<double>(p[k][1]));
        }
        const Int128 o =
            (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0]);
        EXPECT_EQ(oracle::orient(q[0], q[1], q[2]).sign(), sgn(o));
        Int128 rows[3][3];
        for (int k = 0; k < 3; ++k) {
            const Int128 dx = p[k][0] - p[3][0], dy = p[k][1] - p[3][1];
            rows[k][0] = dx;
            rows[k][1] = dy;
            rows[k][2] = dx * dx + dy * dy;
        }
        const Int128 ic = rows[0][0] * (rows[1][1] * rows[2][2] - rows[2][1] * rows[1][2]) -
                          rows[1][0] * (rows[0][1] * rows[2][2] - rows[2][1] * rows[0][2]) +
                          rows[2][0] * (rows[0][1] * rows[1][2] - rows[1][1] * rows[0][2]);
        EXPECT_EQ(oracle::incircle(q[0], q[1], q[2], q[3]).sign(), sgn(ic));
        // And the predicates themselves on exactly representable integers.
        EXPECT_EQ(orient2dSign(q[0], q[1], q[2]), sgn(o));
        EXPECT_EQ(incircleSign(q[0], q[1], q[2], q[3]), sgn(ic));
    }
}

TEST(Orient2d, BasicOrientationAndExactValues) {
    EXPECT_EQ(orient2d({0, 0}, {1, 0}, {0, 1}), 1.0);
    EXPECT_EQ(orient2d({0, 0}, {0, 1}, {1, 0}), -1.0);
    EXPECT_EQ(orient2d({0, 0}, {1, 1}, {2, 2}), 0.0);
    EXPECT_EQ(orient2dSign({0, 0}, {1, 0}, {0, 1}), 1);
    EXPECT_EQ(orient2dSign({0, 0}, {0, 1}, {1, 0}), -1);
    EXPECT_EQ(orient2dSign({-0.0, 0.0}, {0.0, -0.0}, {1, 1}), 0); // signed zeros are one point
}

TEST(Orient2d, RandomPointsMatchOracle) {
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 3000; ++i)
        expectOrientExact({u(rng), u(rng)}, {u(rng), u(rng)}, {u(rng), u(rng)});
}

// Shewchuk's classic picture: a 256 x 256 grid of the doubles nearest (0.5, 0.5) against the
// line through (12, 12) and (24, 24). The naive determinant gets many of these wrong.
TEST(Orient2d, NextafterGridAgainstDiagonalLine) {
    const double ulp = std::ldexp(1.0, -53); // spacing of doubles in [0.5, 1)
    int naiveWrong = 0, collinear = 0;
    for (int i = 0; i < 256; ++i)
        for (int j = 0; j < 256; ++j) {
            const dvec2 p(0.5 + i * ulp, 0.5 + j * ulp), q(12, 12), r(24, 24);
            const int expected = oracle::orient(p, q, r).sign();
            ASSERT_EQ(orient2dSign(p, q, r), expected) << i << ", " << j;
            const double naive = (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
            naiveWrong += sgn(naive) != expected;
            collinear += expected == 0;
        }
    EXPECT_EQ(collinear, 256); // exactly the diagonal i == j
    EXPECT_GT(naiveWrong, 1000) << "the grid should defeat plain floating point";
}

TEST(Orient2d, PointsOnALinePerturbedByUlps) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(-100.0, 100.0), t(0.0, 1.0);
    for (int i = 0; i < 1500; ++i) {
        const dvec2 a(u(rng), u(rng)), b(u(rng), u(rng));
        const double s = t(rng);
        dvec2 c = a + s * (b - a); // on the line up to rounding
        for (int k = 0; k < static_cast<int>(rng() % 4); ++k)
            c.x = std::nextafter(c.x, (rng() & 1) ? 1e9 : -1e9);
        expectOrientExact(a, b, c);
        expectOrientExact(c, a, b);
    }
    // Exactly collinear cases through doubles on the diagonal, whatever their magnitude.
    for (int i = 0; i < 300; ++i) {
        const double x = randomBinade(rng, -1000, 1000), y = randomBinade(rng, -1000, 1000),
                     z = randomBinade(rng, -1000, 1000);
        EXPECT_EQ(orient2d({x, x}, {y, y}, {z, z}), 0.0);
        EXPECT_EQ(orient2d({x, 2 * x}, {y, 2 * y}, {z, 2 * z}), 0.0);
    }
}

TEST(Orient2d, ScalingByPowersOfTwoKeepsTheSign) {
    std::mt19937_64 rng(4);
    std::uniform_int_distribution<int> coord(-40, 40);
    for (int i = 0; i < 300; ++i) {
        dvec2 p[3];
        for (dvec2& v : p) v = dvec2(coord(rng), coord(rng));
        const int expected = oracle::orient(p[0], p[1], p[2]).sign();
        for (int k = -1074; k <= 1016; k += 13) {
            const dvec2 a(std::ldexp(p[0].x, k), std::ldexp(p[0].y, k));
            const dvec2 b(std::ldexp(p[1].x, k), std::ldexp(p[1].y, k));
            const dvec2 c(std::ldexp(p[2].x, k), std::ldexp(p[2].y, k));
            // Near the bottom of the range scaling may round; then only the oracle decides.
            const bool exact = std::ldexp(a.x, -k) == p[0].x && std::ldexp(b.y, -k) == p[1].y &&
                               std::ldexp(c.x, -k) == p[2].x && std::ldexp(c.y, -k) == p[2].y &&
                               std::ldexp(a.y, -k) == p[0].y && std::ldexp(b.x, -k) == p[1].x;
            const int scaledExpected = exact ? expected : oracle::orient(a, b, c).sign();
            ASSERT_EQ(orient2dSign(a, b, c), scaledExpected) << "k = " << k;
        }
    }
}

TEST(Orient2d, HugeAndTinyDeterminantsKeepTheirSign) {
    const double huge = 1e300, tiny = 1e-300;
    // The determinant overflows: the sign must survive, the value stays finite.
    const double big = orient2d({-huge, -huge}, {huge, -huge}, {0, huge});
    EXPECT_GT(big, 0.0);
    EXPECT_TRUE(std::isfinite(big));
    // The determinant underflows: still nonzero with the right sign.
    const double small = orient2d({0, 0}, {tiny, 0}, {0, tiny});
    EXPECT_GT(small, 0.0);
    EXPECT_EQ(orient2d({0, 0}, {0, tiny}, {tiny, 0}), -small);
    const double sub = std::numeric_limits<double>::denorm_min();
    EXPECT_EQ(orient2dSign({0, 0}, {sub, 0}, {0, sub}), 1);
    EXPECT_EQ(orient2dSign({0, 0}, {sub, sub}, {2 * sub, 2 * sub}), 0);
    EXPECT_EQ(orient2dSign({sub, 0}, {0, sub}, {0, 0}), 1);
    const double max = std::numeric_limits<double>::max();
    EXPECT_EQ(orient2dSign({-max, -max}, {max, -max}, {max, max}), 1);
    EXPECT_EQ(orient2dSign({-max, -max}, {max, max}, {0, 0}), 0);
}

TEST(Orient2d, MixedMagnitudesMatchOracle) {
    std::mt19937_64 rng(5);
    int bigIntegerCases = 0;
    for (int i = 0; i < 1500; ++i) {
        double v[6];
        for (double& x : v) {
            const auto kind = rng() % 8;
            x = kind == 0 ? 0.0 : kind == 1 ? randomSubnormal(rng) : randomBinade(rng, -1074, 1023);
        }
        const dvec2 a(v[0], v[1]), b(v[2], v[3]), c(v[4], v[5]);
        expectOrientExact(a, b, c);
        bigIntegerCases += detail::orient2dExactMethod(a, b, c) == detail::ExactMethod::BigInteger;
    }
    EXPECT_GT(bigIntegerCases, 500) << "mixed magnitudes should exercise the big-integer path";
}

// Exactly collinear points whose coordinates span the whole double range, nudged by one ulp: the
// answer hangs on the smallest bits next to the largest.
TEST(Orient2d, MixedMagnitudesNearlyCollinear) {
    std::mt19937_64 rng(6);
    int nonzero = 0;
    for (int i = 0; i < 600; ++i) {
        const double x = randomBinade(rng, -1074, 1023), y = randomBinade(rng, -1074, 1023),
                     z = randomBinade(rng, -1074, 1023);
        dvec2 a(x, x), b(y, y), c(z, z);
        EXPECT_EQ(expectOrientExact(a, b, c), 0);
        dvec2* target = (rng() & 1) ? &a : &c;
        target->y = std::nextafter(target->y, (rng() & 1) ? 1e308 : -1e308);
        nonzero += expectOrientExact(a, b, c) != 0;
    }
    EXPECT_EQ(nonzero, 600);
    // A classic: huge points on the diagonal and a tiny point just off it.
    const double up = std::nextafter(1e-300, 1.0);
    EXPECT_EQ(expectOrientExact({1e300, 1e300}, {-1e300, -1e300}, {1e-300, up}), -1);
    EXPECT_EQ(detail::orient2dExactMethod({1e300, 1e300}, {-1e300, -1e300}, {1e-300, up}),
              detail::ExactMethod::BigInteger);
}

TEST(Orient2d, ExactValueIsAccurate) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 500; ++i) {
        const dvec2 a(u(rng), u(rng)), b(u(rng), u(rng)), c(u(rng), u(rng));
        const double exact = oracle::approximate(oracle::orient(a, b, c));
        EXPECT_NEAR(detail::orient2dExact(a, b, c), exact, 1e-14 * std::fabs(exact));
        EXPECT_NEAR(detail::orient2dBigInteger(a, b, c), exact, 1e-14 * std::fabs(exact));
        // The filter's value is off by less than its error bound, ~3.3e-16 * permanent.
        const double permanent =
            std::fabs((a.x - c.x) * (b.y - c.y)) + std::fabs((a.y - c.y) * (b.x - c.x));
        EXPECT_NEAR(orient2d(a, b, c), exact, 4e-16 * permanent);
    }
}

TEST(Orient2d, AntisymmetryOnNearDegenerateInputs) {
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 2000; ++i) {
        const dvec2 a(u(rng), u(rng)), b(u(rng), u(rng));
        dvec2 c = 0.5 * (a + b);
        c.y = std::nextafter(c.y, (i & 1) ? 2.0 : -2.0);
        const int s = orient2dSign(a, b, c);
        EXPECT_EQ(orient2dSign(b, c, a), s);
        EXPECT_EQ(orient2dSign(c, a, b), s);
        EXPECT_EQ(orient2dSign(b, a, c), -s);
    }
}

TEST(Orient2d, NonFiniteInputThrows) {
    const double inf = std::numeric_limits<double>::infinity();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(orient2d({inf, 0}, {1, 0}, {0, 1}), std::invalid_argument);
    EXPECT_THROW(orient2d({0, 0}, {nan, 0}, {0, 1}), std::invalid_argument);
    EXPECT_THROW(incircle({0, 0}, {1, 0}, {0, 1}, {0, -inf}), std::invalid_argument);
    EXPECT_THROW(incircleSign({0, 0}, {1, 0}, {nan, 1}, {0, 0}), std::invalid_argument);
}

TEST(Incircle, BasicInsideOutsideOn) {
    const dvec2 a(0, 0), b(2, 0), c(0, 2);
    EXPECT_EQ(incircleSign(a, b, c, {1, 1}), 1);
    EXPECT_EQ(incircleSign(a, b, c, {3, 3}), -1);
    EXPECT_EQ(incircleSign(a, b, c, {2, 2}), 0);
    EXPECT_EQ(incircleSign(a, c, b, {1, 1}), -1); // clockwise a, b, c flips the sign
}

TEST(Incircle, RandomPointsMatchOracle) {
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 1500; ++i)
        expectIncircleExact({u(rng), u(rng)}, {u(rng), u(rng)}, {u(rng), u(rng)}, {u(rng), u(rng)});
}

// Integer points on x^2 + y^2 = 65^2 (which has 12 lattice points per quadrant-ish): every four
// of them are exactly cocircular, also translated and scaled by any representable power of two.
std::vector<dvec2> latticeCircle(int r) {
    std::vector<dvec2> pts;
    for (int x = -r; x <= r; ++x)
        for (int y = -r; y <= r; ++y)
            if (x * x + y * y == r * r) pts.emplace_back(x, y);
    std::sort(pts.begin(), pts.end(),
              [](dvec2 p, dvec2 q) { return std::atan2(p.y, p.x) < std::atan2(q.y, q.x); });
    return pts;
}

TEST(Incircle, CocircularIntegerPointsAreExactlyOnTheCircle) {
    const std::vector<dvec2> circle = latticeCircle(65);
    ASSERT_EQ(circle.size(), 36u);
    std::mt19937_64 rng(10);
    std::uniform_int_distribution<std::size_t> pick(0, circle.size() - 1);
    const std::pair<dvec2, int> placements[] = {
        {{0, 0}, 0},           {{1e6, -3e6}, 0},    {{12345, 678}, -1074},
        {{-7, 1 << 20}, -600}, {{1 << 30, 5}, 900}, {{0, 0}, 950},
        {{3, 3}, -1000},       {{1e9, 1e9}, 700},   {{0, 0}, -1060}};
    for (const auto& [offset, k] : placements) {
        for (int i = 0; i < 150; ++i) {
            std::size_t idx[3] = {pick(rng), pick(rng), pick(rng)};
            std::sort(idx, idx + 3);
            if (idx[0] == idx[1] || idx[1] == idx[2]) continue;
            const auto place = [&, off = offset, kk = k](dvec2 p) {
                return dvec2(std::ldexp(p.x + off.x, kk), std::ldexp(p.y + off.y, kk));
            };
            const dvec2 a = place(circle[idx[0]]), b = place(circle[idx[1]]),
                        c = place(circle[idx[2]]), d = place(circle[pick(rng)]);
            ASSERT_EQ(incircleSign(a, b, c, d), 0) << "k = " << k;
            // One ulp inwards or outwards along x: the oracle decides.
            dvec2 moved = d;
            moved.x = std::nextafter(moved.x, (i & 1) ? 1e308 : -1e308);
            if (moved.x == d.x) continue;
            EXPECT_EQ(incircleSign(a, b, c, moved), oracle::incircle(a, b, c, moved).sign());
        }
    }
}

TEST(Incircle, NearlyCocircularFromTrigonometry) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> angle(0.0, 6.283185307179586);
    for (int i = 0; i < 1200; ++i) {
        double t[4];
        for (double& v : t) v = angle(rng);
        std::sort(t, t + 3);
        const double r = std::ldexp(1.0, static_cast<int>(rng() % 200) - 100);
        const auto on = [&](double th) { return dvec2(r * std::cos(th) + 0.25, r * std::sin(th)); };
        expectIncircleExact(on(t[0]), on(t[1]), on(t[2]), on(t[3]));
    }
}

TEST(Incircle, MixedMagnitudesMatchOracle) {
    std::mt19937_64 rng(12);
    int bigIntegerCases = 0;
    for (int i = 0; i < 600; ++i) {
        double v[8];
        for (double& x : v) {
            const auto kind = rng() % 8;
            x = kind == 0 ? 0.0 : kind == 1 ? randomSubnormal(rng) : randomBinade(rng, -1074, 1023);
        }
        const dvec2 a(v[0], v[1]), b(v[2], v[3]), c(v[4], v[5]), d(v[6], v[7]);
        expectIncircleExact(a, b, c, d);
        bigIntegerCases +=
            detail::incircleExactMethod(a, b, c, d) == detail::ExactMethod::BigInteger;
    }
    EXPECT_GT(bigIntegerCases, 300);
}

// A circle of radius r about the origin, with d moved off it by an amount far below r's ulp: the
// sign depends on t^2, hundreds of binades below r^2.
TEST(Incircle, HugeCircleTinyOffset) {
    for (const double r : {1e200, 1e100, 1.0, 1e-100, 1e-150}) {
        for (const double t : {1e-200, 1e-300, 4.9e-324, 1e-20}) {
            const dvec2 a(r, 0), b(0, r), c(-r, 0);
            EXPECT_EQ(incircleSign(a, b, c, {0, -r}), 0);
            EXPECT_EQ(expectIncircleExact(a, b, c, {t, -r}), t == 0 ? 0 : -1)
                << "r " << r << " t " << t;
            // Moving d inwards along y by one ulp of r puts it inside.
            EXPECT_EQ(expectIncircleExact(a, b, c, {t, std::nextafter(-r, 0.0)}),
                      oracle::incircle(a, b, c, {t, std::nextafter(-r, 0.0)}).sign());
        }
    }
}

TEST(Incircle, ScalingByPowersOfTwoKeepsTheSign) {
    std::mt19937_64 rng(13);
    std::uniform_int_distribution<int> coord(-20, 20);
    for (int i = 0; i < 60; ++i) {
        dvec2 p[4];
        for (dvec2& v : p) v = dvec2(coord(rng), coord(rng));
        const int expected = oracle::incircle(p[0], p[1], p[2], p[3]).sign();
        for (int k = -1069; k <= 1010; k += 29) {
            dvec2 s[4];
            for (int j = 0; j < 4; ++j) s[j] = dvec2(std::ldexp(p[j].x, k), std::ldexp(p[j].y, k));
            ASSERT_EQ(incircleSign(s[0], s[1], s[2], s[3]), expected) << "k = " << k;
        }
    }
}

TEST(Incircle, RotationAndSwapSymmetry) {
    std::mt19937_64 rng(14);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 1000; ++i) {
        const dvec2 a(u(rng), u(rng)), b(u(rng), u(rng)), c(u(rng), u(rng));
        // d on the circumcircle up to rounding: nearly degenerate.
        const double A = 2 * (a.x * (b.y - c.y) + b.x * (c.y - a.y) + c.x * (a.y - b.y));
        const double ux =
            ((a.x * a.x + a.y * a.y) * (b.y - c.y) + (b.x * b.x + b.y * b.y) * (c.y - a.y) +
             (c.x * c.x + c.y * c.y) * (a.y - b.y)) /
            A;
        const double uy =
            ((a.x * a.x + a.y * a.y) * (c.x - b.x) + (b.x * b.x + b.y * b.y) * (a.x - c.x) +
             (c.x * c.x + c.y * c.y) * (b.x - a.x)) /
            A;
        const dvec2 d = 2.0 * dvec2(ux, uy) - a; // antipode of a
        const int s = incircleSign(a, b, c, d);
        EXPECT_EQ(incircleSign(b, c, a, d), s);
        EXPECT_EQ(incircleSign(c, a, b, d), s);
        EXPECT_EQ(incircleSign(b, a, c, d), -s);
        if (i < 200) {
            EXPECT_EQ(s, oracle::incircle(a, b, c, d).sign());
        }
    }
}

} // namespace
} // namespace fl::geom
