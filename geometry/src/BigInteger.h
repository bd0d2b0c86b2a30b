#pragma once
// A small signed arbitrary-precision integer: the last resort of the exact predicates, used only
// when the inputs span too many binades for floating-point expansions (Predicates.cpp). Slow
// and simple on purpose: schoolbook arithmetic on 32-bit limbs.

#include <cstdint>
#include <vector>

namespace fl::geom::detail {

class BigInteger {
  public:
    BigInteger() = default;
    /// The integer x * 2^-shift; x * 2^-shift must be an integer (shift at most the exponent of
    /// x's lowest set bit) and x finite.
    static BigInteger fromScaledDouble(double x, int shift);

    /// -1, 0 or +1.
    [[nodiscard]] int sign() const { return mag_.empty() ? 0 : (negative_ ? -1 : 1); }
    /// The value times 2^exponent rounded to a double, clamped so that a nonzero value never
    /// becomes 0 (smallest subnormal instead) or infinite (largest finite instead).
    [[nodiscard]] double toDouble(int exponent) const;

    friend BigInteger operator+(const BigInteger& a, const BigInteger& b);
    friend BigInteger operator-(const BigInteger& a, const BigInteger& b);
    friend BigInteger operator*(const BigInteger& a, const BigInteger& b);

  private:
    using Limbs = std::vector<std::uint32_t>; // little-endian magnitude, no leading zero limbs

    static int compareMagnitude(const Limbs& a, const Limbs& b);
    static Limbs addMagnitude(const Limbs& a, const Limbs& b);
    static Limbs subtractMagnitude(const Limbs& a, const Limbs& b); // requires |a| >= |b|
    static BigInteger signedSum(const BigInteger& a, const BigInteger& b, bool negateB);

    bool negative_ = false;
    Limbs mag_;
};

} // namespace fl::geom::detail
