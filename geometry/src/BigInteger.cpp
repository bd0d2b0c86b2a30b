#include "BigInteger.h"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>
#include <limits>

namespace fl::geom::detail {

BigInteger BigInteger::fromScaledDouble(double x, int shift) {
    BigInteger r;
    if (x == 0.0) return r;
    int exponent = 0;
    const double fraction = std::frexp(std::fabs(x), &exponent); // |x| = fraction * 2^exponent
    // |x| = mantissa * 2^(exponent - 53) with an integer mantissa below 2^53.
    auto mantissa = static_cast<std::uint64_t>(std::ldexp(fraction, 53));
    int bitShift = exponent - 53 - shift;
    if (bitShift < 0) {
        assert(std::countr_zero(mantissa) >= -bitShift);
        mantissa >>= -bitShift;
        bitShift = 0;
    }
    const auto limbShift = static_cast<std::size_t>(bitShift / 32);
    const int rest = bitShift % 32;
    r.mag_.assign(limbShift, 0);
    // mantissa << rest needs up to 85 bits: three limbs.
    const std::uint64_t low = mantissa << rest;
    const std::uint64_t high = rest == 0 ? 0 : mantissa >> (64 - rest);
    r.mag_.push_back(static_cast<std::uint32_t>(low));
    r.mag_.push_back(static_cast<std::uint32_t>(low >> 32));
    r.mag_.push_back(static_cast<std::uint32_t>(high));
    while (!r.mag_.empty() && r.mag_.back() == 0) r.mag_.pop_back();
    r.negative_ = x < 0.0;
    return r;
}

double BigInteger::toDouble(int exponent) const {
    if (mag_.empty()) return 0.0;
    // The top 64 bits (or fewer) as a double, then the remaining power of two in steps that
    // cannot overflow ldexp's int argument.
    const auto topLimb = mag_.size() - 1;
    const int topBits = 32 - std::countl_zero(mag_[topLimb]);
    const auto bitLength = static_cast<long long>(topLimb) * 32 + topBits;
    std::uint64_t top = 0;
    long long dropped = 0; // bits below `top`
    if (bitLength <= 64) {
        for (std::size_t i = mag_.size(); i-- > 0;) top = (top << 32) | mag_[i];
    } else {
        dropped = bitLength - 64;
        // Gather bits [dropped, dropped + 64) from the limbs.
        for (int bit = 63; bit >= 0; --bit) {
            const auto index = static_cast<std::size_t>(dropped + bit);
            top = (top << 1) | ((mag_[index / 32] >> (index % 32)) & 1u);
        }
    }
    const long long totalExponent = dropped + exponent;
    const auto clampedExponent = static_cast<int>(std::clamp(totalExponent, -4000LL, 4000LL));
    double v = std::ldexp(static_cast<double>(top), clampedExponent);
    if (v == 0.0) v = std::numeric_limits<double>::denorm_min();
    if (std::isinf(v)) v = std::numeric_limits<double>::max();
    return negative_ ? -v : v;
}

int BigInteger::compareMagnitude(const Limbs& a, const Limbs& b) {
    if (a.size() != b.size()) return a.size() < b.size() ? -1 : 1;
    for (std::size_t i = a.size(); i-- > 0;)
        if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
    return 0;
}

BigInteger::Limbs BigInteger::addMagnitude(const Limbs& a, const Limbs& b) {
    const Limbs& longer = a.size() >= b.size() ? a : b;
    const Limbs& shorter = a.size() >= b.size() ? b : a;
    Limbs r(longer.size() + 1, 0);
    std::uint64_t carry = 0;
    for (std::size_t i = 0; i < longer.size(); ++i) {
        const std::uint64_t s = carry + longer[i] + (i < shorter.size() ? shorter[i] : 0u);
        r[i] = static_cast<std::uint32_t>(s);
        carry = s >> 32;
    }
    r.back() = static_cast<std::uint32_t>(carry);
    while (!r.empty() && r.back() == 0) r.pop_back();
    return r;
}

BigInteger::Limbs BigInteger::subtractMagnitude(const Limbs& a, const Limbs& b) {
    Limbs r(a.size(), 0);
    std::int64_t borrow = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        std::int64_t d = static_cast<std::int64_t>(a[i]) - borrow -
                         static_cast<std::int64_t>(i < b.size() ? b[i] : 0u);
        borrow = d < 0 ? 1 : 0;
        if (d < 0) d += std::int64_t{1} << 32;
        r[i] = static_cast<std::uint32_t>(d);
    }
    assert(borrow == 0);
    while (!r.empty() && r.back() == 0) r.pop_back();
    return r;
}

BigInteger BigInteger::signedSum(const BigInteger& a, const BigInteger& b, bool negateB) {
    const bool bNegative = negateB ? !b.negative_ : b.negative_;
    BigInteger r;
    if (b.mag_.empty()) return a;
    if (a.mag_.empty()) {
        r.mag_ = b.mag_;
        r.negative_ = bNegative;
        return r;
    }
    if (a.negative_ == bNegative) {
        r.mag_ = addMagnitude(a.mag_, b.mag_);
        r.negative_ = a.negative_;
        return r;
    }
    const int cmp = compareMagnitude(a.mag_, b.mag_);
    if (cmp == 0) return r;
    if (cmp > 0) {
        r.mag_ = subtractMagnitude(a.mag_, b.mag_);
        r.negative_ = a.negative_;
    } else {
        r.mag_ = subtractMagnitude(b.mag_, a.mag_);
        r.negative_ = bNegative;
    }
    return r;
}

BigInteger operator+(const BigInteger& a, const BigInteger& b) {
    return BigInteger::signedSum(a, b, false);
}

BigInteger operator-(const BigInteger& a, const BigInteger& b) {
    return BigInteger::signedSum(a, b, true);
}

BigInteger operator*(const BigInteger& a, const BigInteger& b) {
    BigInteger r;
    if (a.mag_.empty() || b.mag_.empty()) return r;
    r.mag_.assign(a.mag_.size() + b.mag_.size(), 0);
    for (std::size_t i = 0; i < a.mag_.size(); ++i) {
        std::uint64_t carry = 0;
        for (std::size_t j = 0; j < b.mag_.size(); ++j) {
            // a * b + r + carry < 2^64: (2^32 - 1)^2 + 2 (2^32 - 1) = 2^64 - 1.
            const std::uint64_t t =
                static_cast<std::uint64_t>(a.mag_[i]) * b.mag_[j] + r.mag_[i + j] + carry;
            r.mag_[i + j] = static_cast<std::uint32_t>(t);
            carry = t >> 32;
        }
        r.mag_[i + b.mag_.size()] = static_cast<std::uint32_t>(carry);
    }
    while (!r.mag_.empty() && r.mag_.back() == 0) r.mag_.pop_back();
    r.negative_ = a.negative_ != b.negative_;
    return r;
}

} // namespace fl::geom::detail
