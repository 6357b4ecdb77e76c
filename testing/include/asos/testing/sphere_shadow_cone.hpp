#pragma once
// The shadow cone toward a spherical light (paper: "Spherical Light
// Sources", Figure 5b), as a reference: the cone from a shaded point tangent
// to the light's sphere, and its subdivision, each piece a value of its own
// with the smallest cone of its polar rectangle's corners. The renderer's
// beams (lights/sphere_light.hpp) make the same pieces for speed; the tests
// compare them. The paper weights each sub-cone by I A, with A the area of a
// disc facing the point; so the pieces are regions of equal area of the
// light's apparent disc (any cross-section of the tangent cone perpendicular
// to its axis, in unit-disc coordinates). They are the images of the
// quadtree's cells of the unit square [0, 1]^2 under Shirley and Chiu's
// equal-area concentric map (geometry/concentric_disc.hpp), the map the grid
// method places its points by: so a piece's central ray at level K is the
// grid's point of the 2^K x 2^K array, and both methods sample the same
// points where ASOS subdivides to the bottom.
#include <array>
#include <optional>

#include "asos/geometry/concentric_disc.hpp"
#include "asos/geometry/tangent_cone.hpp"

namespace asos {

class SphereShadowCone {
public:
    // The level-0 cone from `point` (rays start at distance tMin) tangent to
    // the sphere (centre, radius > 0). Empty when the point is on or inside
    // the sphere. Throws std::invalid_argument for a radius <= 0.
    static std::optional<SphereShadowCone> make(const Vec3& point, const Vec3& centre, double radius,
                                                double tMin = 0.0);

    // The four level K+1 pieces, of equal area: the images of the cell's
    // quarters, in the order s-half + 2 t-half.
    std::array<SphereShadowCone, 4> split() const;

    // Toward the image of the cell's centre (the light's centre for the
    // level-0 cone); distance: to the sphere.
    BeamRay central() const;
    // Toward the image of (s0 + xi1 (s1 - s0), t0 + xi2 (t1 - t0)): uniform
    // over the piece's area for uniform xi1, xi2.
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
    const DiscCell& region() const { return region_; }
    // The polar rectangle holding the piece's image.
    const PolarBounds& bounds() const { return bounds_; }
    const Vec3& point() const { return point_; }
    int level() const { return level_; }
    // The direction of the disc point (x, y) (unit-disc coordinates).
    Vec3 directionAt(double x, double y) const { return tangent_.ray(point_, Vec2(x, y)).ray.dir; }
    // The ray through the disc point (x, y), to the sphere (TangentCone::ray).
    BeamRay rayAt(double x, double y) const { return tangent_.ray(point_, Vec2(x, y)); }
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
    SphereShadowCone(const Vec3& point, const Vec3& centre, double radius, const DiscCell& region, int level,
                     double tMin);

    Vec3 point_{0.0}, centre_{0.0};
    double radius_ = 1.0;
    double alpha_ = 0.0;
    TangentCone tangent_;
    DiscCell region_;
    PolarBounds bounds_;
    int level_ = 0;
    double tMin_ = 0.0;
    Cone cone_;
};

}  // namespace asos
