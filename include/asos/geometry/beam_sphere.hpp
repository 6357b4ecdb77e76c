#pragma once
// The shadow cone toward a spherical light (paper: "Spherical Light
// Sources", Figure 5b): the cone from a shaded point tangent to the light's
// sphere, and its subdivision. The paper weights each sub-cone by I A, with A
// the area of a disc facing the point; so the pieces are regions of equal area
// of the light's apparent disc (any cross-section of the tangent cone
// perpendicular to its axis, in unit-disc coordinates): polar rectangles
// r in [r0, r1], phi in [phi0, phi1], split four ways into equal areas (the
// level-0 disc into its quadrants; below, 2 x 2, 1 x 4 or 4 x 1 in r^2 and
// phi, whichever keeps the pieces closest to square). Each piece is bounded
// by its own cone.
#include <array>
#include <optional>

#include "asos/geometry/beam.hpp"

namespace asos {

// r in [r0, r1] (unit-disc radius), phi in [phi0, phi1] (radians).
struct DiscRegion {
    double r0 = 0.0, r1 = 1.0, phi0 = 0.0, phi1 = 2.0 * kPi;
};

class SphereShadowCone {
public:
    // The level-0 cone from `point` (rays start at distance tMin) tangent to
    // the sphere (centre, radius > 0). Empty when the point is on or inside
    // the sphere. Throws std::invalid_argument for a radius <= 0.
    static std::optional<SphereShadowCone> make(const Vec3& point, const Vec3& centre, double radius,
                                                double tMin = 0.0);

    // The four level K+1 pieces, of equal area.
    std::array<SphereShadowCone, 4> split() const;

    // Toward the piece's area-median point (r^2 and phi at their middles;
    // the light's centre for the level-0 cone); distance: to the sphere.
    BeamRay central() const;
    // Toward the point r = sqrt(r0^2 + xi1 (r1^2 - r0^2)), phi = phi0 + xi2
    // (phi1 - phi0): uniform over the piece's area for uniform xi1, xi2.
    BeamRay sample(double xi1, double xi2) const;

    // The share of the apparent disc's area: 4^-level, exactly.
    double weight() const;
    // The piece's part of the disc of the light's radius facing the point:
    // weight() pi radius^2 (the paper's A in I A).
    double area() const;
    // The solid angle of the piece's directions (exact, closed form).
    double solidAngle() const;
    // The tangent cone's half-angle, asin(radius / distance to the centre).
    double tangentHalfAngle() const { return alpha_; }
    const DiscRegion& region() const { return region_; }
    const Vec3& point() const { return point_; }
    int level() const { return level_; }
    // The direction of the disc point (x, y) (unit-disc coordinates).
    Vec3 directionAt(double x, double y) const;
    // The distance along a unit direction from the point to the sphere
    // (rays of the tangent cone; at its rim, the distance to the tangent
    // point).
    double distanceToLight(const Vec3& dir) const;
    // The nearest distance at which a ray of the piece meets the light.
    double nearestLightDistance() const;

    // A cone holding every direction of the piece, for t in [tMin, the
    // farthest distance at which a ray of the piece meets the light].
    const Cone& cone() const { return cone_; }

private:
    SphereShadowCone(const Vec3& point, const Vec3& centre, double radius, const DiscRegion& region,
                     int level, double tMin);
    double distanceAtDiscRadius(double r, double widen) const;

    Vec3 point_{0.0}, centre_{0.0};
    double radius_ = 1.0;
    double alpha_ = 0.0;
    Frame frame_{};
    DiscRegion region_;
    int level_ = 0;
    double tMin_ = 0.0;
    Cone cone_;
};

}  // namespace asos
