#pragma once
// An exact-arithmetic oracle for the predicate and triangulation tests, deliberately unlike the
// library's method: each double becomes the dyadic rational m * 2^e it denotes (m a big integer
// in base 2^16, no global scale), and the determinants are expanded by the Leibniz formula over
// the raw coordinates (no coordinate differences, no floating point). Slow and obviously right.

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <vector>

namespace fl::oracle {

/// A natural number: base-2^16 digits, least significant first, no leading zeros.
using Natural = std::vector<std::uint32_t>;

inline void trim(Natural& a) {
    while (!a.empty() && a.back() == 0) a.pop_back();
}

inline int compare(const Natural& a, const Natural& b) {
    if (a.size() != b.size()) return a.size() < b.size() ? -1 : 1;
    for (std::size_t i = a.size(); i-- > 0;)
        if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
    return 0;
}

inline Natural add(const Natural& a, const Natural& b) {
    Natural r(std::max(a.size(), b.size()) + 1, 0);
    std::uint32_t carry = 0;
    for (std::size_t i = 0; i < r.size(); ++i) {
        const std::uint32_t s = carry + (i < a.size() ? a[i] : 0) + (i < b.size() ? b[i] : 0);
        r[i] = s & 0xffff;
        carry = s >> 16;
    }
    trim(r);
    return r;
}

/// a - b for a >= b.
inline Natural subtract(const Natural& a, const Natural& b) {
    Natural r(a.size(), 0);
    std::int32_t borrow = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        std::int32_t d = static_cast<std::int32_t>(a[i]) - borrow -
                         static_cast<std::int32_t>(i < b.size() ? b[i] : 0);
        borrow = d < 0;
        r[i] = static_cast<std::uint32_t>(d + (borrow ? 0x10000 : 0));
    }
    trim(r);
    return r;
}

inline Natural multiply(const Natural& a, const Natural& b) {
    if (a.empty() || b.empty()) return {};
    std::vector<std::uint64_t> acc(a.size() + b.size() + 1, 0);
    for (std::size_t i = 0; i < a.size(); ++i)
        for (std::size_t j = 0; j < b.size(); ++j) acc[i + j] += std::uint64_t{a[i]} * b[j];
    Natural r(acc.size(), 0);
    std::uint64_t carry = 0;
    for (std::size_t i = 0; i < acc.size(); ++i) {
        const std::uint64_t s = acc[i] + carry;
        r[i] = static_cast<std::uint32_t>(s & 0xffff);
        carry = s >> 16;
    }
    trim(r);
    return r;
}

inline Natural shiftLeft(const Natural& a, long bits) {
    if (a.empty()) return {};
    Natural r(static_cast<std::size_t>(bits / 16), 0);
    const int rest = static_cast<int>(bits % 16);
    std::uint32_t carry = 0;
    for (const std::uint32_t digit : a) {
        const std::uint32_t v = (digit << rest) | carry;
        r.push_back(v & 0xffff);
        carry = v >> 16;
    }
    r.push_back(carry);
    trim(r);
    return r;
}

/// The exact value (negative ? -1 : 1) * m * 2^e.
struct Dyadic {
    bool negative = false;
    Natural m;
    long e = 0;

    [[nodiscard]] int sign() const { return m.empty() ? 0 : (negative ? -1 : 1); }
};

inline Dyadic fromDouble(double x) {
    Dyadic r;
    if (x == 0.0) return r;
    r.negative = x < 0;
    int exponent = 0;
    auto mantissa = static_cast<std::uint64_t>(std::ldexp(std::frexp(std::fabs(x), &exponent), 53));
    r.e = exponent - 53;
    while (mantissa != 0) {
        r.m.push_back(static_cast<std::uint32_t>(mantissa & 0xffff));
        mantissa >>= 16;
    }
    return r;
}

inline Dyadic operator*(const Dyadic& a, const Dyadic& b) {
    Dyadic r;
    r.m = multiply(a.m, b.m);
    if (r.m.empty()) return r;
    r.negative = a.negative != b.negative;
    r.e = a.e + b.e;
    return r;
}

inline Dyadic operator-(Dyadic a) {
    a.negative = !a.negative;
    return a;
}

inline Dyadic operator+(const Dyadic& a, const Dyadic& b) {
    if (a.m.empty()) return b;
    if (b.m.empty()) return a;
    const long e = std::min(a.e, b.e);
    const Natural am = shiftLeft(a.m, a.e - e), bm = shiftLeft(b.m, b.e - e);
    Dyadic r;
    r.e = e;
    if (a.negative == b.negative) {
        r.m = add(am, bm);
        r.negative = a.negative;
    } else {
        const int c = compare(am, bm);
        if (c == 0) return {};
        r.m = c > 0 ? subtract(am, bm) : subtract(bm, am);
        r.negative = c > 0 ? a.negative : b.negative;
    }
    return r;
}

/// The value rounded (roughly) to a double; nonzero values that do not fit are not clamped.
inline double approximate(const Dyadic& a) {
    if (a.m.empty()) return 0.0;
    double v = 0.0;
    long scale = a.e;
    // The top five digits carry more than 64 significant bits.
    const std::size_t n = a.m.size();
    const std::size_t from = n > 5 ? n - 5 : 0;
    for (std::size_t i = n; i-- > from;) v = v * 65536.0 + a.m[i];
    scale += static_cast<long>(from) * 16;
    v = std::ldexp(v, static_cast<int>(std::clamp(scale, -5000L, 5000L)));
    return a.negative ? -v : v;
}

/// Determinant of an n x n matrix of exact values by the Leibniz formula.
template <std::size_t N>
Dyadic determinant(const std::array<std::array<Dyadic, N>, N>& m) {
    std::array<std::size_t, N> perm;
    std::iota(perm.begin(), perm.end(), std::size_t{0});
    Dyadic total;
    do {
        int inversions = 0;
        for (std::size_t i = 0; i < N; ++i)
            for (std::size_t j = i + 1; j < N; ++j) inversions += perm[i] > perm[j];
        Dyadic term = m[0][perm[0]];
        for (std::size_t i = 1; i < N; ++i) term = term * m[i][perm[i]];
        total = total + (inversions % 2 ? -term : term);
    } while (std::next_permutation(perm.begin(), perm.end()));
    return total;
}

/// det [[ax, ay, 1], [bx, by, 1], [cx, cy, 1]]: positive for counter-clockwise a, b, c.
inline Dyadic orient(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
    const Dyadic one = fromDouble(1.0);
    std::array<std::array<Dyadic, 3>, 3> m;
    const glm::dvec2 rows[3] = {a, b, c};
    for (int i = 0; i < 3; ++i) m[i] = {fromDouble(rows[i].x), fromDouble(rows[i].y), one};
    return determinant(m);
}

/// det [[x, y, x^2 + y^2, 1]] over rows a, b, c, d: positive when d is inside the circle through
/// counter-clockwise a, b, c.
inline Dyadic incircle(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, glm::dvec2 d) {
    const Dyadic one = fromDouble(1.0);
    std::array<std::array<Dyadic, 4>, 4> m;
    const glm::dvec2 rows[4] = {a, b, c, d};
    for (int i = 0; i < 4; ++i) {
        const Dyadic x = fromDouble(rows[i].x), y = fromDouble(rows[i].y);
        m[i] = {x, y, x * x + y * y, one};
    }
    return determinant(m);
}

} // namespace fl::oracle
