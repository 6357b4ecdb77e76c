#include "asos/shapes/cone_geometry.hpp"

#include <algorithm>

#include "asos/geometry/margins.hpp"

namespace asos::conegeom {

namespace {
// Newton's method on F(t) = (a y0 / (t + a^2))^2 + (b y1 / (t + b^2))^2 - 1,
// the Lagrange condition of the point-to-ellipse distance: F is convex and
// monotone on each branch, so Newton started on the right side of the root
// approaches it monotonically and never overshoots.
struct EllipseRoot {
    double t;
    bool converged;
};

EllipseRoot newtonEllipse(double a, double b, double y0, double y1, double t) {
    const double ay = a * y0, by = b * y1, a2 = a * a, b2 = b * b;
    for (int i = 0; i < 100; ++i) {
        const double u = ay / (t + a2), v = by / (t + b2);
        const double f = u * u + v * v - 1.0;
        const double df = -2.0 * (u * u / (t + a2) + v * v / (t + b2));
        if (f == 0.0 || df == 0.0) return {t, true};
        const double next = t - f / df;
        // Converged once a step is lost in the rounding of t + b^2.
        if (!(std::abs(next - t) > kFewUlps * (std::abs(t) + b2))) return {next, true};
        t = next;
    }
    return {t, false};
}
}  // namespace

double ellipseMinDistance(double a, double b, double y0, double y1) {
    if (y1 == 0.0) return std::max(0.0, y0 - a);
    if (y0 == 0.0) return std::max(0.0, y1 - b);
    // The root is >= a y0 - a^2 and >= b y1 - b^2, where F >= 0.
    const double start = std::max({0.0, a * y0 - a * a, b * y1 - b * b});
    const EllipseRoot r = newtonEllipse(a, b, y0, y1, start);
    if (!r.converged) return 0.0;  // unsure: report the point as close
    const double x0 = a * a * y0 / (r.t + a * a), x1 = b * b * y1 / (r.t + b * b);
    return length2d(y0 - x0, y1 - x1);
}

double ellipseMaxDistance(double a, double b, double y0, double y1) {
    if (a == b) return length2d(y0, y1) + a;
    if (y0 == 0.0) {
        // Farthest from (0, y1): maximise a^2 + y1^2 + 2 b y1 u - (a^2 - b^2) u^2
        // over u = -sin(phi) in [-1, 1].
        const double d = a * a - b * b;
        const double u = b * y1 / d;
        if (u <= 1.0) return std::sqrt(a * a + y1 * y1 + b * b * y1 * y1 / d);
        return y1 + b;
    }
    // The root below -a^2, approached from the right where F >= 0.
    const EllipseRoot r = newtonEllipse(a, b, y0, y1, -a * a - a * y0);
    if (!r.converged) return length2d(y0, y1) + a;  // a bound
    const double x0 = a * a * y0 / (r.t + a * a), x1 = b * b * y1 / (r.t + b * b);
    return length2d(y0 - x0, y1 - x1);
}

DiscRelation footprintVsDisc(const Footprint& f, const Vec2& center, double rho, double absTol) {
    const double a = f.a, b = f.b;
    if (!(b > 0.0)) return DiscRelation::Crossing;
    const Vec2 d = center - f.center;
    const double q1 = std::abs(glm::dot(d, f.major));
    const double q2 = std::abs(d.y * f.major.x - d.x * f.major.y);
    const double qq = q1 * q1 + q2 * q2;
    const double tol = kThousandsOfUlps * (std::sqrt(qq) + a + rho) + absTol;
    const double support = std::sqrt(a * a * q1 * q1 + b * b * q2 * q2);
    // |y - q|^2 <= |q|^2 + 2 S + a^2 over the ellipse (S its support along q).
    const double maxBound = std::sqrt(qq + 2.0 * support + a * a);
    if (maxBound + tol < rho) return DiscRelation::EllipseInside;
    // Surely crossing when one of the centre and the four vertices of the
    // ellipse is inside the disc and another outside.
    const double r2 = rho * rho, slack2 = 2.0 * rho * tol + tol * tol;
    const double probes[5] = {qq, (q1 - a) * (q1 - a) + q2 * q2, (q1 + a) * (q1 + a) + q2 * q2,
                              q1 * q1 + (q2 - b) * (q2 - b), q1 * q1 + (q2 + b) * (q2 + b)};
    bool in = false, out = false;
    for (const double d2 : probes) {
        in = in || d2 < r2 - slack2;
        out = out || d2 > r2 + slack2;
    }
    if (in && out) return DiscRelation::Crossing;
    const double u = q1 / a, v = q2 / b;
    if (u * u + v * v > 1.0) {
        // The disc centre is outside the ellipse: the distance to it is at
        // least |q| - S/|q|, and exactly the nearest-point distance.
        const double qn = std::sqrt(qq);
        if (qn - support / qn - tol > rho) return DiscRelation::EllipseOutside;
        if (ellipseMinDistance(a, b, q1, q2) - tol > rho) return DiscRelation::EllipseOutside;
    }
    if (ellipseMaxDistance(a, b, q1, q2) + tol < rho) return DiscRelation::EllipseInside;
    return DiscRelation::Crossing;
}

bool circleMayMeetCone(const LocalCone& cone, double zc, double rho, const Arc& arc) {
    if (!(rho > 0.0)) {
        // A point: in the cone or not.
        return coneDistance(cone, conePoint(cone, Vec3(0.0, 0.0, zc) - cone.apex)) <= cone.absTol;
    }
    if (const FootprintReach reach = footprintReach(cone, zc); reach.valid) {
        // Quick: a circle farther from the axis' crossing q than the
        // footprint reaches, or wholly around that disc, does not meet it.
        const double q = glm::length(reach.q);
        if (q + reach.radius < rho || q - reach.radius > rho) return false;
    }
    const Footprint f = footprintOnZPlane(cone, zc);
    if (!f.bounded) return !ballOutsideAngular(cone, Vec3(0.0, 0.0, zc), rho);
    if (footprintVsDisc(f, Vec2(0.0), rho, cone.absTol) != DiscRelation::Crossing) return false;
    if (std::isfinite(arc.kappa)) {
        // The ellipse lies wholly on the side of the line away from the arc.
        const double low = glm::dot(arc.nu, f.center) - footprintSupport(f, arc.nu);
        if (low > arc.kappa + kThousandsOfUlps * (std::abs(arc.kappa) + rho + f.a) + cone.absTol) return false;
    }
    return true;
}

}  // namespace asos::conegeom

namespace asos::conegeom {

bool discMayMeetCone(const LocalCone& cone, double zc, double rho) {
    if (const FootprintReach reach = footprintReach(cone, zc); reach.valid)
        return glm::length(reach.q) - reach.radius <= rho;
    return !ballOutsideAngular(cone, Vec3(0.0, 0.0, zc), rho);
}

}  // namespace asos::conegeom
