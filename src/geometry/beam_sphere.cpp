#include "asos/geometry/beam_sphere.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace asos {

namespace {

// How far a polar rectangle is from square: its radial extent against its
// arc length at the area-median radius, as a ratio >= 1.
double aspect(const DiscRegion& d) {
    const double radial = d.r1 - d.r0;
    const double arc = std::sqrt(0.5 * (d.r0 * d.r0 + d.r1 * d.r1)) * (d.phi1 - d.phi0);
    return std::max(radial / arc, arc / radial);
}

// The radius splitting [r0, r1] at fraction f of its area.
double areaRadius(double r0, double r1, double f) {
    return std::sqrt(r0 * r0 + f * (r1 * r1 - r0 * r0));
}

std::array<DiscRegion, 4> splitRegion(const DiscRegion& d, int level) {
    const auto phiAt = [&](double f) { return d.phi0 + f * (d.phi1 - d.phi0); };
    if (level == 0) {
        // The whole disc: its quadrants.
        return {DiscRegion{0.0, 1.0, 0.0, 0.5 * kPi}, DiscRegion{0.0, 1.0, 0.5 * kPi, kPi},
                DiscRegion{0.0, 1.0, kPi, 1.5 * kPi}, DiscRegion{0.0, 1.0, 1.5 * kPi, 2.0 * kPi}};
    }
    const double rm = areaRadius(d.r0, d.r1, 0.5), pm = phiAt(0.5);
    const std::array<DiscRegion, 4> grid = {DiscRegion{d.r0, rm, d.phi0, pm}, DiscRegion{rm, d.r1, d.phi0, pm},
                                            DiscRegion{d.r0, rm, pm, d.phi1}, DiscRegion{rm, d.r1, pm, d.phi1}};
    const double p1 = phiAt(0.25), p3 = phiAt(0.75);
    const std::array<DiscRegion, 4> wedges = {DiscRegion{d.r0, d.r1, d.phi0, p1}, DiscRegion{d.r0, d.r1, p1, pm},
                                              DiscRegion{d.r0, d.r1, pm, p3}, DiscRegion{d.r0, d.r1, p3, d.phi1}};
    const double r1 = areaRadius(d.r0, d.r1, 0.25), r3 = areaRadius(d.r0, d.r1, 0.75);
    const std::array<DiscRegion, 4> rings = {DiscRegion{d.r0, r1, d.phi0, d.phi1}, DiscRegion{r1, rm, d.phi0, d.phi1},
                                             DiscRegion{rm, r3, d.phi0, d.phi1}, DiscRegion{r3, d.r1, d.phi0, d.phi1}};
    const auto worst = [](const std::array<DiscRegion, 4>& pieces) {
        double w = 0.0;
        for (const DiscRegion& p : pieces) w = std::max(w, aspect(p));
        return w;
    };
    const double g = worst(grid), w = worst(wedges), r = worst(rings);
    if (g <= w && g <= r) return grid;
    return w <= r ? wedges : rings;
}

}  // namespace

std::optional<SphereShadowCone> SphereShadowCone::make(const Vec3& point, const Vec3& centre,
                                                       double radius, double tMin) {
    if (!(radius > 0.0)) throw std::invalid_argument("spherical light of radius <= 0");
    const double distance = glm::length(centre - point);
    if (!(distance > radius * (1.0 + 1e-12))) return std::nullopt;
    return SphereShadowCone(point, centre, radius, DiscRegion{}, 0, tMin);
}

SphereShadowCone::SphereShadowCone(const Vec3& point, const Vec3& centre, double radius,
                                   const DiscRegion& region, int level, double tMin)
    : point_(point), centre_(centre), radius_(radius), region_(region), level_(level), tMin_(tMin) {
    const Vec3 toCentre = centre_ - point_;
    const double distance = glm::length(toCentre);
    alpha_ = std::asin(std::min(1.0, radius_ / distance));
    frame_ = Frame::around(toCentre / distance);
    const double far = distanceAtDiscRadius(region_.r1, 1.0) * (1.0 + 1e-12);
    if (level_ == 0) {
        cone_ = {point_, frame_.w, alpha_ + kConeAnglePad, tMin_, far};
        return;
    }
    // The piece lies in the convex hull of its two inner corners and its
    // outer arc (its angular span is at most pi/2). The smallest cone of the
    // four corner directions has its axis inside the piece's angular range,
    // so its widest angle to the outer arc is at an end of the arc: the cone
    // holds the arc, hence the hull (a cone below pi/2 meets the disc's plane
    // in a convex set), hence the piece. docs/accel.md has the details.
    const std::array<Vec3, 4> corners = {
        directionAt(region_.r0 * std::cos(region_.phi0), region_.r0 * std::sin(region_.phi0)),
        directionAt(region_.r0 * std::cos(region_.phi1), region_.r0 * std::sin(region_.phi1)),
        directionAt(region_.r1 * std::cos(region_.phi0), region_.r1 * std::sin(region_.phi0)),
        directionAt(region_.r1 * std::cos(region_.phi1), region_.r1 * std::sin(region_.phi1))};
    const DirectionCone bound = smallestEnclosingCone(corners);
    cone_ = {point_, bound.axis, bound.halfAngle, tMin_, far};
}

std::array<SphereShadowCone, 4> SphereShadowCone::split() const {
    const std::array<DiscRegion, 4> pieces = splitRegion(region_, level_);
    const auto piece = [&](int i) {
        return SphereShadowCone(point_, centre_, radius_, pieces[i], level_ + 1, tMin_);
    };
    return {piece(0), piece(1), piece(2), piece(3)};
}

Vec3 SphereShadowCone::directionAt(double x, double y) const {
    const double tanAlpha = std::tan(alpha_);
    return glm::normalize(frame_.toWorld(tanAlpha * x, tanAlpha * y, 1.0));
}

double SphereShadowCone::distanceToLight(const Vec3& dir) const {
    const Vec3 toCentre = centre_ - point_;
    const double along = glm::dot(dir, toCentre);
    const Vec3 off = glm::cross(dir, toCentre);  // |off| = distance from the centre to the ray's line
    const double inside = radius_ * radius_ - glm::dot(off, off);
    return along - std::sqrt(std::max(0.0, inside));
}

double SphereShadowCone::distanceAtDiscRadius(double r, double widen) const {
    const double distance = glm::length(centre_ - point_);
    const double tanPsi = std::tan(alpha_) * r;
    const double cosPsi = 1.0 / std::sqrt(1.0 + tanPsi * tanPsi);
    const double sinPsi = tanPsi * cosPsi;
    // Near the rim the distance is a square root of a small difference, so
    // a direction off by rounding (1e-16 rad) moves it by ~1e-8 relative;
    // `widen` > 0 (< 0) moves the result out (in) past that uncertainty.
    const double inside =
        radius_ * radius_ - distance * distance * sinPsi * sinPsi - widen * 1e-14 * distance * distance;
    return distance * cosPsi - std::sqrt(std::max(0.0, inside));
}

BeamRay SphereShadowCone::central() const {
    Vec3 dir = frame_.w;
    if (level_ > 0) {
        const double r = areaRadius(region_.r0, region_.r1, 0.5);
        const double phi = 0.5 * (region_.phi0 + region_.phi1);
        dir = directionAt(r * std::cos(phi), r * std::sin(phi));
    }
    return {Ray{point_, dir}, distanceToLight(dir)};
}

BeamRay SphereShadowCone::sample(double xi1, double xi2) const {
    const double r = areaRadius(region_.r0, region_.r1, xi1);
    const double phi = region_.phi0 + xi2 * (region_.phi1 - region_.phi0);
    const Vec3 dir = directionAt(r * std::cos(phi), r * std::sin(phi));
    return {Ray{point_, dir}, distanceToLight(dir)};
}

double SphereShadowCone::weight() const { return std::ldexp(1.0, -2 * level_); }

double SphereShadowCone::area() const { return weight() * kPi * radius_ * radius_; }

double SphereShadowCone::solidAngle() const {
    // The directions of disc radius r make tan(psi) = r tan(alpha) with the
    // axis; integrating the solid angle element over r and phi gives
    // (phi1 - phi0) (cos psi(r0) - cos psi(r1)).
    const double tanAlpha = std::tan(alpha_);
    const auto cosPsi = [&](double r) { return 1.0 / std::sqrt(1.0 + tanAlpha * tanAlpha * r * r); };
    return (region_.phi1 - region_.phi0) * (cosPsi(region_.r0) - cosPsi(region_.r1));
}

double SphereShadowCone::nearestLightDistance() const {
    return distanceAtDiscRadius(region_.r0, -1.0) * (1.0 - 1e-12);
}

}  // namespace asos
