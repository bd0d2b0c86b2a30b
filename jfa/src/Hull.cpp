// Andrew's monotone chain: sort, build the lower and the upper chain, join them.
#include <jfa/Hull.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace fl::jfa {
namespace {

constexpr std::int64_t kMaxIntCoordinate = std::int64_t(1) << 29;

void checkRange(IntPoint p) {
    if (p.x > kMaxIntCoordinate || p.x < -kMaxIntCoordinate || p.y > kMaxIntCoordinate ||
        p.y < -kMaxIntCoordinate)
        throw std::invalid_argument("convex hull: integer coordinate (" + std::to_string(p.x) +
                                    ", " + std::to_string(p.y) + ") beyond +-2^29");
}

void checkRange(RealPoint p) {
    const auto ok = [](double v) {
        const double a = std::fabs(v);
        return a == 0.0 || (a >= std::ldexp(1.0, -400) && a <= std::ldexp(1.0, 500));
    };
    if (!ok(p.x) || !ok(p.y))
        throw std::invalid_argument("convex hull: coordinate not finite or outside 2^-400..2^500");
}

int sign(std::int64_t v) {
    return (v > 0) - (v < 0);
}

int orient(IntPoint a, IntPoint b, IntPoint c) {
    // |differences| <= 2^30, products <= 2^60, their difference <= 2^61: no overflow.
    return sign((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

// Exact real orientation (Shewchuk-style expansion arithmetic, no FMA needed):
//   det = (bx - ax)(cy - ay) - (by - ay)(cx - ax)
//       = bx cy - bx ay - ax cy - by cx + by ax + ay cx      (the ax ay terms cancel),
// six products of the inputs themselves, so no rounded difference enters. Each product is split
// exactly into p + e (Dekker), the twelve terms are summed into a nonoverlapping expansion with
// Knuth's TwoSum, and the sign of its most significant nonzero component is the sign of det.
// Exact for finite coordinates whose products neither overflow nor underflow (|v| in
// [2^-400, 2^500] or 0), which covers every float.

// a + b = s + err exactly.
void twoSum(double a, double b, double& s, double& err) {
    s = a + b;
    const double bv = s - a;
    err = (a - (s - bv)) + (b - bv);
}

// a = hi + lo with each half holding at most 26 significant bits (Veltkamp).
void split(double a, double& hi, double& lo) {
    const double c = 134217729.0 * a; // 2^27 + 1
    hi = c - (c - a);
    lo = a - hi;
}

// a * b = p + err exactly.
void twoProduct(double a, double b, double& p, double& err) {
    p = a * b;
    double ah = 0.0, al = 0.0, bh = 0.0, bl = 0.0;
    split(a, ah, al);
    split(b, bh, bl);
    err = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
}

int orient(RealPoint a, RealPoint b, RealPoint c) {
    const double factors[6][2] = {{b.x, c.y},  {-b.x, a.y}, {-a.x, c.y},
                                  {-b.y, c.x}, {b.y, a.x},  {a.y, c.x}};
    std::vector<double> expansion; // nonoverlapping, increasing magnitude
    expansion.reserve(16);
    const auto grow = [&expansion](double term) {
        std::size_t out = 0;
        for (std::size_t i = 0; i < expansion.size(); ++i) {
            double sum = 0.0, err = 0.0;
            twoSum(term, expansion[i], sum, err);
            term = sum;
            if (err != 0.0) expansion[out++] = err;
        }
        expansion.resize(out);
        if (term != 0.0) expansion.push_back(term);
    };
    for (const auto& f : factors) {
        double p = 0.0, err = 0.0;
        twoProduct(f[0], f[1], p, err);
        grow(err);
        grow(p);
    }
    return expansion.empty() ? 0 : (expansion.back() > 0.0 ? 1 : -1);
}

template <class P>
bool lexLess(const P& a, const P& b) {
    return a.x < b.x || (a.x == b.x && a.y < b.y);
}

// Sorted distinct points.
template <class P>
std::vector<P> sortedUnique(std::span<const P> points) {
    for (const P& p : points) checkRange(p);
    std::vector<P> pts(points.begin(), points.end());
    std::sort(pts.begin(), pts.end(), lexLess<P>);
    pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
    return pts;
}

// True if all (sorted, distinct, n >= 3) points lie on one line.
template <class P>
bool collinear(const std::vector<P>& pts) {
    for (std::size_t i = 2; i < pts.size(); ++i)
        if (orient(pts[0], pts[1], pts[i]) != 0) return false;
    return true;
}

template <class P>
std::vector<P> hullOfSorted(std::vector<P> pts, HullBoundary keep) {
    const std::size_t n = pts.size();
    if (n <= 2) return pts;
    if (collinear(pts)) {
        if (keep == HullBoundary::KeepCollinear) return pts; // sorted along the line
        return {pts.front(), pts.back()};
    }

    // Pop while the last turn is clockwise (KeepCollinear) or not counter-clockwise (Vertices).
    // Kept collinear runs cannot double back: at the right end the upper chain starts down a
    // vertical run the lower chain already holds, but the first point left of that line is a
    // clockwise turn and pops the run again (likewise at the left end); only an all-collinear
    // input would never pop, and that was handled above.
    const auto mustPop = [keep](int turn) {
        return keep == HullBoundary::KeepCollinear ? turn < 0 : turn <= 0;
    };
    std::vector<P> h(2 * n);
    std::size_t k = 0;
    for (std::size_t i = 0; i < n; ++i) { // lower chain, left to right
        while (k >= 2 && mustPop(orient(h[k - 2], h[k - 1], pts[i]))) --k;
        h[k++] = pts[i];
    }
    for (std::size_t i = n - 1, lower = k + 1; i-- > 0;) { // upper chain, right to left
        while (k >= lower && mustPop(orient(h[k - 2], h[k - 1], pts[i]))) --k;
        h[k++] = pts[i];
    }
    h.resize(k - 1); // the last point repeats the first
    return h;
}

template <class P>
std::vector<P> hull(std::span<const P> points, HullBoundary keep) {
    return hullOfSorted(sortedUnique(points), keep);
}

template <class P>
std::int64_t triangles(std::span<const P> points) {
    std::vector<P> pts = sortedUnique(points);
    const auto m = static_cast<std::int64_t>(pts.size());
    if (m < 3 || collinear(pts)) return 0;
    const auto b =
        static_cast<std::int64_t>(hullOfSorted(std::move(pts), HullBoundary::KeepCollinear).size());
    return 2 * m - 2 - b; // Euler: V - E + F = 2 with 3T + b = 2E, F = T + 1
}

} // namespace

int orientation(IntPoint a, IntPoint b, IntPoint c) {
    checkRange(a);
    checkRange(b);
    checkRange(c);
    return orient(a, b, c);
}

int orientation(RealPoint a, RealPoint b, RealPoint c) {
    checkRange(a);
    checkRange(b);
    checkRange(c);
    return orient(a, b, c);
}

std::vector<IntPoint> convexHull(std::span<const IntPoint> points, HullBoundary keep) {
    return hull(points, keep);
}

std::vector<RealPoint> convexHull(std::span<const RealPoint> points, HullBoundary keep) {
    return hull(points, keep);
}

std::int64_t triangulationTriangleCount(std::span<const IntPoint> points) {
    return triangles(points);
}

std::int64_t triangulationTriangleCount(std::span<const RealPoint> points) {
    return triangles(points);
}

} // namespace fl::jfa
