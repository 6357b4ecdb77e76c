#include "asos/shapes/plane.hpp"

#include <cmath>

#include "asos/diag/format_number.hpp"
#include "asos/geometry/margins.hpp"
#include "asos/shapes/cone_geometry.hpp"
#include "asos/shapes/local_frame.hpp"

namespace asos {

using namespace conegeom;

std::optional<LocalHit> Plane::intersect(const Ray& ray, double tMin, double tMax) const {
    const double denom = glm::dot(normal_, ray.dir);
    if (denom == 0.0) return std::nullopt;
    const double t = (distance_ - glm::dot(normal_, ray.origin)) / denom;
    if (!(t >= tMin && t <= tMax)) return std::nullopt;
    return LocalHit{t, ray.at(t), normal_};
}

ConeClass Plane::classify(const LocalCone& cone) const {
    // The plane lies at signed distance h along n from the apex; a ray
    // crosses it at t = h / (n.d) when that is positive.
    const double h = distance_ - glm::dot(normal_, cone.apex);
    const double hTol = kFewUlps * (std::abs(distance_) + glm::length(cone.apex)) + cone.absTol;
    const DotRange range = dotRange(cone, normal_);
    if (std::abs(h) <= hTol) {
        // Apex on the plane (to rounding): rays cross at |t| <= hTol / |n.d|.
        const double slope = range.lo > 0.0 ? range.lo : range.hi < 0.0 ? -range.hi : 0.0;
        if (slope > 0.0) {
            const double tHit = hTol / slope;
            if (cone.surelyBefore(tHit)) return missClass();
            return marginalClass(cone, cone.tMin, tHit);
        }
        return marginalClass(cone, cone.tMin, cone.tMax);
    }
    const PlaneCrossing crossing = planeCrossing(range, h);
    if (!crossing.any) return missClass();
    if (cone.surelyAfter(crossing.tNear) || cone.surelyBefore(crossing.tFar)) return missClass();
    if (crossing.all && cone.surelyWithin(crossing.tNear, crossing.tFar))
        return fullClass(crossing.tNear, crossing.tFar);
    // The boundary in the cone is the horizon (a straight line in any image
    // plane) unless the range cuts the footprint.
    const bool horizonOnly =
        !crossing.all && !std::isfinite(cone.tMax) && crossing.tNear >= cone.tMinInner;
    return marginalClass(cone, crossing.tNear, crossing.tFar, horizonOnly);
}

std::vector<ShapeIssue> validate(const PlaneShape& record) {
    IssueList issues;
    if (issues.finite(0, record.normal, "the normal of a plane") && !(glm::length(record.normal) > 0.0))
        issues.add(0, "the normal of a plane must not be zero");
    if (!std::isfinite(record.distance))
        issues.add(1, "the distance of a plane must be finite, not " + formatNumber(record.distance));
    return issues.take();
}

Placed<Plane> place(const PlaneShape& record, const Transform& worldFromObject) {
    return {Plane(record.normal / glm::length(record.normal), record.distance),
            LocalFrame::make(worldFromObject, Mat3(1.0), Vec3(0.0)), Plane::kName};
}

}  // namespace asos
