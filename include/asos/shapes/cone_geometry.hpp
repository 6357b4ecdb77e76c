#pragma once
// Conservative building blocks of cone classification, shared by the
// primitives (paper: "Detection Phase"). Every function takes the cone in the
// primitive's local frame. A test named "...Outside" answers true only when
// sure; a test named "...Meets" may answer true when unsure. Angles are never
// computed: each test compares sines and cosines, and the cone membership of a
// point w (relative to the apex) is written s*sigma >= c*|perp| with
// sigma = w.axis and perp = w - sigma*axis, which stays exact for tiny cones
// where cos(halfAngle) rounds to 1.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>

#include "asos/geometry/margins.hpp"
#include "asos/geometry/vec.hpp"
#include "asos/shapes/local_cone.hpp"

namespace asos::conegeom {

// sqrt(x^2 + y^2) without std::hypot's (slow) overflow guard: the
// coordinates here are far from overflow.
inline double length2d(double x, double y) { return std::sqrt(x * x + y * y); }

inline ConeClass missClass() { return {}; }
inline ConeClass fullClass(double tNear, double tFar) {
    return {Coverage::Full, tNear, tFar, false};
}
// Marginal, with the depth bounds clipped to the cone's range.
inline ConeClass marginalClass(const LocalCone& cone, double tNear, double tFar,
                               bool singleEdge = false) {
    return {Coverage::Marginal, std::max(cone.tMin, tNear), std::min(cone.tMax, tFar), singleEdge};
}

// A fast path's way back for a local cone whose range is set (a shape's
// classify): the answer as it stands, and the cone's range tests and
// answers. RigidBounds is the other (classifyRanging), the same tests and
// answers in world units for a cone whose range is not set.
struct LocalFinish {
    const LocalCone& cone;
    ConeClass operator()(const ConeClass& out) const { return out; }
    bool surelyAfter(double tNearBound) const { return cone.surelyAfter(tNearBound); }
    bool surelyBefore(double tFarBound) const { return cone.surelyBefore(tFarBound); }
    bool surelyWithin(double lo, double hi) const { return cone.surelyWithin(lo, hi); }
    bool startsWithin(double lo) const { return lo >= cone.tMinInner; }
    ConeClass full(double tNear, double tFar) const { return fullClass(tNear, tFar); }
    ConeClass marginal(double tNear, double tFar, bool singleEdge = false) const {
        return marginalClass(cone, tNear, tFar, singleEdge);
    }
};

// The answer for a footprint known to miss the object, to lie wholly on it
// (full), or neither (Marginal), with every ray's hit depth in [tNear, tFar]:
// the range then turns a Full into a Marginal or anything into a Miss. The
// same answers as missClass / range.full / range.marginal, without a branch.
// `range` is LocalFinish or RigidBounds.
template <class Range>
ConeClass rangedClass(const Range& range, bool miss, bool full, double tNear, double tFar) {
    miss = miss | range.surelyAfter(tNear) | range.surelyBefore(tFar);
    full = full & range.surelyWithin(tNear, tFar);
    // A Full's bounds are inside the range already: the Marginal's clipped
    // bounds serve both.
    const ConeClass bounds = range.marginal(tNear, tFar);
    ConeClass out;
    // Miss 0, Full 1, Marginal 2: the coverage computed from the two flags.
    static_assert(static_cast<int>(Coverage::Miss) == 0 && static_cast<int>(Coverage::Full) == 1 &&
                  static_cast<int>(Coverage::Marginal) == 2);
    out.coverage = static_cast<Coverage>(static_cast<int>(!miss) * (2 - static_cast<int>(full)));
    out.tNear = selectDouble(miss, kInfinity, bounds.tNear);
    out.tFar = selectDouble(miss, -kInfinity, bounds.tFar);
    return out;
}
inline ConeClass rangedClass(const LocalCone& cone, bool miss, bool full, double tNear,
                             double tFar) {
    return rangedClass(LocalFinish{cone}, miss, full, tNear, tFar);
}

// angle(n, axis) <= halfAngle, from k = n.axis and g = |n x axis|.
inline bool angleWithin(double k, double g, double c, double s) {
    if (k >= 0.0) return c < 0.0 || g <= s;
    return c < 0.0 && g >= s;
}

// The range [lo, hi] of n.d over the unit directions d of the cone; n unit.
struct DotRange {
    double lo;
    double hi;
};

inline DotRange dotRange(const LocalCone& cone, double k, double g) {
    const double c = cone.cosHalf, s = cone.sinHalf;
    const double hi = angleWithin(k, g, c, s) ? 1.0 : k * c + g * s;
    const double lo = angleWithin(-k, g, c, s) ? -1.0 : k * c - g * s;
    return {lo, hi};
}

inline DotRange dotRange(const LocalCone& cone, const Vec3& n) {
    return dotRange(cone, glm::dot(n, cone.axis), glm::length(glm::cross(n, cone.axis)));
}

// The rays of a cone against the plane at signed distance h (h != 0) along
// the unit normal n from the apex, given the DotRange of n: a ray crosses at
// t = h / (n.d) when that is positive.
struct PlaneCrossing {
    bool any = false;  // some ray crosses
    bool all = false;  // every ray crosses
    double tNear = kInfinity;
    double tFar = -kInfinity;  // infinite when not every ray crosses
};

inline PlaneCrossing planeCrossing(DotRange range, double h) {
    double lo = range.lo, hi = range.hi;
    if (h < 0.0) {
        h = -h;
        const double oldLo = lo;
        lo = -hi;
        hi = -oldLo;
    }
    PlaneCrossing out;
    if (!(hi > 0.0)) return out;
    out.any = true;
    out.all = lo > 0.0;
    out.tNear = h / hi;
    out.tFar = out.all ? h / lo : kInfinity;
    return out;
}

// A point w relative to the apex, split along the axis, with the cone's
// membership polynomial q = s^2 sigma^2 - c^2 |perp|^2.
struct ConePoint {
    Vec3 w;
    double sigma;
    Vec3 perp;
    double r2;  // |w|^2
    double q;
    bool inside;
};

inline ConePoint conePoint(const LocalCone& cone, const Vec3& w) {
    const double c = cone.cosHalf, s = cone.sinHalf;
    ConePoint p;
    p.w = w;
    p.sigma = glm::dot(w, cone.axis);
    p.perp = w - p.sigma * cone.axis;
    const double perp2 = glm::dot(p.perp, p.perp);
    p.r2 = perp2 + p.sigma * p.sigma;
    p.q = s * s * p.sigma * p.sigma - c * c * perp2;
    p.inside = c >= 0.0 ? (p.sigma >= 0.0 && p.q >= 0.0) : (p.sigma >= 0.0 || p.q <= 0.0);
    return p;
}

// The distance from a point to the cone (0 inside).
inline double coneDistance(const LocalCone& cone, const ConePoint& p) {
    if (p.inside) return 0.0;
    const double c = cone.cosHalf, s = cone.sinHalf;
    const double dp = glm::length(p.perp);
    if (p.sigma * c + dp * s < 0.0) return std::sqrt(p.r2);  // nearest is the apex
    return std::max(0.0, dp * c - p.sigma * s);
}

// Whether the segment between two cone points meets the cone grown by the
// distance tolerance absTol (rounding of positions of the size of the scene).
// q is a quadratic along the segment, largest at its vertex (or at an end).
// The vertex is located from the coefficients, but membership is then
// decided afresh from the point itself: near its maximum q is tiny next to
// its values at the ends (a thin cone, an edge close to the apex), where the
// expanded polynomial would only return rounding noise.
inline bool segmentMeetsCone(const LocalCone& cone, const ConePoint& a, const ConePoint& b) {
    if (a.inside || b.inside) return true;
    const double c = cone.cosHalf, s = cone.sinHalf;
    const double tol = cone.absTol;
    if (c < 0.0) {
        // Wider than a hemisphere: the complement is convex, so the segment
        // stays out only if both ends are (by more than the tolerance).
        return coneDistance(cone, a) <= tol || coneDistance(cone, b) <= tol;
    }
    if (a.sigma < 0.0 && b.sigma < 0.0) {
        // Both behind the apex: only a segment passing the apex comes near.
        const Vec3 e = b.w - a.w;
        if (!(glm::dot(e, e) > 0.0)) return a.r2 <= tol * tol;
        const double tc = std::clamp(-glm::dot(a.w, e) / glm::dot(e, e), 0.0, 1.0);
        const Vec3 nearest = a.w + tc * e;
        return glm::dot(nearest, nearest) <= tol * tol;
    }
    const Vec3 e = b.w - a.w;
    const double se = b.sigma - a.sigma;
    // The part of the segment in front of the apex (sigma >= 0).
    double t0 = 0.0, t1 = 1.0;
    if (a.sigma < 0.0) t0 = -a.sigma / se;
    else if (b.sigma < 0.0) t1 = -a.sigma / se;
    const Vec3 pe = b.perp - a.perp;
    const double s2 = s * s, c2 = c * c;
    // q(t) = A t^2 + 2 B t + C.
    const double qa = s2 * se * se - c2 * glm::dot(pe, pe);
    const double qb = s2 * a.sigma * se - c2 * glm::dot(a.perp, pe);
    const double qc = a.q;
    auto q = [&](double t) { return (qa * t + 2.0 * qb) * t + qc; };
    double best = q(t0) >= q(t1) ? t0 : t1;
    if (qa < 0.0) {
        const double tv = -qb / qa;
        if (tv > t0 && tv < t1) best = tv;
    }
    // Far from the cone, q is well below zero: |q| >= dist * (c |perp| + s sigma)
    // and c |perp| + s sigma <= sqrt(2) |w|.
    const double qBest = q(best);
    const double w2 = std::max(a.r2, b.r2);
    if (qBest < 0.0 && qBest * qBest > 2.0 * w2 * tol * tol) return false;
    const ConePoint m = conePoint(cone, best < 0.5 ? a.w + best * e : b.w - (1.0 - best) * e);
    return coneDistance(cone, m) <= tol;
}

// The least k = cos^2(theta) - sin^2(gamma) (gamma the axis' angle from a
// plane's normal) at which the footprints and the fast paths take every ray
// of a cone as crossing the plane: below it the footprint is too elongated
// (its semi-major axis grows as 1 / k) and the cone goes to the exact tests.
// A modelling choice; FootprintQuadric's rounding bound follows from it.
inline constexpr double kFootprintMinK = 1e-6;

// The quick footprint bound on the plane z = zc (the circle tests of
// cylinder and cone): when the cone is narrower than a hemisphere, its axis
// heads for the plane and no ray of the cone is nearly parallel to it (k =
// c^2 - sin^2(gamma) > kFootprintMinK, gamma the axis' angle from the
// normal), every ray crosses the plane (planeDepths gives the depths), and
// the footprint (an ellipse of semi-major depth s c / k about a centre depth
// g s^2 / (an k) from q) lies within `radius` of the axis' crossing q.
struct FootprintReach {
    bool valid = false;
    Vec2 q{0.0};
    double radius = 0.0;
};

inline FootprintReach footprintReach(const LocalCone& cone, double zc) {
    FootprintReach f;
    const Vec3& p = cone.apex;
    const Vec3& axis = cone.axis;
    const double c = cone.cosHalf, s = cone.sinHalf;
    const double h = zc - p.z;
    if (!(c > 0.0 && h * axis.z > 0.0)) return f;
    const double an = std::abs(axis.z);
    const double g2 = axis.x * axis.x + axis.y * axis.y;
    const double k = c * c - g2;
    if (!(k > kFootprintMinK)) return f;
    f.valid = true;
    // sin(gamma) = sqrt(g2) <= (1 + g2) / 2: the radius needs no root (it
    // grows by a fraction of order sin^2(theta)); the depths do.
    const double gBound = 0.5 * (1.0 + g2);
    const double depth = std::abs(h);
    const double invAn = 1.0 / an;
    const double tAxis = depth * invAn;
    f.q = Vec2(p.x + tAxis * axis.x, p.y + tAxis * axis.y);
    f.radius = padUp(depth * s / k * (c + gBound * s * invAn)) + cone.absTol;
    return f;
}

// The same reach without its divisions, scaled by an k (an = |axis.z|) as
// the fast paths' crossing an k q is (Disc, EllipticDisc, Polygon), padded
// by absTol: every point of the footprint lies within it of an k q.
inline double scaledReach(double depth, double an, double g2, double c, double s, double absTol,
                          double ank) {
    return padUp(depth * s * (c * an + 0.5 * (1.0 + g2) * s)) + absTol * ank;
}

// What the fast paths on the plane z = 0 (Disc, EllipticDisc, Polygon)
// start from: the apex's
// height h under the plane, the axis' g2 = sin^2(gamma) and k = c^2 - g2,
// and whether every ray crosses the plane well conditioned (footprintReach's
// test); then an = |axis.z|, depth = |h| and an k.
struct ZPlaneApproach {
    bool crosses;
    double h, g2, k, an, depth, ank;
};
inline ZPlaneApproach zPlaneApproach(const LocalCone& cone) {
    const Vec3& axis = cone.axis;
    const double c = cone.cosHalf;
    ZPlaneApproach z;
    z.h = -cone.apex.z;
    z.g2 = axis.x * axis.x + axis.y * axis.y;
    z.k = c * c - z.g2;
    z.crosses = (c > 0.0) & (z.h * axis.z > 0.0) & (z.k > kFootprintMinK);
    z.an = std::abs(axis.z);
    z.depth = std::abs(z.h);
    z.ank = z.an * z.k;
    return z;
}

// The depths [tNear, tFar] at which the rays cross the plane, for a valid
// FootprintReach (apart, since the quick misses do not need the root).
struct CrossingDepths {
    double tNear;
    double tFar;
};

// With depth h, an = cos(gamma) > 0 and g2 = sin^2(gamma) of a plane that
// every ray crosses (c > 0): h / hi and h / lo, lo and hi the least and
// greatest cosine of a ray with the normal (hi = 1 when the normal is in the
// cone). One division by lo hi = an^2 c^2 - g2 s^2, which needs no root, so
// that it runs beside the root of g2 rather than after it.
inline CrossingDepths planeDepthsWithG(double depth, double an, double g2, double g, double c,
                                       double s) {
    const double scaled = depth / (an * an * c * c - g2 * s * s);
    const double lo = an * c - g * s, hi = an * c + g * s;
    return {g2 <= s * s ? depth : lo * scaled, hi * scaled};
}
inline CrossingDepths planeDepths(double depth, double an, double g2, double c, double s) {
    return planeDepthsWithG(depth, an, g2, std::sqrt(g2), c, s);
}

// The footprint on the plane z = 0 (every ray of the cone crossing it, as
// for a valid FootprintReach) as a quadratic form: with m its centre, e =
// depth s / k and a the axis' (x, y), a point x of the plane is in the cone
// iff |y|^2 - (a.y)^2 / c^2 <= e^2 k (y = x - m): the ellipse's matrix is
// e^2 (k I + a a^T), whose inverse is (I - a a^T / c^2) / (e^2 k). Grown by
// the distance tolerance (the ellipse scaled by 1 + tol / b contains it, b
// its minor semi-axis), and by the rounding of the form, so that "outside"
// is sure; a segment meets it iff the form's minimum along it is within.
class FootprintQuadric {
public:
    FootprintQuadric(const LocalCone& cone, double depth, double an, double k) {
        const Vec3& p = cone.apex;
        a_ = Vec2(cone.axis.x, cone.axis.y);
        const double c = cone.cosHalf;
        invC2_ = 1.0 / (c * c);
        const double invK = 1.0 / k;
        const double t = depth * an * invK;
        m_ = Vec2(p.x + t * a_.x, p.y + t * a_.y);
        const double e = depth * cone.sinHalf * invK;
        const double minor = e * std::sqrt(k);
        const double tol = cone.absTol + kThousandsOfUlps * (std::abs(m_.x) + std::abs(m_.y) + e * c);
        // The form's relative rounding is at most a few ulps of
        // c^2 / k <= 1 / kFootprintMinK = 1e6: under 1e-9.
        limit_ = (minor + tol) * (minor + tol) * (1.0 + 1e-9);
        minor2_ = minor * minor;
    }

    bool contains(const Vec2& x) const { return form(x - m_) <= limit_; }
    // In the footprint itself, not grown (a point of a boundary inside the
    // cone, for the single-edge criterion).
    bool containsStrictly(const Vec2& x) const { return form(x - m_) <= minor2_; }

    bool segmentMeets(const Vec2& v0, const Vec2& v1) const {
        const Vec2 e = v1 - v0, y0 = v0 - m_;
        const double ae = glm::dot(a_, e);
        const double qa = glm::dot(e, e) - ae * ae * invC2_;
        const double qb = glm::dot(y0, e) - glm::dot(a_, y0) * ae * invC2_;
        // The form is positive definite: qa > 0 unless the edge is a point
        // (then t is NaN or infinite and ends at 0 or 1). No branch: where
        // the nearest point falls is as good as random (selected by masks:
        // written with std::min and std::max, the clamp compiles to
        // branches on where t falls).
        const double r = -qb / qa;
        const double t0 = selectDouble(r > 0.0, r, 0.0);
        const double t = selectDouble(t0 < 1.0, t0, 1.0);
        return form(y0 + t * e) <= limit_;
    }

private:
    double form(const Vec2& y) const {
        const double ay = glm::dot(a_, y);
        return glm::dot(y, y) - ay * ay * invC2_;
    }

    Vec2 m_{0.0}, a_{0.0};
    double invC2_ = 1.0, limit_ = 0.0, minor2_ = 0.0;
};

// The footprint ellipse (on a plane z = zc every ray of the cone crosses, as
// for a valid FootprintReach) against circles about (0, 0, zc), for footprints small next to the circles (a pixel's
// cone against a disc): tight bounds from the ellipse's extent along the
// direction n of its centre m, with no unit vector, no division and no root
// but two (the major axis' certificates, when those leave a circle
// undecided, take one more).
//
// With e = depth s / k the ellipse is {m + y : y^T M^-1 y <= 1},
// M = e^2 (k I + a a^T) (a = the axis' (x, y)), whose support along a unit
// n is S = e sqrt(k + (n.a)^2) and across it S' = e sqrt(c^2 - (n.a)^2).
// Every point x has n.x in [d - S, d + S] (d = |m|) and |x|^2 <= (d + S)^2 +
// S'^2; the points m and m - M n / S (where n.x = d - S) are in it, and one
// point has |x| >= d + S; the origin is in it when m^T M^-1 m <= 1. A circle of radius rho is wholly around the
// ellipse, wholly off it, surely crossing it, or (within a few tolerances
// of tangency, or the centre on the origin) undecided.
enum class CircleRelation { EllipseInside, EllipseOutside, Crossing, Unsure };

class CircleFootprint {
public:
    // depth, an, k: as in FootprintReach (the plane z = apex.z + depth sign(axis.z)).
    // Every length is kept multiplied by k (m by k is k p + depth an a, e by k
    // is depth s), so that no division is needed: a circle's radius is
    // scaled by k in relation().
    CircleFootprint(const LocalCone& cone, double depth, double an, double k) : k_(k) {
        const Vec3& p = cone.apex;
        const Vec2 a(cone.axis.x, cone.axis.y);
        const double c = cone.cosHalf;
        const double ta = depth * an;
        const Vec2 m(k * p.x + ta * a.x, k * p.y + ta * a.y);  // k m
        const double e = depth * cone.sinHalf, e2 = e * e;        // k e
        d2_ = glm::dot(m, m);
        const double mu = glm::dot(m, a);
        const double sd2 = e2 * (k * d2_ + mu * mu);  // (k^2 S d)^2
        d_ = std::sqrt(d2_);
        sd_ = std::sqrt(sd2);                         // k^2 S d
        across2_ = e2 * (c * c * d2_ - mu * mu);      // k^4 S'^2 d^2
        // m - M n / S = m - e^2 (k m + (m.a) a) / (S d): times S d k^2 (in
        // the scaled terms), k^2 S d m - e^2 (k m + (m.a) a), no division.
        const Vec2 near = sd_ * m - e2 * (k * m + mu * a);
        near2_ = glm::dot(near, near);
        nearLimit_ = sd2;  // near2_ < inner^2 sd2 puts the point inside
        // The origin is in the ellipse: m^T M^-1 m <= 1, M^-1 = (I - a a^T / c^2) / (e^2 k).
        originIn_ = across2_ <= e2 * e2 * k * c * c;
        tolBase_ = cone.absTol * k + kThousandsOfUlps * (d_ + e * c);
        mu_ = mu;
        g2_ = glm::dot(a, a);
        ec_ = e * c;
    }

    CircleRelation relation(double rho) const {
        const double kRho = k_ * rho;
        const double tol = tolBase_ + kThousandsOfUlps * kRho;
        const double outer = kRho + tol, inner = kRho - tol;
        // Multiplied by d: d - S > outer, and so on.
        const double lowD = d2_ - sd_, highD = d2_ + sd_;
        const double inner2 = inner * inner;
        const bool outside = lowD > outer * d_;
        const bool inside = (inner > 0.0) & (highD * highD + across2_ < inner2 * d2_);
        const bool pointOut = highD > outer * d_;
        const bool pointIn =
            (inner > 0.0) & (originIn_ | (near2_ < inner2 * nearLimit_) | (d2_ < inner2));
        // EllipseInside 0, EllipseOutside 1, Crossing 2: the relation computed
        // from the two flags.
        static_assert(static_cast<int>(CircleRelation::EllipseInside) == 0 &&
                      static_cast<int>(CircleRelation::EllipseOutside) == 1 &&
                      static_cast<int>(CircleRelation::Crossing) == 2);
        if (outside | inside | (pointOut & pointIn)) [[likely]]
            return static_cast<CircleRelation>(static_cast<int>(outside) +
                                               2 * static_cast<int>(!outside & !inside));
        return inner > 0.0 && majorAxisCrosses(outer, inner) ? CircleRelation::Crossing
                                                             : CircleRelation::Unsure;
    }

private:
    // The major axis, the segment m + u a / g with |u| <= e c (g = |a|), lies
    // in the ellipse: its point nearest the origin inside the circle and an
    // end outside it prove a crossing. Times g^2, with T = u g:
    // g^2 |m + u a / g|^2 = g^2 d^2 + 2 T (m.a) + T^2, no division.
    // Rare (undecided by the cheap tests): kept out of line.
    [[gnu::noinline, gnu::cold]] bool majorAxisCrosses(double outer, double inner) const {
        const double g = std::sqrt(g2_), reach = ec_ * g;
        const double nearest = std::clamp(-mu_, -reach, reach);
        const double base = g2_ * d2_;
        const bool in = base + nearest * (2.0 * mu_ + nearest) < inner * inner * g2_;
        // The end farther from the origin: T = reach sign(m.a).
        const bool out = base + reach * (2.0 * std::abs(mu_) + reach) > outer * outer * g2_;
        const bool pointOut = out || d2_ + sd_ > outer * d_;
        const bool pointIn = in || originIn_ || near2_ < inner * inner * nearLimit_ ||
                             d2_ < inner * inner;
        return pointOut && pointIn;
    }

    double k_, d2_, d_, sd_, across2_, near2_, nearLimit_, tolBase_, mu_, g2_, ec_;
    bool originIn_;
};

// A cone whose apex lies in the plane z = 0 (to rounding: |apex.z| <= hTol),
// given the DotRange of +z: its rays cross the plane at |t| <= hTol / |d.z|,
// so either all of them do so before the range (Miss) or the answer is
// Marginal, up to tFarBound at most.
inline ConeClass apexInPlaneClass(const LocalCone& cone, DotRange range, double hTol,
                                  double tFarBound) {
    const double slope = range.lo > 0.0 ? range.lo : range.hi < 0.0 ? -range.hi : 0.0;
    if (slope > 0.0) {
        const double tHit = hTol / slope;
        if (cone.surelyBefore(tHit)) return missClass();
        return marginalClass(cone, cone.tMin, std::min(tHit, tFarBound));
    }
    return marginalClass(cone, cone.tMin, tFarBound);
}

// The tolerance within which an apex counts as lying in the plane z = 0.
inline double apexInPlaneTolerance(const LocalCone& cone) {
    const Vec3& p = cone.apex;
    return kFewUlps * (std::abs(p.x) + std::abs(p.y) + std::abs(p.z)) + cone.absTol;
}

// Off the fast path: the axis turned away from the plane z = 0 (or along
// it), and so is every ray (|a_z| c > g s: no direction within the
// half-angle reaches the plane's side), the apex off the plane by more than
// its tolerance: a Miss, as the exact test would find after its bounding
// ball and its dot range.
inline bool turnedAwayFromPlane(const LocalCone& cone, double h, double g2) {
    const double az = cone.axis.z, c = cone.cosHalf, s = cone.sinHalf;
    return (c > 0.0) & (h * az <= 0.0) & (padUp(g2 * s * s) < az * az * c * c) &
           (std::abs(h) > apexInPlaneTolerance(cone));
}

// The fast path of an annulus hole <= |x| <= outer about the origin of the
// plane z = 0 (Disc; EllipticDisc in its stretched plane D = diag(dx, dy),
// where its circles are), from the approach z. Every answer is computed for
// every cone and settled by one branch in the caller: whether a cone misses,
// covers or straddles the annulus is as good as random from one cone to the
// next, and a branch per answer would be mispredicted about once a cone
// (docs/geometry.md, "Disc"). Where the axis does not cross the plane the
// crossing's values are meaningless (even inf or NaN) and are not selected.
//
// Crossing: every ray crosses the plane, at depths [tNear, tFar], and the
// footprint lies within `reach` of the axis' crossing q (see
// footprintReach), its image within dMax reach of D q: against the circles
// that is a comparison of |D q| with their radii, one each way. Scaled by
// an k (an = |axis.z|), q and reach need no division; |D q| is one root. The
// footprint holds the disc of radius L s / (c + s) >= L s (1 - s) about q (L
// = depth / an, the axis' depth), its image the disc dMin times that about D
// q: a circle through that disc has footprint points on both sides, in the
// annulus and off it, so the cone is Marginal without the ellipse. The hole's
// comparisons are made only for an annulus with a hole (a branch that follows
// the objects).
// No crossing: never settled here. The caller tests the cones turned away
// from the plane past its branch (turnedAwayFromPlane): they are rare, and
// the test cost every cone about 30 instructions (docs/geometry.md, "Disc").
struct AnnulusStretch {
    double dx = 1.0, dy = 1.0, dMax = 1.0, dMin = 1.0;
};
struct AnnulusFastPath {
    bool settled, miss, full;  // settled: miss, full and the depths answer the cone
    double tNear, tFar;
};
inline AnnulusFastPath annulusFastPath(const LocalCone& cone, const ZPlaneApproach& z, double outer,
                                       double hole, const AnnulusStretch& d) {
    const Vec3& p = cone.apex;
    const Vec3& axis = cone.axis;
    const double c = cone.cosHalf, s = cone.sinHalf;
    const auto [crosses, h, g2, k, an, depth, ank] = z;
    const double g = std::sqrt(g2);
    const double qx = (an * p.x + depth * axis.x) * d.dx, qy = (an * p.y + depth * axis.y) * d.dy;
    const double q = std::sqrt(qx * qx + qy * qy) * k;
    const double reach = scaledReach(depth, an, g2, c, s, cone.absTol, ank) * d.dMax;
    const double inner = padDown(depth * k * s * (1.0 - s)) * d.dMin - cone.absTol * ank * d.dMax;
    const double outerK = ank * outer;
    bool miss = q > outerK + reach;
    bool full = q < outerK - reach;
    bool nearCircle = std::abs(q - outerK) < inner;
    if (hole > 0.0) {
        const double holeK = ank * hole;
        miss = miss | (q < holeK - reach);
        full = full & (q > holeK + reach);
        nearCircle = nearCircle | (std::abs(q - holeK) < inner);
    }
    const auto [tNear, tFar] = planeDepthsWithG(depth, an, g2, g, c, s);
    AnnulusFastPath f;
    f.settled = crosses & (miss | full | nearCircle);
    f.miss = miss;
    f.full = full;
    f.tNear = tNear;
    f.tFar = tFar;
    return f;
}

// True when no point of the ball (centre m, radius r) lies in the infinite
// cone (angular test only). Exact: the distance from m to the cone exceeds r
// (the ball grown by the cone's distance tolerance, for an apex on it).
inline bool ballOutsideAngular(const LocalCone& cone, const Vec3& m, double r) {
    r = padUp(r) + cone.absTol;
    const Vec3 w = m - cone.apex;
    const double d2 = glm::dot(w, w);
    if (d2 <= r * r) return false;
    const double c = cone.cosHalf, s = cone.sinHalf;
    const double sigma = glm::dot(w, cone.axis);
    const Vec3 perp = w - sigma * cone.axis;
    const double p2 = glm::dot(perp, perp);
    if (c >= 0.0) {
        // Nearest cone point is the apex (sigma c + |perp| s < 0), or the
        // perpendicular distance to the rim line |perp| c - sigma s exceeds r.
        if (sigma < 0.0 && sigma * sigma * c * c > p2 * s * s) return true;
        const double rhs = sigma * s + r;
        return rhs < 0.0 || p2 * c * c > rhs * rhs;
    }
    // Wider than a hemisphere: the same distance, once m is outside the cone.
    const double dp = std::sqrt(p2);
    if (s * sigma >= c * dp) return false;
    return sigma * c + dp * s < 0.0 || dp * c - sigma * s > r;
}

// True when the ball lies wholly nearer than the range or wholly beyond it.
inline bool ballOutsideRange(const LocalCone& cone, const Vec3& m, double r) {
    r = padUp(r) + cone.absTol;
    const Vec3 w = m - cone.apex;
    const double d2 = glm::dot(w, w);
    const double far = cone.tMaxOuter + r;  // |w| - r > tMaxOuter
    if (std::isfinite(far) && d2 > far * far) return true;
    const double near = cone.tMinOuter - r;  // |w| + r < tMinOuter
    return near > 0.0 && d2 < near * near;
}

inline bool ballOutside(const LocalCone& cone, const Vec3& m, double r) {
    return ballOutsideAngular(cone, m, r) || ballOutsideRange(cone, m, r);
}

// The start of the exact tests of a flat shape in the plane z = 0 whose
// points lie in the ball of radius `ball` about the origin, at depths
// [dNear, dFar] from the apex: `answer` is set for a Miss (the ball, the
// plane's crossing or the range) or an apex in the plane; otherwise every hit
// lies at depths [tLo, tHi].
struct PlaneBand {
    std::optional<ConeClass> answer;
    double tLo = 0.0, tHi = 0.0;
};
inline PlaneBand exactPlaneBand(const LocalCone& cone, double ball, double dNear, double dFar) {
    PlaneBand out;
    const Vec3& axis = cone.axis;
    const double h = -cone.apex.z;
    if (ballOutside(cone, Vec3(0.0), ball)) {
        out.answer = missClass();
        return out;
    }
    const DotRange range = dotRange(cone, axis.z, std::sqrt(axis.x * axis.x + axis.y * axis.y));
    const double hTol = apexInPlaneTolerance(cone);
    if (std::abs(h) <= hTol) {
        out.answer = apexInPlaneClass(cone, range, hTol, dFar);
        return out;
    }
    const PlaneCrossing crossing = planeCrossing(range, h);
    out.tLo = std::max(crossing.tNear, dNear);
    out.tHi = std::min(crossing.tFar, dFar);
    if (!crossing.any || cone.surelyAfter(out.tLo) || cone.surelyBefore(out.tHi)) out.answer = missClass();
    return out;
}

// The cone's footprint on the plane z = zc when every ray crosses it: an
// ellipse in (x, y), and the range of crossing distances.
struct Footprint {
    bool bounded = false;  // false: some ray does not cross, or badly conditioned
    Vec2 center{0.0};
    Vec2 major{1.0, 0.0};  // unit
    double a = 0.0;        // semi-axes, a >= b
    double b = 0.0;
    double tNear = 0.0;
    double tFar = 0.0;
};

// The footprint on the plane x[axis] = value, in the coordinates
// (x[(axis + 1) % 3], x[(axis + 2) % 3]).
inline Footprint footprintOnPlane(const LocalCone& cone, int axis, double value) {
    Footprint f;
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    const Vec3& p = cone.apex;
    const Vec3& ax = cone.axis;
    const double delta = value - p[axis];
    const double c = cone.cosHalf, s = cone.sinHalf;
    if (delta == 0.0 || !(c > 0.0)) return f;
    const double h = std::abs(delta);
    const double an = delta > 0.0 ? ax[axis] : -ax[axis];  // cos of the axis to the plane normal
    const double g2 = ax[i] * ax[i] + ax[j] * ax[j];
    // k = cos^2(theta) - sin^2(gamma) = cos(theta + gamma) cos(theta - gamma):
    // positive when every ray crosses; kept away from 0 so that the ellipse
    // is well conditioned (an elongated footprint goes to the fallbacks).
    const double k = c * c - g2;
    if (!(an > 0.0) || !(k > kFootprintMinK)) return f;
    const double g = std::sqrt(g2);
    f.bounded = true;
    f.major = g > 0.0 ? Vec2(ax[i], ax[j]) / g : Vec2(1.0, 0.0);
    f.center = Vec2(p[i], p[j]) + (h * an / k) * Vec2(ax[i], ax[j]);
    f.a = h * s * c / k;
    f.b = h * s / std::sqrt(k);
    const double lo = an * c - g * s;
    const double hi = angleWithin(an, g, c, s) ? 1.0 : an * c + g * s;
    f.tNear = h / hi;
    f.tFar = h / lo;
    return f;
}

inline Footprint footprintOnZPlane(const LocalCone& cone, double zc) {
    return footprintOnPlane(cone, 2, zc);
}

// Support of the footprint ellipse in the unit direction nu: max over the
// ellipse of nu.(y - center).
inline double footprintSupport(const Footprint& f, const Vec2& nu) {
    const double u = glm::dot(nu, f.major);
    const double v = nu.y * f.major.x - nu.x * f.major.y;
    return std::sqrt(f.a * f.a * u * u + f.b * f.b * v * v);
}

// Where an ellipse lies relative to a disc.
enum class DiscRelation { EllipseInside, EllipseOutside, Crossing };

// The footprint ellipse against the disc (centre, radius rho) in its plane;
// Crossing when the disc's circle meets the ellipse (or when unsure).
// absTol: an absolute distance tolerance (rounding of positions).
DiscRelation footprintVsDisc(const Footprint& f, const Vec2& center, double rho, double absTol);

// Distances from the point (y0, y1), y0, y1 >= 0, to the ellipse
// (x/a)^2 + (y/b)^2 = 1 with a >= b > 0: the nearest (for a point outside)
// and the farthest boundary point.
double ellipseMinDistance(double a, double b, double y0, double y1);
double ellipseMaxDistance(double a, double b, double y0, double y1);

// Whether the circle {z = zc, x^2 + y^2 = rho^2} may meet the infinite cone.
// With an arc given (nu unit, kappa), only the arc nu.(x, y) <= kappa counts.
struct Arc {
    Vec2 nu{1.0, 0.0};
    double kappa = kInfinity;
};
bool circleMayMeetCone(const LocalCone& cone, double zc, double rho, const Arc& arc = {});

// Whether the filled disc {z = zc, x^2 + y^2 <= rho^2} may meet the cone.
bool discMayMeetCone(const LocalCone& cone, double zc, double rho);

}  // namespace asos::conegeom
