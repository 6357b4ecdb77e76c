#pragma once
// A flat disc facing a point: centred at distance d along the frame's w from
// the point, perpendicular to w, of radius r (POV-Ray's `circular orient`
// area light, lights/oriented_disc_light.hpp). As TangentCone, a map from the
// unit disc onto rays: the disc's point (x, y) is r (x u + y v) from its
// centre, so its direction from the point is w + tan alpha (x u + y v) with
// tan alpha = r / d, and the same pieces and tables serve both
// (lights/disc_beam.hpp).
#include <cmath>

#include "asos/geometry/beam.hpp"
#include "asos/geometry/frame.hpp"
#include "asos/geometry/margins.hpp"

namespace asos {

struct FacingDisc {
    Frame frame{};           // w toward the centre
    double distance = 1.0;   // to the centre, d
    double tanAlpha = 0.0;   // r / d

    // `frame.w` the unit direction from the point to the centre, at
    // `distance` > 0.
    static FacingDisc make(const Frame& frame, double distance, double radius) {
        return {frame, distance, radius / distance};
    }
    // The angle from w to the disc's rim.
    double halfAngle() const { return std::atan(tanAlpha); }
    // The rays end on the disc itself: at d, radius d tan alpha, within the
    // distance to its rim.
    EndCircle endCircle() const {
        return {distance, distance * tanAlpha, distance * std::sqrt(1.0 + tanAlpha * tanAlpha)};
    }
    // The ray from `origin` (the point) through the disc point (x, y), with
    // rho2 = x^2 + y^2 given (TangentCone::ray's arguments; the rim is not
    // needed): direction (w + tan alpha (x u + y v)) cos psi, cos psi = 1 /
    // sqrt(1 + tan^2 alpha rho2), and the distance d / cos psi.
    BeamRay ray(const Vec3& origin, double x, double y, double rho2, double) const {
        const double cosPsi = 1.0 / std::sqrt(1.0 + tanAlpha * tanAlpha * rho2);
        const Vec3 dir = frame.toWorld(tanAlpha * x, tanAlpha * y, 1.0) * cosPsi;
        return {Ray{origin, dir}, distance / cosPsi};
    }
    BeamRay ray(const Vec3& origin, const Vec2& p) const { return ray(origin, p.x, p.y, p.x * p.x + p.y * p.y, 0.0); }
    // The distance to the disc along the rays at disc radius r, moved out
    // (`widen` > 0) or in (< 0) past its rounding.
    double distanceAtRadius(double r, double widen) const {
        const double tanPsi = tanAlpha * r;
        return distance * std::sqrt(1.0 + tanPsi * tanPsi) * (1.0 + widen * kThousandsOfUlps);
    }
};

}  // namespace asos
