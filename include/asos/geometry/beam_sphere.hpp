#pragma once
// The shadow cone toward a spherical light (paper: "Spherical Light
// Sources", Figure 5b): the cone from a shaded point tangent to the light's
// sphere, and its subdivision. The paper weights each sub-cone by I A, with A
// the area of a disc facing the point; so the pieces are regions of equal area
// of the light's apparent disc (any cross-section of the tangent cone
// perpendicular to its axis, in unit-disc coordinates). They are the images of
// the quadtree's cells of the unit square [0, 1]^2 under Shirley and Chiu's
// equal-area concentric map, the map the grid method places its points by
// (render/grid_light.hpp): so a piece's central ray at level K is the grid's
// point of the 2^K x 2^K array, and both methods sample the same points where
// ASOS subdivides to the bottom. Each piece is bounded by its own cone, made
// from the polar rectangle (radius and angle ranges) that holds its image.
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "asos/geometry/beam.hpp"
#include "asos/geometry/frame.hpp"

namespace asos {

// Shirley and Chiu's concentric map from [0, 1]^2 onto the unit disc: equal
// areas to equal areas, square rings to circles, rays from the square's
// centre to rays from the disc's.
Vec2 concentricDisc(double s, double t);

// A cell of the unit square, s in [s0, s1], t in [t0, t1].
struct DiscCell {
    double s0 = 0.0, s1 = 1.0, t0 = 0.0, t1 = 1.0;
};

// The polar rectangle r in [r0, r1], phi in [phi0, phi1] (phi1 - phi0 <=
// pi / 2) that holds the concentric image of a cell lying in one quadrant of
// the square (every cell but the whole square); the whole square's is the
// whole disc, phi in [0, 2 pi]. The radius of the image of (s, t) is
// max(|2s - 1|, |2t - 1|), and its angle grows with the angle of (2s - 1,
// 2t - 1): the bounds are exact (the cell's corners and its nearest point to
// the centre attain them).
struct PolarBounds {
    double r0 = 0.0, r1 = 1.0, phi0 = 0.0, phi1 = 2.0 * kPi;
};
PolarBounds polarBounds(const DiscCell& cell);
// Its r0 alone: the least radius of the cell's image.
double innerRadius(const DiscCell& cell);

// The cone from a point tangent to a sphere, as a map from the unit disc (the
// cone's cross-section) onto rays: the shadow cone below, the grid's points
// and the renderer's beams all make their rays by ray(), so that they are the
// same rays bit for bit.
struct TangentCone {
    Frame frame{};                // w toward the centre
    double distance = 1.0;        // to the centre, d
    double radius = 0.0;          // the sphere's, r
    double tanAlpha = 0.0, sinAlpha = 0.0;
    double cos2Alpha = 1.0;       // cos^2 alpha, as (d - r)(d + r) / d^2
    // Requires distance > radius > 0.
    static TangentCone make(const Vec3& point, const Vec3& centre, double radius);
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
