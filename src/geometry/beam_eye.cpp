#include "asos/geometry/beam_eye.hpp"

#include <algorithm>
#include <cmath>

#include "asos/geometry/margins.hpp"

namespace asos {

namespace {

// How far behind the orthographic prism the cone's apex goes, relative to
// the depth over which the cone must stay close to the prism: the cone's
// radius grows from the prism's radius rho at the near end to
// rho (1 + depth / standoff) at the far end.
constexpr double kStandoffPerDepth = 16.0;
// With no far end, the half-angle is fixed instead: tan = 2^-12.
constexpr double kUnboundedStandoffPerRadius = 4096.0;

}  // namespace

double EyePyray::weight() const { return std::ldexp(1.0, -2 * level_); }

EyePyray::EyePyray(const ImageSquare& square, int level, const Ray& central,
                   const std::array<Ray, 4>& corners, double tMin, double tMax)
    : square_(square), level_(level), central_(central), corners_(corners), tMin_(tMin), tMax_(tMax) {
    const bool sameOrigin = std::all_of(corners.begin(), corners.end(),
                                        [&](const Ray& r) { return r.origin == central.origin; });
    const bool sameDirection = std::all_of(corners.begin(), corners.end(),
                                           [&](const Ray& r) { return r.dir == central.dir; });
    const Vec3 axis = glm::normalize(central.dir);
    if (sameOrigin) {
        projection_ = Projection::Perspective;
        double largest = 0.0;
        for (const Ray& r : corners) largest = std::max(largest, angleBetween(axis, r.dir));
        if (!(largest < 0.5 * kPi))
            throw std::invalid_argument("eye pyray: a square spanning half the directions or more");
        cone_ = {central.origin, axis, largest + kConeAnglePad, tMin, tMax};
        return;
    }
    if (!sameDirection)
        throw std::invalid_argument(
            "eye pyray: camera rays share neither their origin (perspective) nor their direction "
            "(orthographic)");
    projection_ = Projection::Orthographic;
    // The prism: points o + t d, o in the parallelogram of the corner origins,
    // t in [tMin, tMax]. Each point lies at axial offset s + t and radial
    // distance at most rho from the central ray (its origin c), where s is the
    // offset of o along d (between the corners' extremes: o is affine).
    double rho = 0.0, sMin = 0.0, sMax = 0.0;
    for (const Ray& r : corners) {
        const Vec3 offset = r.origin - central.origin;
        const double s = glm::dot(offset, axis);
        rho = std::max(rho, glm::length(offset - s * axis));
        sMin = std::min(sMin, s);
        sMax = std::max(sMax, s);
    }
    // The apex sits on the central line, `standoff` before the nearest prism
    // point (axially). A prism point x then has axial distance A >= standoff
    // from the apex and radial distance <= rho, so its angle from the axis is
    // at most atan(rho / standoff): inside the cone. Its distance from the
    // apex lies in [A, A / cos(halfAngle)], which the t-range covers.
    const double depth = (tMax - tMin) + (sMax - sMin);
    double standoff = std::isfinite(depth) ? kStandoffPerDepth * depth : kUnboundedStandoffPerRadius * rho;
    standoff = std::max({standoff, kUnboundedStandoffPerRadius * rho, kPositiveFloor});
    const double halfAngle = std::atan2(rho, standoff) + kConeAnglePad;
    const Vec3 apex = central.origin + (sMin + tMin - standoff) * axis;
    const double farAxial = standoff + (sMax - sMin) + (tMax - tMin);
    const double far = std::isfinite(farAxial) ? padUp(farAxial / std::cos(halfAngle)) : kInfinity;
    cone_ = {apex, axis, halfAngle, padDown(standoff), far};
}

}  // namespace asos
