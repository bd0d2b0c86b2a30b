#pragma once
// Floating-point expansions (Priest, Shewchuk 1997): a value held exactly as a sum of doubles
// ordered by increasing magnitude whose bits do not overlap. Used by the exact stage of the
// predicates in Predicates.cpp.
//
// Every routine here is exact only while no operation overflows or underflows (the error-free
// transformations below assume both); Predicates.cpp scales its inputs by a power of two so that
// every component stays in [2^-1000, 2^1000] and calls something else when that is impossible.
// They also need round-to-nearest-even arithmetic without fused multiply-adds: the project
// compiles with -ffp-contract=off, and x86-64 / AArch64 round to even.

#include <cassert>
#include <cstddef>

namespace fl::geom::detail {

/// x + y == a + b exactly, x = fl(a + b) (Knuth's Two-Sum).
inline void twoSum(double a, double b, double& x, double& y) {
    x = a + b;
    const double bVirtual = x - a;
    const double aVirtual = x - bVirtual;
    y = (a - aVirtual) + (b - bVirtual);
}

/// x + y == a + b exactly for |a| >= |b| (Dekker's Fast-Two-Sum).
inline void fastTwoSum(double a, double b, double& x, double& y) {
    x = a + b;
    y = b - (x - a);
}

/// x + y == a - b exactly, x = fl(a - b).
inline void twoDiff(double a, double b, double& x, double& y) {
    x = a - b;
    const double bVirtual = a - x;
    const double aVirtual = x + bVirtual;
    y = (a - aVirtual) + (bVirtual - b);
}

/// hi + lo == a with each half at most 26 significant bits (Veltkamp's split).
inline void split(double a, double& hi, double& lo) {
    constexpr double kSplitter = 134217729.0; // 2^27 + 1
    const double c = kSplitter * a;
    const double big = c - a;
    hi = c - big;
    lo = a - hi;
}

/// x + y == a * b exactly, x = fl(a * b) (Dekker's Two-Product).
inline void twoProduct(double a, double b, double& x, double& y) {
    x = a * b;
    double aHi, aLo, bHi, bLo;
    split(a, aHi, aLo);
    split(b, bHi, bLo);
    const double err1 = x - aHi * bHi;
    const double err2 = err1 - aLo * bHi;
    const double err3 = err2 - aHi * bLo;
    y = aLo * bLo - err3;
}

/// An expansion with room for N components; n == 0 means the value 0. Components are nonzero.
template <std::size_t N>
struct Expansion {
    double c[N];
    std::size_t n = 0;

    /// Appends a component (callers append in increasing magnitude); zeros are dropped.
    void push(double v) {
        if (v != 0.0) {
            assert(n < N);
            c[n++] = v;
        }
    }
    /// The sign of the value: the largest component outweighs all the others together.
    [[nodiscard]] int sign() const { return n == 0 ? 0 : (c[n - 1] > 0.0 ? 1 : -1); }
    /// The value to within a few ulps, with the exact sign. The components are summed from the
    /// smallest up (the largest alone can be off by as much as its lowest set bit). That sum can
    /// only go wrong by rounding the rest up to exactly minus a power-of-two top component,
    /// giving 0; the top component then stands in, sign intact.
    [[nodiscard]] double estimate() const {
        if (n == 0) return 0.0;
        double s = 0.0;
        for (std::size_t i = 0; i < n; ++i) s += c[i];
        return (s > 0.0) == (c[n - 1] > 0.0) && s != 0.0 ? s : c[n - 1];
    }
    void negate() {
        for (std::size_t i = 0; i < n; ++i) c[i] = -c[i];
    }
};

/// The two-component expansion of a Two-Diff or Two-Product result: y below x, zeros dropped.
inline Expansion<2> twoComponents(double x, double y) {
    Expansion<2> e;
    e.push(y);
    e.push(x);
    return e;
}

/// The exact difference a - b of two doubles as an expansion.
inline Expansion<2> difference(double a, double b) {
    double x, y;
    twoDiff(a, b, x, y);
    return twoComponents(x, y);
}

/// The exact product a * b of two doubles as an expansion.
inline Expansion<2> product(double a, double b) {
    double x, y;
    twoProduct(a, b, x, y);
    return twoComponents(x, y);
}

/// Writes e + f into h (room for en + fn) and returns its length: Shewchuk's
/// Fast-Expansion-Sum with zero elimination. The components are merged by magnitude into h,
/// then a running sum is carried through them in place (step m reads h[m] and writes below m).
inline std::size_t sumInto(const double* e, std::size_t en, const double* f, std::size_t fn,
                           double* h) {
    std::size_t i = 0, j = 0, k = 0;
    while (i < en && j < fn) {
        const double ei = e[i], fj = f[j];
        h[k++] = (ei < 0 ? -ei : ei) <= (fj < 0 ? -fj : fj) ? e[i++] : f[j++];
    }
    while (i < en) h[k++] = e[i++];
    while (j < fn) h[k++] = f[j++];
    if (k < 2 || en == 0 || fn == 0) return k;

    std::size_t out = 0;
    double q, err;
    fastTwoSum(h[1], h[0], q, err);
    if (err != 0.0) h[out++] = err;
    for (std::size_t m = 2; m < k; ++m) {
        double next;
        twoSum(q, h[m], next, err);
        if (err != 0.0) h[out++] = err;
        q = next;
    }
    if (q != 0.0) h[out++] = q;
    return out;
}

/// e + f.
template <std::size_t N, std::size_t M>
Expansion<N + M> sum(const Expansion<N>& e, const Expansion<M>& f) {
    Expansion<N + M> h;
    h.n = sumInto(e.c, e.n, f.c, f.n, h.c);
    return h;
}

/// e - f.
template <std::size_t N, std::size_t M>
Expansion<N + M> diff(const Expansion<N>& e, Expansion<M> f) {
    f.negate();
    return sum(e, f);
}

/// h = e * b (Shewchuk's Scale-Expansion with zero elimination).
template <std::size_t N>
Expansion<2 * N> scale(const Expansion<N>& e, double b) {
    Expansion<2 * N> h;
    if (e.n == 0 || b == 0.0) return h;
    double q, err;
    twoProduct(e.c[0], b, q, err);
    h.push(err);
    for (std::size_t i = 1; i < e.n; ++i) {
        double pHi, pLo, s;
        twoProduct(e.c[i], b, pHi, pLo);
        twoSum(q, pLo, s, err);
        h.push(err);
        fastTwoSum(pHi, s, q, err);
        h.push(err);
    }
    h.push(q);
    return h;
}

/// e * f: one scaled copy of e per component of f, accumulated.
template <std::size_t N, std::size_t M>
Expansion<2 * N * M> product(const Expansion<N>& e, const Expansion<M>& f) {
    Expansion<2 * N * M> h, next;
    for (std::size_t j = 0; j < f.n; ++j) {
        const Expansion<2 * N> part = scale(e, f.c[j]);
        // At most 2N components join per step, so the total stays within 2NM.
        next.n = sumInto(h.c, h.n, part.c, part.n, next.c);
        h.n = next.n;
        for (std::size_t i = 0; i < next.n; ++i) h.c[i] = next.c[i];
    }
    return h;
}

} // namespace fl::geom::detail
