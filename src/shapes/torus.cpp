#include "asos/shapes/torus.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "asos/diag/format_number.hpp"
#include "asos/geometry/margins.hpp"
#include "asos/shapes/box.hpp"
#include "asos/shapes/cone_geometry.hpp"
#include "asos/shapes/sphere.hpp"

namespace asos {

using namespace conegeom;

namespace {

// The ball inside the solid that a Full answer rests on is shrunk by this
// share of r, so that a ray meeting it goes into the solid by more than the
// quartic's rounding (a ray grazing the ball would graze the torus).
constexpr double kBallShrink = 1e-6;
// The root search's interval is the swept sphere's chord widened by this
// share of its length each way, so that roots where the torus touches the
// sphere (its outer equator) are not lost at an end.
constexpr double kChordPad = 1e-9;
// The tube test's balls along the core circle: as many as keep their growth
// (the chord to the farthest core point between two) within r / 2, at most
// this many.
constexpr int kMaxTubeBalls = 64;
// A root is refined to this share of the chord (far below any tolerance of
// the tracers, a few ulps above the rounding of the distance function).
constexpr double kRootTolerance = 1e-14;

// A root in [lo, hi] of a function that changes sign over it (vd(x) gives
// its value and derivative; sLo the sign of its value at lo): Newton's steps,
// bisection where a step leaves the bracket, to `tol`.
template <class ValueAndSlope>
double refineRoot(const ValueAndSlope& vd, double lo, double hi, bool negativeAtLo, double tol) {
    double x = 0.5 * (lo + hi);
    for (int i = 0; i < 200; ++i) {
        const auto [v, d] = vd(x);
        if (v == 0.0) return x;
        if ((v < 0.0) == negativeAtLo) lo = x;
        else hi = x;
        double next = x - v / d;
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (hi - lo <= tol || std::abs(next - x) <= tol) return next;
        x = next;
    }
    return x;
}

// The roots of a x^2 + b x + c = 0 inside (lo, hi), ascending, without
// cancellation.
int quadraticRootsIn(double a, double b, double c, double lo, double hi, double out[2]) {
    int n = 0;
    double r0, r1;
    if (a == 0.0) {
        if (b == 0.0) return 0;
        r0 = r1 = -c / b;
    } else {
        const double disc = b * b - 4.0 * a * c;
        if (disc < 0.0) return 0;
        const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
        if (q == 0.0) {
            r0 = r1 = -0.5 * b / a;
        } else {
            r0 = q / a;
            r1 = c / q;
        }
        if (r0 > r1) std::swap(r0, r1);
    }
    if (r0 > lo && r0 < hi) out[n++] = r0;
    if (r1 > lo && r1 < hi && (n == 0 || r1 != out[0])) out[n++] = r1;
    return n;
}

// Whether every ray of the cone crosses the slab |y| <= r within the hole's
// cylinder (distance from the y axis below R - r), missing the torus.
bool throughHole(const LocalCone& cone, double major, double minor) {
    const double hole = major - minor;
    if (!(hole > 0.0)) return false;
    // Every ray crosses the slab |y| <= r (d.y of one sign, away from 0)
    // within depths [ta, tb].
    const DotRange dy = dotRange(cone, Vec3(0.0, 1.0, 0.0));
    if (!(dy.lo > 0.0 || dy.hi < 0.0)) return false;
    const double oy = cone.apex.y;
    const double slowest = std::min(std::abs(dy.lo), std::abs(dy.hi));
    const double fastest = std::max(std::abs(dy.lo), std::abs(dy.hi));
    // Heights to the slab's planes along the rays' y direction.
    const double sign = dy.lo > 0.0 ? 1.0 : -1.0;
    const double hNear = sign * (-sign * minor - oy), hFar = sign * (sign * minor - oy);
    if (hFar < 0.0) return true;  // the slab lies behind every ray
    const double ta = std::max(0.0, hNear >= 0.0 ? hNear / fastest : hNear / slowest);
    const double tb = hFar / slowest;
    // The rays' points at depths in [ta, tb] lie in the hull of the balls
    // about apex + t axis of radius 2 t sin(theta / 2) at both ends; the
    // distance from the y axis plus the radius, convex along the hull, is
    // largest at an end.
    const double chord = std::sqrt(std::max(0.0, 2.0 * (1.0 - cone.cosHalf)));
    const double limit = hole * (1.0 - kRootTolerance * 1e3) - 2.0 * cone.absTol;
    for (const double t : {ta, tb}) {
        const Vec3 c = cone.apex + t * cone.axis;
        if (!(std::sqrt(c.x * c.x + c.z * c.z) + padUp(t * chord) <= limit)) return false;
    }
    return true;
}

}  // namespace

Bounds3 Torus::worldBounds(const Mat3& m, const Vec3& offset) const {
    const double rs = major_ + minor_;
    return Box(Vec3(-rs, -minor_, -rs), Vec3(rs, minor_, rs)).worldBounds(m, offset);
}

TorusRoots Torus::roots(const Ray& ray) const {
    TorusRoots out;
    const double rs = major_ + minor_;
    const sphere_detail::Roots chord = sphere_detail::sphereRoots(ray, rs);
    if (!chord.real) return out;
    const Vec3& d = ray.dir;
    const double a = glm::dot(d, d);
    const double pad = kChordPad * (chord.far - chord.near) + kChordPad * rs / std::sqrt(a);
    const double t0 = chord.near - pad;
    const double length = chord.far + pad - t0;
    // The line from q = o + t0 d (on the swept sphere: coefficients of the
    // size of the torus), as f(s) = g^2 - 4 R^2 rho with g = |x|^2 + R^2 - r^2
    // and rho = x^2 + z^2: a quartic, whose derivatives place its monotone
    // stretches. Its sign is h's, h = (sqrt(rho) - R)^2 + y^2 - r^2 (f is h
    // times a positive factor for r <= R), which rounds far better near the
    // surface: the roots are h's, refined in each stretch where it changes sign.
    const Vec3 q = ray.origin + t0 * d;
    const double big = major_ * major_, small = minor_ * minor_;
    const double b = glm::dot(q, d), k = glm::dot(q, q) + big - small;
    const double ah = d.x * d.x + d.z * d.z, bh = q.x * d.x + q.z * d.z;
    const double c4 = a * a, c3 = 4.0 * a * b, c2 = 4.0 * b * b + 2.0 * a * k - 4.0 * big * ah,
                 c1 = 4.0 * b * k - 8.0 * big * bh;
    const double tol = kRootTolerance * length;
    // f'(s) = 4 c4 s^3 + 3 c3 s^2 + 2 c2 s + c1, monotone between the roots of f''.
    const auto slope = [&](double s) {
        return std::pair{((4.0 * c4 * s + 3.0 * c3) * s + 2.0 * c2) * s + c1, (12.0 * c4 * s + 6.0 * c3) * s + 2.0 * c2};
    };
    double bends[2];
    const int bendCount = quadraticRootsIn(12.0 * c4, 6.0 * c3, 2.0 * c2, 0.0, length, bends);
    double turns[5];
    int turnCount = 0;
    {
        double lo = 0.0;
        double loValue = slope(lo).first;
        for (int i = 0; i <= bendCount; ++i) {
            const double hi = i < bendCount ? bends[i] : length;
            const double hiValue = slope(hi).first;
            if ((loValue < 0.0) != (hiValue < 0.0) && loValue != 0.0 && hiValue != 0.0)
                turns[turnCount++] = refineRoot(slope, lo, hi, loValue < 0.0, tol);
            lo = hi;
            loValue = hiValue;
        }
    }
    const auto distance = [&](double s) {
        const Vec3 x = q + s * d;
        const double rho = std::sqrt(x.x * x.x + x.z * x.z);
        const double across = rho - major_;
        const double value = across * across + x.y * x.y - small;
        // d/ds: 2 (rho - R) rho' + 2 y y', rho' = (x.x d.x + x.z d.z) / rho.
        const double radial = rho > 0.0 ? (x.x * d.x + x.z * d.z) / rho : 0.0;
        return std::pair{value, 2.0 * (across * radial + x.y * d.y)};
    };
    double lo = 0.0;
    double loValue = distance(lo).first;
    for (int i = 0; i <= turnCount && out.count < 4; ++i) {
        const double hi = i < turnCount ? turns[i] : length;
        if (!(hi > lo)) continue;
        const double hiValue = distance(hi).first;
        double root = -1.0;
        if (loValue == 0.0) root = lo;
        else if (hiValue != 0.0 && (loValue < 0.0) != (hiValue < 0.0))
            root = refineRoot(distance, lo, hi, loValue < 0.0, tol);
        if (root >= 0.0 && (out.count == 0 || out.t[out.count - 1] != t0 + root)) out.t[out.count++] = t0 + root;
        lo = hi;
        loValue = hiValue;
    }
    if (loValue == 0.0 && out.count < 4 && (out.count == 0 || out.t[out.count - 1] != t0 + lo))
        out.t[out.count++] = t0 + lo;
    return out;
}

std::optional<LocalHit> Torus::intersect(const Ray& ray, double tMin, double tMax) const {
    const TorusRoots all = roots(ray);
    for (int i = 0; i < all.count; ++i) {
        const double t = all.t[i];
        if (!(t >= tMin && t <= tMax)) continue;
        const Vec3 p = ray.at(t);
        // POV-Ray's: the point less its nearest point of the core circle.
        const double rho = std::sqrt(p.x * p.x + p.z * p.z);
        const Vec3 core = rho > 0.0 ? Vec3(major_ * p.x / rho, 0.0, major_ * p.z / rho) : Vec3(0.0);
        return LocalHit{t, p, p - core};
    }
    return std::nullopt;
}

bool Torus::inside(const Vec3& p) const {
    const double across = std::sqrt(p.x * p.x + p.z * p.z) - major_;
    return across * across + p.y * p.y <= minor_ * minor_;
}

double Torus::support(const Vec3& dir) const {
    return major_ * std::sqrt(dir.x * dir.x + dir.z * dir.z) + minor_ * glm::length(dir);
}

bool Torus::raysLeave(const LocalRays& rays) const {
    const double rs = major_ + minor_;
    return glm::dot(rays.origin, rays.origin) >= rs * rs && rays.awayFrom(rays.origin);
}

ConeClass Torus::classify(const LocalCone& cone) const {
    const double rs = major_ + minor_;
    // The swept ball as a solid (a sphere's or a box's own answer is about
    // its surface, which a cone from inside may miss).
    if (ballOutsideAngular(cone, Vec3(0.0), rs)) return missClass();
    if (throughHole(cone, major_, minor_)) return missClass();
    // The tube test: the solid lies in balls about n points of the core
    // circle, each of radius r + 2 R sin(pi / 2n) (every core point is that
    // near one of them). Miss where the cone misses every ball; otherwise
    // every crossing lies within the depths of the balls it may meet (by
    // angle alone: a crossing before the range bounds the Full test's depths).
    const double grow = std::min(0.5 * minor_, 2.0 * major_);
    const int n = std::clamp(static_cast<int>(std::ceil(kPi / (2.0 * std::asin(std::min(1.0, grow / (2.0 * major_)))))),
                             8, kMaxTubeBalls);
    const double tube = minor_ + padUp(2.0 * major_ * std::sin(kPi / (2.0 * n)));
    double nearest = kInfinity, farthest = -kInfinity;
    for (int k = 0; k < n; ++k) {
        const double a = 2.0 * kPi * k / n;
        const Vec3 c(major_ * std::cos(a), 0.0, major_ * std::sin(a));
        if (ballOutsideAngular(cone, c, tube)) continue;
        const double d = glm::length(c - cone.apex);
        nearest = std::min(nearest, d - tube);
        farthest = std::max(farthest, d + tube);
    }
    if (!(nearest <= farthest)) return missClass();
    const double dist = glm::length(cone.apex);
    nearest = std::max(0.0, padDown(nearest) - cone.absTol);
    farthest = padUp(farthest) + cone.absTol;
    if (cone.surelyAfter(nearest) || cone.surelyBefore(farthest)) return missClass();
    // Full: the apex outside the solid, by more than rounding, and the cone
    // inside a ball about the core point nearest the axis' first hit. A ray
    // that reaches the ball has crossed the surface on its way in.
    const Vec3& o = cone.apex;
    const double across = std::sqrt(o.x * o.x + o.z * o.z) - major_;
    const double outside = across * across + o.y * o.y - minor_ * minor_;
    const double band = kTensOfUlps * (dist * dist + rs * rs) + 2.0 * rs * cone.absTol;
    if (outside > band) {
        if (const auto hit = intersect(Ray{o, cone.axis}, 0.0, kInfinity)) {
            const double rho = std::sqrt(hit->point.x * hit->point.x + hit->point.z * hit->point.z);
            if (rho > 0.0) {
                LocalCone shifted = cone;
                shifted.apex = o - Vec3(major_ * hit->point.x / rho, 0.0, major_ * hit->point.z / rho);
                const ConeClass ball = Sphere(minor_ * (1.0 - kBallShrink)).classify(shifted);
                if (ball.coverage == Coverage::Full && cone.surelyWithin(nearest, ball.tFar))
                    return fullClass(nearest, padUp(ball.tFar));
            }
        }
    }
    return marginalClass(cone, nearest, farthest);
}

std::vector<ShapeIssue> validate(const TorusShape& record) {
    IssueList issues;
    const bool major = issues.positive(0, record.major, "the major radius of a torus");
    const bool minor = issues.positive(1, record.minor, "the minor radius of a torus");
    if (major && minor && record.minor > record.major)
        issues.add(1, "a torus whose minor radius " + formatNumber(record.minor) + " exceeds its major radius " +
                          formatNumber(record.major) + " (POV-Ray's spindle torus) is not supported");
    return issues.take();
}

Placed<Torus> place(const TorusShape& record, const Transform& worldFromObject) {
    return {Torus(record.major, record.minor), LocalFrame::make(worldFromObject, Mat3(1.0), Vec3(0.0)), Torus::kName};
}

}  // namespace asos
