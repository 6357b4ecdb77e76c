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
    if (empty()) return std::nullopt;
    const auto hit = crossZPlane(ray, tMin, tMax);
    if (!hit) return std::nullopt;
    const double r2 = hit->x * hit->x + hit->y * hit->y;
    if (r2 > radius_ * radius_ || r2 < hole_ * hole_) return std::nullopt;
    return LocalHit{hit->t, Vec3(hit->x, hit->y, 0.0), Vec3(0.0, 0.0, 1.0)};
}

ConeClass Disc::classify(const LocalCone& cone) const {
    return classifyWith(cone, [] {}, [](const ConeClass& out) { return out; });
}

std::optional<ConeClass> Disc::classifyAcrossScale(const PreparedCone& cone,
                                                   const LocalFrame& frame) const {
    if (empty()) return missClass();
    // The plane z = 0, with its unit normal kept with the frame, through the
    // disc's centre, the world image of the local origin.
    const Mat3& a = frame.localFromWorld;
    const Vec3& n = frame.planeNormal;
    const Vec3 w = cone.apex - frame.worldOffset;
    const double c = cone.cosHalf, s = cone.sinHalf;
    // As in the local fast path below, in world units: h the apex's height
    // under the plane, a_n = |n.axis|, g^2 the axis' part in the plane.
    const double h = -glm::dot(n, w), az = glm::dot(n, cone.axis);
    const Vec3 along = cone.axis - az * n;
    const double g2 = glm::dot(along, along), k = c * c - g2;
    if (!(c > 0.0 && h * az > 0.0 && k > 1e-6)) return std::nullopt;
    const double an = std::abs(az), depth = std::abs(h), ank = an * k;
    // The axis' crossing times a_n, a vector in the plane, and its local
    // in-plane coordinates (rows 0 and 1 of localFromWorld).
    const Vec3 qs = an * w + depth * cone.axis;
    const double qx = a[0][0] * qs.x + a[1][0] * qs.y + a[2][0] * qs.z;
    const double qy = a[0][1] * qs.x + a[1][1] * qs.y + a[2][1] * qs.z;
    const double q2 = (qx * qx + qy * qy) * (k * k);
    // The world footprint lies within its reach of the crossing; mapped, within
    // sigmaMax times that. absTol in world units: the coordinates' size (the
    // apex from the centre, and the centre itself, whose rounding the local
    // offset carries) and the disc's world extent (at most radius / sigmaMin).
    const Vec3& centre = frame.worldOffset;
    const double absTol =
        1e-11 * (std::abs(w.x) + std::abs(w.y) + std::abs(w.z) + std::abs(centre.x) +
                 std::abs(centre.y) + std::abs(centre.z) + radius_ / frame.sigmaMin);
    const double reachWorld = scaledReach(depth, an, g2, c, s, absTol, ank);
    const double radius = reachWorld * frame.sigmaMax * (1.0 + 1e-12);
    const auto [miss, full] = circlesAgainstReach(q2, ank, radius);
    if (miss) return missClass();
    if (!full) return std::nullopt;
    // Every ray crosses the plane within the disc: the world depths against
    // the world range, padded as a rigid frame's are.
    LocalCone world;
    world.setRange(cone.tMin, cone.tMax, absTol);
    const auto [tNear, tFar] = planeDepths(depth, an, g2, c, s);
    return RigidBounds{absTol, 1.0, cone.tMin, cone.tMax}(
        rangedClass(world, false, true, tNear, tFar));
}

std::optional<ConeClass> Disc::bandClass(const LocalCone& cone, double depth, double an, double k,
                                         double tNear, double tFar) const {
    const CircleFootprint ellipse(cone, depth, an, k);
    const CircleRelation outer = ellipse.relation(radius_);
    // The hole matters only to an ellipse inside the outer circle.
    const CircleRelation inner = hole_ > 0.0 && outer == CircleRelation::EllipseInside
                                     ? ellipse.relation(hole_)
                                     : CircleRelation::EllipseOutside;
    const bool unsure = (outer == CircleRelation::Unsure) |
                        ((outer == CircleRelation::EllipseInside) & (inner == CircleRelation::Unsure));
    if (unsure) return std::nullopt;
    const bool ellipseMiss = (outer == CircleRelation::EllipseOutside) |
                             ((outer == CircleRelation::EllipseInside) &
                              (inner == CircleRelation::EllipseInside));
    const bool ellipseFull = (outer == CircleRelation::EllipseInside) &
                             (inner == CircleRelation::EllipseOutside);
    // The disc's own distance (its bounding ball) against the range, too.
    const bool outOfRange = ballOutsideRange(cone, Vec3(0.0), radius_);
    return rangedClass(cone, ellipseMiss | outOfRange, ellipseFull, tNear, tFar);
}

ConeClass Disc::classifyExactly(const LocalCone& cone) const {
    const Vec3& p = cone.apex;
    const Vec3& axis = cone.axis;
    const double h = -p.z;
    if (ballOutside(cone, Vec3(0.0), radius_)) return missClass();
    const DotRange range = dotRange(cone, axis.z, std::sqrt(axis.x * axis.x + axis.y * axis.y));
    // Depths of the annulus' points from the apex.
    const double rho = length2d(p.x, p.y);
    const double dNear = length2d(h, rho - std::clamp(rho, hole_, radius_));
    const double dFar = length2d(h, rho + radius_);
    const double hTol = apexInPlaneTolerance(cone);
    if (std::abs(h) <= hTol) return apexInPlaneClass(cone, range, hTol, dFar);
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
