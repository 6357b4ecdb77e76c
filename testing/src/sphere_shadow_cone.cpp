#include "asos/testing/sphere_shadow_cone.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "asos/geometry/margins.hpp"
#include "asos/testing/direction_cone.hpp"

namespace asos {

namespace {

// The solid angle of the directions through the part of the concentric image
// of the square cell [a0, a1] x [b0, b1] (coordinates a = 2s - 1, b = 2t - 1)
// in the sector a > |b|, where the disc point has r = a and phi = (pi/4) b/a,
// for a tangent cone with tan(alpha) = tanAlpha. With tan(psi) = r tan(alpha),
// the solid angle element sin(psi) dpsi dphi is w(a) da db with
// w(a) = (pi/4) T^2 / (1 + a^2 T^2)^(3/2); the cell's extent in b at a,
// L(a) = |[b0, b1] n (-a, a)|, is piecewise linear, and w and a w have the
// closed antiderivatives (pi/4) T sin(psi) and -(pi/4) cos(psi).
double sectorSolidAngle(double a0, double a1, double b0, double b1, double T) {
    const double lo = std::max(a0, 0.0), hi = a1;
    if (!(hi > lo)) return 0.0;
    const auto extent = [&](double a) { return std::max(0.0, std::min(b1, a) - std::max(b0, -a)); };
    const auto sinPsiT = [&](double a) { return T * (a * T) / std::sqrt(1.0 + a * a * T * T); };
    // cos psi(u) - cos psi(v), without the cancellation of the difference.
    const auto cosDrop = [&](double u, double v) {
        const double su = std::sqrt(1.0 + u * u * T * T), sv = std::sqrt(1.0 + v * v * T * T);
        return (v - u) * (v + u) * T * T / ((su + sv) * su * sv);
    };
    std::array<double, 7> cuts = {lo, hi, b1, -b0, b0, -b1, 0.0};
    std::sort(cuts.begin(), cuts.end());
    double total = 0.0, u = lo;
    for (double cut : cuts) {
        const double v = std::min(cut, hi);
        if (!(v > u)) continue;
        const double slope = (extent(v) - extent(u)) / (v - u);
        const double offset = extent(u) - slope * u;
        total += offset * (sinPsiT(v) - sinPsiT(u)) + slope * cosDrop(u, v);
        u = v;
    }
    return 0.25 * kPi * total;
}

}  // namespace

std::optional<SphereShadowCone> SphereShadowCone::make(const Vec3& point, const Vec3& centre,
                                                       double radius, double tMin) {
    if (!(radius > 0.0)) throw std::invalid_argument("spherical light of radius <= 0");
    const double distance = glm::length(centre - point);
    if (!(distance > padUp(radius))) return std::nullopt;
    return SphereShadowCone(point, centre, radius, DiscCell{}, 0, tMin);
}

SphereShadowCone::SphereShadowCone(const Vec3& point, const Vec3& centre, double radius,
                                   const DiscCell& region, int level, double tMin)
    : point_(point), centre_(centre), radius_(radius), region_(region), level_(level), tMin_(tMin) {
    tangent_ = TangentCone::make(point_, centre_, radius_);
    alpha_ = std::asin(tangent_.sinAlpha);
    if (level_ > 0) bounds_ = polarBounds(region_);
    const double far = padUp(tangent_.distanceAtRadius(bounds_.r1, 1.0));
    if (level_ == 0) {
        cone_ = {point_, tangent_.frame.w, alpha_ + kConeAnglePad, tMin_, far};
        return;
    }
    // The piece lies in its polar rectangle, which lies in the convex hull
    // of its two inner corners and its outer arc (its angular span is at
    // most pi/2). The smallest cone of the four corner directions has its
    // axis inside the angular range, so its widest angle to the outer arc is
    // at an end of the arc: the cone holds the arc, hence the hull (a cone
    // below pi/2 meets the disc's plane in a convex set), hence the piece.
    // docs/accel.md has the details.
    const PolarBounds& b = bounds_;
    const std::array<Vec3, 4> corners = {directionAt(b.r0 * std::cos(b.phi0), b.r0 * std::sin(b.phi0)),
                                         directionAt(b.r0 * std::cos(b.phi1), b.r0 * std::sin(b.phi1)),
                                         directionAt(b.r1 * std::cos(b.phi0), b.r1 * std::sin(b.phi0)),
                                         directionAt(b.r1 * std::cos(b.phi1), b.r1 * std::sin(b.phi1))};
    const DirectionCone bound = smallestEnclosingCone(corners);
    cone_ = {point_, bound.axis, bound.halfAngle, tMin_, far};
}

std::array<SphereShadowCone, 4> SphereShadowCone::split() const {
    const double s[3] = {region_.s0, 0.5 * (region_.s0 + region_.s1), region_.s1};
    const double t[3] = {region_.t0, 0.5 * (region_.t0 + region_.t1), region_.t1};
    const auto piece = [&](int q) {
        const int i = q & 1, j = q >> 1;
        return SphereShadowCone(point_, centre_, radius_, DiscCell{s[i], s[i + 1], t[j], t[j + 1]}, level_ + 1,
                                tMin_);
    };
    return {piece(0), piece(1), piece(2), piece(3)};
}

double SphereShadowCone::distanceToLight(const Vec3& dir) const {
    const Vec3 toCentre = centre_ - point_;
    const double along = glm::dot(dir, toCentre);
    const Vec3 off = glm::cross(dir, toCentre);  // |off| = distance from the centre to the ray's line
    const double inside = radius_ * radius_ - glm::dot(off, off);
    return along - std::sqrt(std::max(0.0, inside));
}

BeamRay SphereShadowCone::central() const {
    if (level_ == 0) return tangent_.ray(point_, Vec2(0.0));
    return tangent_.ray(point_, concentricDisc(0.5 * (region_.s0 + region_.s1), 0.5 * (region_.t0 + region_.t1)));
}

BeamRay SphereShadowCone::sample(double xi1, double xi2) const {
    return tangent_.ray(point_, concentricDisc(region_.s0 + xi1 * (region_.s1 - region_.s0),
                                               region_.t0 + xi2 * (region_.t1 - region_.t0)));
}

double SphereShadowCone::weight() const { return std::ldexp(1.0, -2 * level_); }

double SphereShadowCone::area() const { return weight() * kPi * radius_ * radius_; }

double SphereShadowCone::solidAngle() const {
    // The four sectors of the concentric map, each turned onto a > |b| by
    // quarter turns of the cell (the map commutes with them).
    const double T = tangent_.tanAlpha;
    const double a0 = 2.0 * region_.s0 - 1.0, a1 = 2.0 * region_.s1 - 1.0;
    const double b0 = 2.0 * region_.t0 - 1.0, b1 = 2.0 * region_.t1 - 1.0;
    return sectorSolidAngle(a0, a1, b0, b1, T) + sectorSolidAngle(b0, b1, -a1, -a0, T) +
           sectorSolidAngle(-a1, -a0, -b1, -b0, T) + sectorSolidAngle(-b1, -b0, a0, a1, T);
}

double SphereShadowCone::nearestLightDistance() const {
    return padDown(tangent_.distanceAtRadius(bounds_.r0, -1.0));
}

}  // namespace asos
