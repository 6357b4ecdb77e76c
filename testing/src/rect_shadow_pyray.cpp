#include "asos/testing/rect_shadow_pyray.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "asos/geometry/margins.hpp"
#include "asos/testing/direction_cone.hpp"
#include "asos/testing/solid_angle.hpp"

namespace asos {

std::optional<RectShadowPyray> RectShadowPyray::make(const Vec3& point, const RectangleLight& light,
                                                     double tMin) {
    const Vec3 normal = glm::cross(light.edgeA, light.edgeB);
    const double area = glm::length(normal);
    if (!(area > 0.0)) throw std::invalid_argument("rectangular light of zero area");
    // Distance of the point from the light's plane, against the light's size
    // and position: below rounding, the point is in the plane.
    const double height = std::abs(glm::dot(point - light.corner, normal)) / area;
    const double scale = glm::length(light.edgeA) + glm::length(light.edgeB) +
                         glm::length(point - light.corner);
    if (!(height > kThousandsOfUlps * scale)) return std::nullopt;
    return RectShadowPyray(point, light, RectRegion{}, 0, tMin);
}

RectShadowPyray::RectShadowPyray(const Vec3& point, const RectangleLight& light,
                                 const RectRegion& region, int level, double tMin)
    : point_(point), light_(light), region_(region), level_(level), tMin_(tMin) {
    const std::array<Vec3, 4> c = corners();
    std::array<Vec3, 4> directions;
    double farthest = 0.0;
    for (int i = 0; i < 4; ++i) {
        const Vec3 offset = c[i] - point_;
        const double distance = glm::length(offset);
        farthest = std::max(farthest, distance);
        directions[i] = offset / distance;
    }
    // The point is off the light's plane, so the corner directions lie in an
    // open hemisphere and the cone holds the pyramid they span.
    const DirectionCone bound = smallestEnclosingCone(directions);
    cone_ = {point_, bound.axis, bound.halfAngle, tMin_, padUp(farthest)};
}

std::array<RectShadowPyray, 4> RectShadowPyray::split() const {
    const double sm = 0.5 * (region_.s0 + region_.s1), tm = 0.5 * (region_.t0 + region_.t1);
    const auto quarter = [&](int q) {
        const RectRegion r{(q & 1) ? sm : region_.s0, (q & 2) ? tm : region_.t0,
                           (q & 1) ? region_.s1 : sm, (q & 2) ? region_.t1 : tm};
        return RectShadowPyray(point_, light_, r, level_ + 1, tMin_);
    };
    return {quarter(0), quarter(1), quarter(2), quarter(3)};
}

BeamRay RectShadowPyray::toward(double xi1, double xi2) const {
    const Vec3 target = lightPoint(region_.s0 + xi1 * (region_.s1 - region_.s0),
                                   region_.t0 + xi2 * (region_.t1 - region_.t0));
    const Vec3 offset = target - point_;
    const double distance = glm::length(offset);
    return {Ray{point_, offset / distance}, distance};
}

double RectShadowPyray::weight() const { return std::ldexp(1.0, -2 * level_); }

double RectShadowPyray::area() const {
    return weight() * glm::length(glm::cross(light_.edgeA, light_.edgeB));
}

Vec3 RectShadowPyray::lightNormal() const {
    return glm::normalize(glm::cross(light_.edgeA, light_.edgeB));
}

double RectShadowPyray::cosTheta() const {
    return std::abs(glm::dot(lightNormal(), central().ray.dir));
}

double RectShadowPyray::solidAngle() const {
    const std::array<Vec3, 4> c = corners();
    return solidAngleOfPolygon(point_, c);
}

std::array<Vec3, 4> RectShadowPyray::corners() const {
    return {lightPoint(region_.s0, region_.t0), lightPoint(region_.s1, region_.t0),
            lightPoint(region_.s1, region_.t1), lightPoint(region_.s0, region_.t1)};
}

double RectShadowPyray::nearestLightDistance() const {
    // The closest point of the parallelogram: project onto its plane in
    // (s, t) coordinates and clamp to the region; where the projection
    // falls outside, the closest point lies on an edge, found by clamping
    // along each edge in turn.
    const std::array<Vec3, 4> c = corners();
    const auto segmentDistance = [&](const Vec3& a, const Vec3& b) {
        const Vec3 ab = b - a;
        const double f = std::clamp(glm::dot(point_ - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
        return glm::length(point_ - (a + f * ab));
    };
    const Vec3 ea = c[1] - c[0], eb = c[3] - c[0];
    const Vec3 n = glm::cross(ea, eb);
    const Vec3 rel = point_ - c[0];
    // Coordinates of the projection along ea and eb.
    const double s = glm::dot(glm::cross(rel, eb), n) / glm::dot(n, n);
    const double t = glm::dot(glm::cross(ea, rel), n) / glm::dot(n, n);
    if (s >= 0.0 && s <= 1.0 && t >= 0.0 && t <= 1.0) {
        return std::abs(glm::dot(rel, n)) / glm::length(n);
    }
    return std::min({segmentDistance(c[0], c[1]), segmentDistance(c[1], c[2]),
                     segmentDistance(c[2], c[3]), segmentDistance(c[3], c[0])});
}

}  // namespace asos
