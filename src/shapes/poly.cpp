#include "asos/shapes/poly.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "asos/diag/format_number.hpp"
#include "asos/geometry/margins.hpp"
#include "asos/shapes/box.hpp"
#include "asos/shapes/cone_geometry.hpp"
#include "asos/shapes/local_frame.hpp"

namespace asos {

using namespace conegeom;

namespace {

constexpr int kMaxOrder = PolyShape::kMaxOrder;
// The relative rounding allowed for a value computed from the terms (each
// bound is padded by it times the sum of the terms' sizes): far above the
// few dozen ulps a sum of products of up to 35 factors loses.
constexpr double kValueRounding = 1e-12;
// A root is refined to this share of the size of the coordinates around it.
constexpr double kRootTolerance = 1e-14;
// A leading coefficient of the ray's polynomial within this share of the
// size of its terms is zero to rounding.
constexpr double kLeadingRounding = 1e-13;
// The cone's depth pieces: at most this deep a halving, this many in all.
constexpr int kMaxSplitDepth = 24;
constexpr int kPieceBudget = 160;
// The boundedness proof: patches per edge of each face of the cube.
constexpr int kCubePatches = 12;
// Its box: the octree's depth (cells of 1/32 of the proven ball's size).
constexpr int kOctreeDepth = 5;

using Coefficients = std::array<double, kMaxOrder + 1>;

double horner(const double* c, int n, double x) {
    double v = c[n];
    for (int k = n - 1; k >= 0; --k) v = v * x + c[k];
    return v;
}

// A root in [lo, hi] of a function that changes sign over it (vd(x) gives its
// value and slope; negativeAtLo the sign at lo): Newton's steps, bisection
// where a step leaves the bracket, to the tolerance.
template <class ValueAndSlope>
double refineRoot(const ValueAndSlope& vd, double lo, double hi, bool negativeAtLo, double tol, double start) {
    double x = start > lo && start < hi ? start : 0.5 * (lo + hi);
    for (int i = 0; i < 300; ++i) {
        const auto [v, d] = vd(x);
        if (v == 0.0) return x;
        if ((v < 0.0) == negativeAtLo) lo = x;
        else hi = x;
        double next = x - v / d;
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (hi - lo <= tol || std::abs(next - x) <= tol || next == x) return next;
        x = next;
    }
    return x;
}

// The roots of a function in [lo, hi] given the points that split it where it
// is monotone (ascending): one per stretch whose ends differ in sign, and every
// end where it is exactly zero (a tangency found exactly). `value` is the
// function alone (for the stretches' ends); `guess(a, b, negativeAtA)` a
// first estimate of a stretch's root for Newton's steps to start from.
template <class Value, class ValueAndSlope, class Guess>
int rootsOnStretches(const Value& value, const ValueAndSlope& vd, const Guess& guess, const double* splits,
                     int splitCount, double lo, double hi, double tol, double* out) {
    int n = 0;
    double a = lo;
    double va = value(a);
    for (int i = 0; i <= splitCount; ++i) {
        const double b = i < splitCount ? std::clamp(splits[i], lo, hi) : hi;
        if (!(b > a) && i < splitCount) continue;
        const double vb = value(b);
        if (va == 0.0) {
            if (n == 0 || out[n - 1] != a) out[n++] = a;
        } else if (vb != 0.0 && (va < 0.0) != (vb < 0.0)) {
            out[n++] = refineRoot(vd, a, b, va < 0.0, tol, guess(a, b, va < 0.0));
        }
        a = b;
        va = vb;
    }
    if (va == 0.0 && (n == 0 || out[n - 1] != a)) out[n++] = a;
    return n;
}

// The real roots in [lo, hi] of the polynomial c[0] + c[1] x + ... + c[n] x^n
// (c[n] != 0), ascending: the roots of its derivative split it into monotone
// stretches (recursively), each holding at most one root.
int polynomialRoots(const double* c, int n, double lo, double hi, double tol, double* out) {
    if (n <= 0) return 0;
    if (n == 1) {
        const double r = -c[0] / c[1];
        if (r >= lo && r <= hi) {
            out[0] = r;
            return 1;
        }
        return 0;
    }
    Coefficients slope{};
    for (int k = 0; k < n; ++k) slope[k] = (k + 1) * c[k + 1];
    double splits[kMaxOrder];
    const int splitCount = polynomialRoots(slope.data(), n - 1, lo, hi, tol, splits);
    const auto value = [&](double x) { return horner(c, n, x); };
    const auto vd = [&](double x) { return std::pair{horner(c, n, x), horner(slope.data(), n - 1, x)}; };
    const auto middle = [](double a, double b, bool) { return 0.5 * (a + b); };
    return rootsOnStretches(value, vd, middle, splits, splitCount, lo, hi, tol, out);
}

// (a + b x)^m as coefficients, m = 0..order.
struct Powers {
    std::array<Coefficients, kMaxOrder + 1> p;
    void fill(double a, double b, int order) {
        p[0] = {};
        p[0][0] = 1.0;
        for (int m = 1; m <= order; ++m) {
            p[m] = {};
            for (int e = 0; e < m; ++e) {
                p[m][e] += a * p[m - 1][e];
                p[m][e + 1] += b * p[m - 1][e];
            }
        }
    }
};

using Bracket = std::pair<double, double>;

Bracket mul(Bracket a, Bracket b) {
    const double p0 = a.first * b.first, p1 = a.first * b.second, p2 = a.second * b.first, p3 = a.second * b.second;
    return {std::min(std::min(p0, p1), std::min(p2, p3)), std::max(std::max(p0, p1), std::max(p2, p3))};
}

// x^m over [lo, hi], tight.
Bracket power(Bracket x, int m) {
    if (m == 0) return {1.0, 1.0};
    const double a = std::pow(x.first, m), b = std::pow(x.second, m);
    if (m % 2 == 1) return {a, b};
    if (x.first >= 0.0) return {a, b};
    if (x.second <= 0.0) return {b, a};
    return {0.0, std::max(a, b)};
}

// The powers 0..order of each coordinate's interval over a box.
struct BoxPowers {
    std::array<std::array<Bracket, kMaxOrder + 1>, 3> p;
    std::array<std::array<double, kMaxOrder + 1>, 3> size;  // max |x|^m
    BoxPowers(const Vec3& lo, const Vec3& hi, int order) {
        for (int a = 0; a < 3; ++a) {
            const Bracket x{lo[a], hi[a]};
            const double big = std::max(std::abs(lo[a]), std::abs(hi[a]));
            double s = 1.0;
            for (int m = 0; m <= order; ++m) {
                p[a][m] = power(x, m);
                size[a][m] = s;
                s *= big;
            }
        }
    }
};

// Sums intervals, and the terms' sizes for the rounding pad.
struct IntervalSum {
    double lo = 0.0, hi = 0.0, magnitude = 0.0;
    void add(double c, Bracket x, double size) {
        const Bracket v = c >= 0.0 ? Bracket{c * x.first, c * x.second} : Bracket{c * x.second, c * x.first};
        lo += v.first;
        hi += v.second;
        magnitude += std::abs(c) * size;
    }
    std::pair<double, double> padded() const {
        const double pad = kValueRounding * magnitude;
        return {lo - pad, hi + pad};
    }
};

}  // namespace

Poly::Poly(int order, const std::vector<double>& coefficients)
    : order_(order), dense_(static_cast<std::size_t>((order + 1) * (order + 1) * (order + 1)), 0.0),
      degreeNorm_(order + 1, 0.0) {
    std::size_t n = 0;
    for (int i = order; i >= 0; --i)
        for (int j = order - i; j >= 0; --j)
            for (int k = order - i - j; k >= 0; --k, ++n) {
                const double c = n < coefficients.size() ? coefficients[n] : 0.0;
                if (c == 0.0) continue;
                terms_.push_back({c, i, j, k});
                dense_[static_cast<std::size_t>((i * (order + 1) + j) * (order + 1) + k)] = c;
                degreeNorm_[i + j + k] += std::abs(c);
                coefficientNorm_ += std::abs(c);
            }
    proveBounded();
}

double Poly::value(const Vec3& p) const {
    std::array<std::array<double, kMaxOrder + 1>, 3> pw;
    for (int a = 0; a < 3; ++a) {
        pw[a][0] = 1.0;
        for (int m = 1; m <= order_; ++m) pw[a][m] = pw[a][m - 1] * p[a];
    }
    double v = 0.0;
    for (const Term& t : terms_) v += t.c * pw[0][t.i] * pw[1][t.j] * pw[2][t.k];
    return v;
}

Vec3 Poly::gradient(const Vec3& p) const {
    std::array<std::array<double, kMaxOrder + 1>, 3> pw;
    for (int a = 0; a < 3; ++a) {
        pw[a][0] = 1.0;
        for (int m = 1; m <= order_; ++m) pw[a][m] = pw[a][m - 1] * p[a];
    }
    Vec3 g(0.0);
    for (const Term& t : terms_) {
        if (t.i > 0) g.x += t.c * t.i * pw[0][t.i - 1] * pw[1][t.j] * pw[2][t.k];
        if (t.j > 0) g.y += t.c * t.j * pw[0][t.i] * pw[1][t.j - 1] * pw[2][t.k];
        if (t.k > 0) g.z += t.c * t.k * pw[0][t.i] * pw[1][t.j] * pw[2][t.k - 1];
    }
    return g;
}

Poly::Interval Poly::topOver(const Vec3& lo, const Vec3& hi) const {
    const BoxPowers b(lo, hi, order_);
    IntervalSum s;
    for (const Term& t : terms_)
        if (t.i + t.j + t.k == order_)
            s.add(t.c, mul(mul(b.p[0][t.i], b.p[1][t.j]), b.p[2][t.k]), b.size[0][t.i] * b.size[1][t.j] * b.size[2][t.k]);
    const auto [l, h] = s.padded();
    return {l, h};
}

// f = F_N + ... + F_0 (its parts of each degree). Over a patch of directions
// where the top part F_N has one strict sign, |F_N(u)| >= m on unit u, and
// |F_k(u)| <= M_k (the sum of |c| over degree k, as |u_i| <= 1): at |p| = s,
// |F_N(p)| = s^N |F_N(u)| exceeds the rest once s > 2 max_k (M_k / m)^(1/(N-k))
// (Fujiwara's bound). The patches tile the cube's faces; a unit u = p / |p|
// with p on a patch has |F_N(u)| >= min |F_N(p)| / max |p|^N.
void Poly::proveBounded() {
    if (degreeNorm_[order_] == 0.0) return;
    double radius = 0.0;
    int sign = 0;
    for (int axis = 0; axis < 3; ++axis)
        for (const double side : {-1.0, 1.0})
            for (int a = 0; a < kCubePatches; ++a)
                for (int b = 0; b < kCubePatches; ++b) {
                    Vec3 lo, hi;
                    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
                    lo[axis] = hi[axis] = side;
                    lo[u] = -1.0 + 2.0 * a / kCubePatches;
                    hi[u] = -1.0 + 2.0 * (a + 1) / kCubePatches;
                    lo[v] = -1.0 + 2.0 * b / kCubePatches;
                    hi[v] = -1.0 + 2.0 * (b + 1) / kCubePatches;
                    const Interval top = topOver(lo, hi);
                    const int s = top.lo > 0.0 ? 1 : top.hi < 0.0 ? -1 : 0;
                    if (s == 0 || (sign != 0 && s != sign)) return;
                    sign = s;
                    double far2 = 0.0;
                    for (int c = 0; c < 3; ++c) far2 += std::max(lo[c] * lo[c], hi[c] * hi[c]);
                    const double m = std::min(std::abs(top.lo), std::abs(top.hi)) /
                                     std::pow(std::sqrt(far2), order_) * (1.0 - kValueRounding);
                    for (int k = 0; k < order_; ++k)
                        if (degreeNorm_[k] > 0.0)
                            radius = std::max(radius, 2.0 * std::pow(degreeNorm_[k] / m, 1.0 / (order_ - k)));
                }
    bounded_ = true;
    farSign_ = sign;
    radius = padUp(radius) * (1.0 + 1e-9) + kPositiveFloor;
    // The surface lies in the cells of an octree over the cube of half-side
    // R where f's sign is not known (a cell of one strict sign holds none of
    // it): their box bounds it, far tighter than the ball.
    Vec3 lo(kInfinity), hi(-kInfinity);
    std::vector<double> room;
    struct Cell {
        Vec3 centre;
        double half;
        int depth;
    };
    std::vector<Cell> cells{{Vec3(0.0), radius, 0}};
    while (!cells.empty()) {
        const Cell c = cells.back();
        cells.pop_back();
        const Local l = about(c.centre, padUp(c.half * std::sqrt(3.0)), room);
        if (l.value > l.spread || l.value < -l.spread) continue;
        if (c.depth == kOctreeDepth) {
            lo = glm::min(lo, c.centre - Vec3(c.half));
            hi = glm::max(hi, c.centre + Vec3(c.half));
            continue;
        }
        const double h = 0.5 * c.half;
        for (int n = 0; n < 8; ++n)
            cells.push_back({c.centre + Vec3(n & 1 ? h : -h, n & 2 ? h : -h, n & 4 ? h : -h), h, c.depth + 1});
    }
    if (!(lo.x <= hi.x)) lo = hi = Vec3(0.0);  // no surface at all
    const Vec3 pad = Vec3(1e-9 * radius);
    box_ = {lo - pad, hi + pad};
    centre_ = 0.5 * (box_.lo + box_.hi);
    radius_ = padUp(0.5 * glm::length(box_.hi - box_.lo)) + kPositiveFloor;
}

Bounds3 Poly::worldBounds(const Mat3& m, const Vec3& offset) const {
    if (!bounded_) return {Vec3(-kInfinity), Vec3(kInfinity)};
    return Box(box_.lo, box_.hi).worldBounds(m, offset);
}

double Poly::support(const Vec3& dir) const {
    return bounded_ ? glm::dot(dir, centre_) + radius_ * glm::length(dir) : kInfinity;
}

bool Poly::raysLeave(const LocalRays& rays) const {
    const Vec3 out = rays.origin - centre_;
    return bounded_ && glm::dot(out, out) >= radius_ * radius_ && rays.awayFrom(out);
}

PolyRoots Poly::roots(const Ray& ray) const {
    PolyRoots out;
    const double dLength = glm::length(ray.dir);
    if (!(dLength > 0.0) || !std::isfinite(dLength)) return out;
    const Vec3 e = ray.dir / dLength;
    // The line as q + u e, u a local distance: q on the bounding ball's chord
    // (or, unbounded, the line's point nearest the origin), so that the
    // coefficients are of the size of the shape however far the ray starts.
    double t0 = -glm::dot(ray.origin - centre_, e) / dLength;
    double uLo = -kInfinity, uHi = kInfinity;
    if (bounded_) {
        const Vec3 mid = ray.origin + t0 * ray.dir - centre_;
        const double h2 = radius_ * radius_ - glm::dot(mid, mid);
        if (h2 < 0.0) return out;
        const double h = std::sqrt(h2) * (1.0 + 1e-9) + 1e-9 * radius_;
        uLo = -h;
        uHi = h;
    }
    const Vec3 q = ray.origin + t0 * ray.dir;
    // f(q + u e) = sum c_m u^m, and the sizes of the terms behind each c_m.
    Powers px, py, pz, ax, ay, az;
    px.fill(q.x, e.x, order_);
    py.fill(q.y, e.y, order_);
    pz.fill(q.z, e.z, order_);
    ax.fill(std::abs(q.x), std::abs(e.x), order_);
    ay.fill(std::abs(q.y), std::abs(e.y), order_);
    az.fill(std::abs(q.z), std::abs(e.z), order_);
    Coefficients c{}, size{};
    Coefficients xy{}, xyAbs{};
    for (const Term& t : terms_) {
        xy = {};
        xyAbs = {};
        for (int a = 0; a <= t.i; ++a)
            for (int b = 0; b <= t.j; ++b) {
                xy[a + b] += px.p[t.i][a] * py.p[t.j][b];
                xyAbs[a + b] += ax.p[t.i][a] * ay.p[t.j][b];
            }
        const double ac = std::abs(t.c);
        for (int a = 0; a <= t.i + t.j; ++a)
            for (int b = 0; b <= t.k; ++b) {
                c[a + b] += t.c * xy[a] * pz.p[t.k][b];
                size[a + b] += ac * xyAbs[a] * az.p[t.k][b];
            }
    }
    int n = order_;
    while (n > 0 && std::abs(c[n]) <= kLeadingRounding * size[n]) --n;
    if (n == 0) return out;
    if (!bounded_) {
        // Every root lies within Fujiwara's bound 2 max_k |c_(n-k) / c_n|^(1/k).
        double bound = 0.0;
        for (int k = 1; k <= n; ++k)
            if (c[n - k] != 0.0) bound = std::max(bound, std::pow(std::abs(c[n - k] / c[n]), 1.0 / k));
        bound = 2.0 * bound * (1.0 + 1e-9) + kPositiveFloor;
        uLo = -bound;
        uHi = bound;
    }
    const double tol = kRootTolerance * (glm::length(q) + (bounded_ ? radius_ : 1.0));
    double splits[kMaxOrder];
    int splitCount = 0;
    if (n >= 2) {
        Coefficients slope{};
        for (int k = 0; k < n; ++k) slope[k] = (k + 1) * c[k + 1];
        splitCount = polynomialRoots(slope.data(), n - 1, uLo, uHi, tol, splits);
    }
    // The roots are f's own along the line, which rounds far better near the
    // surface than the expanded polynomial; its slope is the gradient's along e.
    const auto valueAt = [&](double u) { return value(q + u * e); };
    const auto vd = [&](double u) {
        const Vec3 p = q + u * e;
        return std::pair{value(p), glm::dot(gradient(p), e)};
    };
    // Newton's steps on f start where the line's own polynomial (cheap, by
    // Horner) has its root in the stretch: a step or two of f's then polish it.
    Coefficients slope1{};
    for (int k = 0; k < n; ++k) slope1[k] = (k + 1) * c[k + 1];
    const auto guess = [&](double a, double b, bool negativeAtA) {
        const double ha = horner(c.data(), n, a), hb = horner(c.data(), n, b);
        if (ha == 0.0 || hb == 0.0 || (ha < 0.0) == (hb < 0.0) || (ha < 0.0) != negativeAtA) return 0.5 * (a + b);
        const auto line = [&](double u) { return std::pair{horner(c.data(), n, u), horner(slope1.data(), n - 1, u)}; };
        return refineRoot(line, a, b, ha < 0.0, 1e3 * tol, 0.5 * (a + b));
    };
    double found[kMaxOrder];
    const int count = rootsOnStretches(valueAt, vd, guess, splits, splitCount, uLo, uHi, tol, found);
    for (int i = 0; i < count && out.count < kMaxOrder; ++i) out.t[out.count++] = t0 + found[i] / dLength;
    return out;
}

std::optional<LocalHit> Poly::intersect(const Ray& ray, double tMin, double tMax) const {
    const PolyRoots all = roots(ray);
    for (int i = 0; i < all.count; ++i) {
        const double t = all.t[i];
        if (!(t >= tMin && t <= tMax)) continue;
        const Vec3 p = ray.at(t);
        const Vec3 n = gradient(p);
        // POV-Ray's normal where the gradient vanishes: +x.
        return LocalHit{t, p, n == Vec3(0.0) ? Vec3(1.0, 0.0, 0.0) : n};
    }
    return std::nullopt;
}

// f(centre + u) = sum b_a u^a (a Taylor shift of the dense coefficients, one
// axis at a time: repeated synthetic division); over |u| <= r each u^a is at
// most r^|a| in size.
Poly::Local Poly::about(const Vec3& centre, double r, std::vector<double>& b) const {
    const int n1 = order_ + 1;
    b = dense_;
    const auto at = [&](int i, int j, int k) -> double& { return b[static_cast<std::size_t>((i * n1 + j) * n1 + k)]; };
    for (int axis = 0; axis < 3; ++axis) {
        const double c = centre[axis];
        if (c == 0.0) continue;
        for (int p = 0; p <= order_; ++p)
            for (int q = 0; p + q <= order_; ++q) {
                const int d = order_ - p - q;
                // The line of coefficients along `axis`, the other two powers p, q.
                const auto coef = [&](int e) -> double& {
                    return axis == 0 ? at(e, p, q) : axis == 1 ? at(p, e, q) : at(p, q, e);
                };
                for (int s = 0; s < d; ++s)
                    for (int e = d - 1; e >= s; --e) coef(e) += c * coef(e + 1);
            }
    }
    std::array<double, PolyShape::kMaxOrder + 1> rp;
    rp[0] = 1.0;
    for (int m = 1; m <= order_; ++m) rp[m] = rp[m - 1] * r;
    Local out;
    out.value = at(0, 0, 0);
    out.grad = Vec3(at(1, 0, 0), at(0, 1, 0), at(0, 0, 1));
    double spread = 0.0;
    Vec3 stray(0.0);
    for (int i = 0; i <= order_; ++i)
        for (int j = 0; i + j <= order_; ++j)
            for (int k = 0; i + j + k <= order_; ++k) {
                const int deg = i + j + k;
                if (deg == 0) continue;
                const double a = std::abs(at(i, j, k));
                if (a == 0.0) continue;
                spread += a * rp[deg];
                if (deg >= 2) stray += Vec3(i, j, k) * (a * rp[deg - 1]);
            }
    // The rounding of the shift: far below kValueRounding of the sizes of the
    // terms over the ball, sum |c| rho^deg with rho = |centre|_inf + r.
    const double rho = std::max({std::abs(centre.x), std::abs(centre.y), std::abs(centre.z)}) + r;
    double size = 0.0, slopeSize = 0.0, power = 1.0;
    for (int m = 0; m <= order_; ++m) {
        size += degreeNorm_[static_cast<std::size_t>(m)] * power;
        if (m < order_) slopeSize += (m + 1) * degreeNorm_[static_cast<std::size_t>(m + 1)] * power;
        power *= rho;
    }
    out.spread = spread + kValueRounding * size;
    out.stray = stray;
    out.slopePad = kValueRounding * slopeSize;
    return out;
}

ConeClass Poly::classify(const LocalCone& cone) const {
    if (cone.rangeEmpty()) return missClass();
    if (!(cone.cosHalf > 0.0)) return marginalClass(cone, cone.tMin, cone.tMax);
    const double reach = glm::length(cone.apex - centre_);
    double lo = std::max(0.0, cone.tMinOuter);
    double end = cone.tMaxOuter;
    // Past `end` f keeps the sign farSign for every ray (0: not known).
    int farSign = 0;
    if (bounded_) {
        if (ballOutsideAngular(cone, centre_, radius_)) return missClass();
        lo = std::max(lo, padDown(reach - radius_) - cone.absTol);
        const double far = padUp(reach + radius_) + cone.absTol;
        if (far < end) {
            end = far;
            farSign = farSign_;
        } else {
            farSign = 2;  // the range itself ends: nothing past it to know
        }
        if (!(lo <= end)) return missClass();
    } else if (!std::isfinite(end)) {
        // The directions of the points apex + t d, t >= T0, lie within
        // theta + asin(|apex| / T0) of the axis; where the top part keeps one
        // sign there, f keeps it past T = max(T0, |apex| + R) (proveBounded's
        // bound over those directions).
        const double t0 = 32.0 * (reach + 1.0);
        const double spread = std::acos(std::clamp(cone.cosHalf, -1.0, 1.0)) + std::asin(reach / t0) + 1e-9;
        end = 2.0 * lo + 4.0 * (reach + 1.0);
        if (spread < 1.0 && degreeNorm_[order_] > 0.0) {
            const double chord = padUp(2.0 * std::sin(0.5 * spread));
            const Vec3 lo3 = glm::max(cone.axis - Vec3(chord), Vec3(-1.0));
            const Vec3 hi3 = glm::min(cone.axis + Vec3(chord), Vec3(1.0));
            const Interval top = topOver(lo3, hi3);
            const int s = top.lo > 0.0 ? 1 : top.hi < 0.0 ? -1 : 0;
            if (s != 0) {
                const double m = std::min(std::abs(top.lo), std::abs(top.hi)) * (1.0 - kValueRounding);
                double radius = 0.0;
                for (int k = 0; k < order_; ++k)
                    if (degreeNorm_[k] > 0.0)
                        radius = std::max(radius, 2.0 * std::pow(degreeNorm_[k] / m, 1.0 / (order_ - k)));
                end = std::max(lo, std::max(t0, padUp(reach + radius) * (1.0 + 1e-9)));
                farSign = s;
            }
        }
    } else {
        farSign = 2;  // the range itself ends: nothing past it to know
    }

    // The rays' unit directions lie within `chord` of the axis.
    const double chord = padUp(std::sqrt(2.0 * (1.0 - cone.cosHalf)));
    std::vector<double> shifted;  // about()'s room

    // Pieces of [lo, end] nearest first, halved where f's sign over a piece is
    // not known (and f is not monotone along the rays there). A piece [ta, tb]
    // of every ray lies in the ball about the axis point at
    // m = cosHalf (ta + tb) / 2 of radius its ends' farthest rim point.
    struct Span {
        double ta, tb;
        int depth;
    };
    std::array<Span, kMaxSplitDepth + 2> stack{};
    int top = 0;
    stack[top++] = {lo, end, 0};
    int first = 0;               // the sign of the first piece
    double tNear = kInfinity;    // the start of the first piece not of that sign
    int budget = kPieceBudget;
    while (top > 0) {
        const Span s = stack[--top];
        if (--budget < 0) return marginalClass(cone, std::min(tNear, s.ta), cone.tMax);
        const double m = 0.5 * (s.ta + s.tb) * cone.cosHalf;
        auto rim = [&](double t) { return t * t + m * m - 2.0 * t * m * cone.cosHalf; };
        const double radius = std::sqrt(std::max(0.0, std::max(rim(s.ta), rim(s.tb)))) * (1.0 + 1e-12) + cone.absTol;
        const Vec3 centre = cone.apex + m * cone.axis;
        const Local local = about(centre, radius, shifted);
        int sign = local.value > local.spread ? 1 : local.value < -local.spread ? -1 : 0;
        // The slope along a ray, grad f . d: within |grad f(centre)| chord of
        // grad f(centre) . axis, and grad f strays from grad f(centre) by at
        // most |stray| over the ball.
        const double along = glm::dot(local.grad, cone.axis);
        const double slopeSpread = glm::length(local.grad) * chord + glm::length(local.stray) + local.slopePad;
        const int slopeSign = along > slopeSpread ? 1 : along < -slopeSpread ? -1 : 0;
        // The first piece, its sign not known but f monotone along the rays
        // (the apex on the surface, or near it): f's sign where the rays
        // start. The same as the slope's, f keeps it over the piece; the
        // opposite, each ray crosses once in it.
        if (first == 0 && sign == 0 && slopeSign != 0) {
            const double m0 = s.ta * cone.cosHalf;
            const double r0 = std::sqrt(std::max(0.0, s.ta * s.ta + m0 * m0 - 2.0 * s.ta * m0 * cone.cosHalf)) *
                                  (1.0 + 1e-12) + cone.absTol;
            const Local start = about(cone.apex + m0 * cone.axis, r0, shifted);
            const int startSign = start.value > start.spread ? 1 : start.value < -start.spread ? -1 : 0;
            if (startSign == slopeSign) sign = slopeSign;
            else if (startSign == -slopeSign) first = startSign;
        }

        const bool monotone = first != 0 && slopeSign == -first;
        // A piece no longer than the cone is wide there gains little from
        // halving (its ball is the cross-section's); a monotone one is halved
        // while it is long beside that width, for tighter depths.
        const double width = s.tb * chord + cone.absTol;
        const bool worthHalving = s.tb - s.ta > (monotone ? 4.0 : 0.5) * width;
        if (sign == 0 && worthHalving && s.depth < kMaxSplitDepth) {
            const double mid = 0.5 * (s.ta + s.tb);
            stack[top++] = {mid, s.tb, s.depth + 1};
            stack[top++] = {s.ta, mid, s.depth + 1};
            continue;
        }
        if (first == 0 && sign == 0) return marginalClass(cone, lo, cone.tMax);
        if (first == 0) {
            first = sign;
            continue;
        }
        // Once Full is out of reach, nothing more is worth a piece: Marginal
        // from the first piece of unknown sign to where the range is closed.
        const double closedEnd = farSign != 0 ? end : cone.tMax;
        if (sign == first) {
            // Back to the first sign after pieces of unknown sign: a ray may
            // have crossed twice there, or not at all.
            if (tNear < kInfinity) return marginalClass(cone, tNear, closedEnd);
            continue;
        }
        if (sign == 0) {
            tNear = std::min(tNear, s.ta);
            if (!monotone) return marginalClass(cone, tNear, closedEnd);
            continue;
        }
        // The opposite sign: every ray has crossed before this piece; where
        // f is monotone along each ray over the pieces between, each crosses
        // once there, so its first hit moves smoothly over the cone.
        const double tFar = s.ta;
        if (tNear == kInfinity) tNear = s.ta;  // a crossing at a piece's end
        if (cone.surelyWithin(tNear, tFar)) return fullClass(tNear, padUp(tFar));
        return marginalClass(cone, tNear, tFar);
    }
    // No piece of the opposite sign.
    const bool rangeEnds = farSign == 2;
    if (tNear == kInfinity) {
        if (rangeEnds || farSign == first) return missClass();
        return marginalClass(cone, end, cone.tMax);
    }
    return marginalClass(cone, tNear, rangeEnds || farSign == first ? end : cone.tMax);
}

std::vector<ShapeIssue> validate(const PolyShape& record) {
    IssueList issues;
    if (record.order < 2 || record.order > PolyShape::kMaxOrder) {
        issues.add(0, "the order of a poly must be 2 to " + std::to_string(PolyShape::kMaxOrder) + ", not " +
                          std::to_string(record.order));
        return issues.take();
    }
    const int count = PolyShape::termCount(record.order);
    if (static_cast<int>(record.coefficients.size()) != count) {
        const std::string keyword = record.keyword ? record.keyword : "poly";
        issues.add(1, "a " + keyword + (keyword == "poly" ? " of order " + std::to_string(record.order) : "") +
                          " takes " + std::to_string(count) + " coefficients, not " +
                          std::to_string(record.coefficients.size()));
        return issues.take();
    }
    bool finite = true;
    for (std::size_t n = 0; n < record.coefficients.size(); ++n)
        if (!std::isfinite(record.coefficients[n])) {
            issues.add(1, "coefficient " + std::to_string(n + 1) + " of the " + (record.keyword ? record.keyword : "poly") +
                              " must be finite, not " + formatNumber(record.coefficients[n]),
                       static_cast<int>(n));
            finite = false;
            break;
        }
    // The last coefficient is the constant term.
    if (finite && std::all_of(record.coefficients.begin(), record.coefficients.end() - 1,
                              [](double c) { return c == 0.0; }))
        issues.add(1, std::string("a ") + (record.keyword ? record.keyword : "poly") +
                          " without a term in x, y or z has no surface");
    return issues.take();
}

Placed<Poly> place(const PolyShape& record, const Transform& worldFromObject) {
    return {Poly(record.order, record.coefficients), LocalFrame::make(worldFromObject, Mat3(1.0), Vec3(0.0)),
            record.keyword ? record.keyword : Poly::kName};
}

}  // namespace asos
