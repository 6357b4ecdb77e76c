#include "asos/testing/segment_shadow_pyray.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "asos/geometry/margins.hpp"
#include "asos/testing/direction_cone.hpp"

namespace asos {

std::optional<SegmentShadowPyray> SegmentShadowPyray::make(const Vec3& point, const Vec3& a,
                                                           const Vec3& b, double tMin) {
    const Vec3 ab = b - a;
    const double length = glm::length(ab);
    if (!(length > 0.0)) throw std::invalid_argument("linear light of zero length");
    // On the segment (to rounding): the rays to its ends point apart and no
    // cone narrower than a half-space holds them.
    const double f = std::clamp(glm::dot(point - a, ab) / (length * length), 0.0, 1.0);
    const double offLine = glm::length(point - (a + f * ab));
    const double scale = length + glm::length(point - a);
    if (!(offLine > kThousandsOfUlps * scale)) return std::nullopt;
    return SegmentShadowPyray(point, a, b, 0.0, 1.0, 0, tMin);
}

SegmentShadowPyray::SegmentShadowPyray(const Vec3& point, const Vec3& a, const Vec3& b, double s0,
                                       double s1, int level, double tMin)
    : point_(point), a_(a), b_(b), s0_(s0), s1_(s1), level_(level), tMin_(tMin) {
    const Vec3 toStart = lightPoint(s0_) - point_, toEnd = lightPoint(s1_) - point_;
    const double startDistance = glm::length(toStart), endDistance = glm::length(toEnd);
    const std::array<Vec3, 2> directions = {toStart / startDistance, toEnd / endDistance};
    // Two directions that are not opposite: the cone about their bisector
    // holds the arc between them, i.e. every ray of the triangle.
    const DirectionCone bound = smallestEnclosingCone(directions);
    cone_ = {point_, bound.axis, bound.halfAngle, tMin_, padUp(std::max(startDistance, endDistance))};
}

std::array<SegmentShadowPyray, 2> SegmentShadowPyray::split() const {
    const double mid = 0.5 * (s0_ + s1_);
    return {SegmentShadowPyray(point_, a_, b_, s0_, mid, level_ + 1, tMin_),
            SegmentShadowPyray(point_, a_, b_, mid, s1_, level_ + 1, tMin_)};
}

BeamRay SegmentShadowPyray::toward(double xi) const {
    const Vec3 offset = lightPoint(s0_ + xi * (s1_ - s0_)) - point_;
    const double distance = glm::length(offset);
    return {Ray{point_, offset / distance}, distance};
}

double SegmentShadowPyray::weight() const { return std::ldexp(1.0, -level_); }

double SegmentShadowPyray::length() const { return (s1_ - s0_) * glm::length(b_ - a_); }

double SegmentShadowPyray::nearestLightDistance() const {
    const Vec3 start = lightPoint(s0_), along = lightPoint(s1_) - start;
    const double f = std::clamp(glm::dot(point_ - start, along) / glm::dot(along, along), 0.0, 1.0);
    return glm::length(point_ - (start + f * along));
}

}  // namespace asos
