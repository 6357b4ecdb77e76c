#include "asos/shapes/disc.hpp"

#include <algorithm>
#include <cmath>

#include "asos/diag/format_number.hpp"
#include "asos/geometry/frame.hpp"
#include "asos/shapes/cone_geometry.hpp"
#include "asos/shapes/local_frame.hpp"

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
    return classifyWith(cone, [] {}, LocalFinish{cone});
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
    const double h = -p.z;
    // Depths of the annulus' points from the apex.
    const double rho = length2d(p.x, p.y);
    const double dNear = length2d(h, rho - std::clamp(rho, hole_, radius_));
    const double dFar = length2d(h, rho + radius_);
    const PlaneBand band = exactPlaneBand(cone, radius_, dNear, dFar);
    if (band.answer) return *band.answer;
    const double tLo = band.tLo, tHi = band.tHi;

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

std::vector<ShapeIssue> validate(const DiscShape& record) {
    IssueList issues;
    issues.finite(0, record.center, "the centre of a disc");
    if (issues.finite(1, record.normal, "the normal of a disc") && !(glm::length(record.normal) > 0.0))
        issues.add(1, "the normal of a disc must not be zero");
    issues.positive(2, record.radius, "the radius of a disc");
    const double hole = record.holeRadius;
    if (hole < 0.0 || (record.radius > 0.0 && hole >= record.radius))
        issues.add(3, "the hole radius of a disc must be at least 0 and less than its radius " +
                          formatNumber(record.radius) + ", not " + formatNumber(hole));
    else if (!std::isfinite(hole))
        issues.add(3, "the hole radius of a disc must be finite, not " + formatNumber(hole));
    return issues.take();
}

std::variant<Placed<Disc>, Placed<EllipticDisc>> place(const DiscShape& record,
                                                       const Transform& worldFromObject) {
    const Disc disc(record.radius, record.holeRadius);
    const LocalFrame frame = LocalFrame::make(
        worldFromObject, frameAroundAxis(record.normal / glm::length(record.normal)), record.center);
    if (frame.kind != LocalFrame::Kind::General) return Placed<Disc>{disc, frame, Disc::kName};
    // An affine image of a circle is an ellipse: the disc is laid out again
    // in a rigid frame whose x and y run along the axes of the ellipse
    // {A x : |x| <= radius} (A = inPlane), the eigenvectors of A A^T, its
    // semi-axes radius times the rows' lengths there.
    const glm::dmat2 a = frame.flattened().inPlane;
    const glm::dmat2 p = a * glm::transpose(a);
    const double angle = 0.5 * std::atan2(2.0 * p[1][0], p[0][0] - p[1][1]);
    const LocalFrame::Flattened flat = frame.flattened(angle);
    const glm::dmat2& b = flat.inPlane;
    return Placed<EllipticDisc>{EllipticDisc(record.radius * std::hypot(b[0][0], b[1][0]),
                                             record.radius * std::hypot(b[0][1], b[1][1]),
                                             record.holeRadius / record.radius),
                                flat.frame, Disc::kName};
}

}  // namespace asos
