#include "asos/shapes/disc.hpp"

#include <algorithm>
#include <cmath>

#include "asos/shapes/cone_geometry.hpp"

namespace asos {

using namespace conegeom;

Bounds3 Disc::worldBounds(const Mat3& m, const Vec3& offset) const {
    // A circle of radius r spanned by columns u, v reaches r sqrt(u_i^2 + v_i^2)
    // along world axis i.
    Vec3 half;
    for (int i = 0; i < 3; ++i) half[i] = radius_ * length2d(m[0][i], m[1][i]);
    return {offset - half, offset + half};
}

std::optional<LocalHit> Disc::intersect(const Ray& ray, double tMin, double tMax) const {
    if (ray.dir.z == 0.0 || empty()) return std::nullopt;
    const double t = -ray.origin.z / ray.dir.z;
    if (!(t >= tMin && t <= tMax)) return std::nullopt;
    const double x = ray.origin.x + t * ray.dir.x, y = ray.origin.y + t * ray.dir.y;
    const double r2 = x * x + y * y;
    if (r2 > radius_ * radius_ || r2 < hole_ * hole_) return std::nullopt;
    return LocalHit{t, Vec3(x, y, 0.0), Vec3(0.0, 0.0, 1.0)};
}

ConeClass Disc::classify(const LocalCone& cone) const {
    if (empty()) return missClass();
    const Vec3& p = cone.apex;
    const Vec3& axis = cone.axis;
    const double c = cone.cosHalf, s = cone.sinHalf;
    const double h = -p.z;
    if (c > 0.0 && h * axis.z > 0.0) {
        // Fast path. When every ray crosses, the footprint (an ellipse) lies
        // within `radius` of the axis' crossing q: against the two circles
        // that is a comparison of |q| with their radii.
        const double an = std::abs(axis.z);
        const double g2 = axis.x * axis.x + axis.y * axis.y;
        const double k = c * c - g2;
        if (k > 1e-6) {
            // sin(gamma) = sqrt(g2) <= (1 + g2) / 2: the radius needs no root
            // (it grows by a fraction of order sin^2(theta)); the depths do.
            const double gBound = 0.5 * (1.0 + g2), depth = std::abs(h);
            const double invAn = 1.0 / an;
            const double tAxis = depth * invAn;
            const double qx = p.x + tAxis * axis.x, qy = p.y + tAxis * axis.y;
            const double q2 = qx * qx + qy * qy;
            const double radius = depth * s / k * (c + gBound * s * invAn) * (1.0 + 1e-12) + cone.absTol;
            if (q2 > (radius_ + radius) * (radius_ + radius)) return missClass();
            if (hole_ > radius && q2 < (hole_ - radius) * (hole_ - radius)) return missClass();
            const double g = std::sqrt(g2);
            const double lo = an * c - g * s;
            const double hi = angleWithin(an, g, c, s) ? 1.0 : an * c + g * s;
            const double tNear = depth / hi, tFar = depth / lo;
            if (radius_ > radius && q2 < (radius_ - radius) * (radius_ - radius) &&
                (hole_ == 0.0 || q2 > (hole_ + radius) * (hole_ + radius))) {
                if (cone.surelyAfter(tNear) || cone.surelyBefore(tFar)) return missClass();
                if (cone.surelyWithin(tNear, tFar)) return fullClass(tNear, tFar);
                return marginalClass(cone, tNear, tFar);
            }
            // Surely crossing a circle: q (in the footprint) on one side, a
            // point of the disc inscribed in the ellipse (centre m, radius
            // the minor semi-axis) on the other.
            const double scale = depth * an / k;
            const double m = length2d(p.x + scale * axis.x, p.y + scale * axis.y);
            const double minor = depth * s / std::sqrt(k);
            const double q1 = std::sqrt(q2), tol = cone.absTol + 1e-12 * (q1 + radius_);
            auto crosses = [&](double rho) {
                return (q1 < rho - tol && m + minor > rho + tol) ||
                       (q1 > rho + tol && m - minor < rho - tol);
            };
            if (crosses(radius_) || (hole_ > 0.0 && crosses(hole_))) {
                if (cone.surelyAfter(tNear) || cone.surelyBefore(tFar)) return missClass();
                return marginalClass(cone, tNear, tFar);
            }
        }
    }
    if (ballOutside(cone, Vec3(0.0), radius_)) return missClass();
    const DotRange range = dotRange(cone, axis.z, std::sqrt(axis.x * axis.x + axis.y * axis.y));
    // Depths of the annulus' points from the apex.
    const double rho = length2d(p.x, p.y);
    const double dNear = length2d(h, rho - std::clamp(rho, hole_, radius_));
    const double dFar = length2d(h, rho + radius_);
    const double hTol = 1e-15 * (std::abs(p.x) + std::abs(p.y) + std::abs(p.z)) + cone.absTol;
    if (std::abs(h) <= hTol) {
        // Apex in the plane (to rounding): rays cross at |t| <= hTol / |d.z|.
        const double slope = range.lo > 0.0 ? range.lo : range.hi < 0.0 ? -range.hi : 0.0;
        if (slope > 0.0) {
            const double tHit = hTol / slope;
            if (cone.surelyBefore(tHit)) return missClass();
            return marginalClass(cone, cone.tMin, std::min(tHit, dFar));
        }
        return marginalClass(cone, cone.tMin, dFar);
    }
    const PlaneCrossing crossing = planeCrossing(range, h);
    if (!crossing.any) return missClass();
    const double tLo = std::max(crossing.tNear, dNear), tHi = std::min(crossing.tFar, dFar);
    if (cone.surelyAfter(tLo) || cone.surelyBefore(tHi)) return missClass();

    const Footprint f = footprintOnZPlane(cone, 0.0);
    if (!f.bounded) {
        // Some rays run parallel to the plane (or the footprint is too
        // elongated to resolve): the rim, near the cone, may be in it.
        return marginalClass(cone, tLo, tHi);
    }
    const DiscRelation outer = footprintVsDisc(f, Vec2(0.0), radius_, cone.absTol);
    if (outer == DiscRelation::EllipseOutside) return missClass();
    if (outer == DiscRelation::Crossing) return marginalClass(cone, tLo, tHi);
    if (hole_ > 0.0) {
        const DiscRelation inner = footprintVsDisc(f, Vec2(0.0), hole_, cone.absTol);
        if (inner == DiscRelation::EllipseInside) return missClass();
        if (inner == DiscRelation::Crossing) return marginalClass(cone, tLo, tHi);
    }
    if (cone.surelyWithin(f.tNear, f.tFar)) return fullClass(f.tNear, f.tFar);
    return marginalClass(cone, f.tNear, f.tFar);
}

}  // namespace asos
