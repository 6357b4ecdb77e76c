#pragma once
// The cone from a point tangent to a sphere (paper: "Spherical Light
// Sources", Figure 5b), as a map from the unit disc (the cone's
// cross-section perpendicular to its axis) onto rays: a spherical light's
// beam pieces and its grid's points (lights/sphere_light.hpp) make their
// rays by ray(), so that they are the same rays bit for bit.
#include <algorithm>
#include <cmath>

#include "asos/geometry/beam.hpp"
#include "asos/geometry/frame.hpp"

namespace asos {

struct TangentCone {
    Frame frame{};                // w toward the centre
    double distance = 1.0;        // to the centre, d
    double radius = 0.0;          // the sphere's, r
    double tanAlpha = 0.0, sinAlpha = 0.0;
    double cos2Alpha = 1.0;       // cos^2 alpha, as (d - r)(d + r) / d^2
    // Requires distance > radius > 0.
    static TangentCone make(const Vec3& point, const Vec3& centre, double radius);
    // The cone's half-angle, alpha.
    double halfAngle() const { return std::asin(sinAlpha); }
    // The rays end on the sphere's near cap, inside the tangent circle: at
    // d cos^2 alpha along the axis, of radius d cos alpha sin alpha, within
    // the tangent length d cos alpha.
    EndCircle endCircle() const {
        const double cosAlpha = std::sqrt(cos2Alpha);
        return {distance * cos2Alpha, distance * cosAlpha * sinAlpha, distance * cosAlpha};
    }
    // The ray from `origin` (the point) through the disc point (x, y), with
    // rho2 = x^2 + y^2 <= 1 and rim = sqrt(1 - rho2) given: the direction
    // (w + tan alpha (x u + y v)) cos psi, cos psi = 1 / sqrt(1 + tan^2 alpha
    // rho2), and the distance to the sphere along it, d cos psi (1 - sin alpha
    // rim), computed as d cos psi (cos^2 alpha + sin^2 alpha rho2) / (1 + sin
    // alpha rim) (the same, without the difference that loses digits where
    // the point is near the sphere).
    BeamRay ray(const Vec3& origin, double x, double y, double rho2, double rim) const {
        const double cosPsi = 1.0 / std::sqrt(1.0 + tanAlpha * tanAlpha * rho2);
        const Vec3 dir = frame.toWorld(tanAlpha * x, tanAlpha * y, 1.0) * cosPsi;
        const double t = distance * cosPsi * (cos2Alpha + sinAlpha * sinAlpha * rho2) / (1.0 + sinAlpha * rim);
        return {Ray{origin, dir}, t};
    }
    // A disc point's rho2 and rim, as ray(origin, p) takes them (tables of
    // disc points keep them made so, for the same rays bit for bit).
    struct Radial {
        double rho2, rim;
    };
    static Radial radial(const Vec2& p) {
        const double rho2 = std::min(1.0, p.x * p.x + p.y * p.y);
        return {rho2, std::sqrt(1.0 - rho2)};
    }
    BeamRay ray(const Vec3& origin, const Vec2& p) const {
        const Radial q = radial(p);
        return ray(origin, p.x, p.y, q.rho2, q.rim);
    }
    // The distance to the sphere along the rays at disc radius r (tan psi = r
    // tan alpha) by the direct formula. Near the rim it is the square root of
    // a small difference, so a direction off by rounding (1e-16 rad) moves
    // it by ~1e-8 relative; `widen` > 0 (< 0) moves the result out (in) past
    // that uncertainty: the bounds of the beams' t-ranges.
    double distanceAtRadius(double r, double widen) const;
};

}  // namespace asos
