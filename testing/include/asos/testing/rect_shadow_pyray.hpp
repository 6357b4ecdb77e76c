#pragma once
// The shadow pyray toward a rectangular light (paper: "Rectangular Light
// Sources", Figure 5a): from a shaded point to the four corners of the light,
// or of a sub-rectangle of it at level K, bounded by a cone and split into the
// four quarters of the rectangle when marginal. Each piece carries its share
// of the light's area, and the tracer weights it by I A cos(theta) along the
// central ray. A reference, each piece a value of its own with the smallest
// cone of its corner rays: the renderer's beams (lights/rectangle_light.hpp)
// make the same pieces for speed; the tests compare them.
#include <array>
#include <optional>

#include "asos/geometry/beam.hpp"
#include "asos/lights/rectangle_light.hpp"

namespace asos {

// [s0, s1] x [t0, t1] of the light's parameter square.
struct RectRegion {
    double s0 = 0.0, t0 = 0.0, s1 = 1.0, t1 = 1.0;
};

class RectShadowPyray {
public:
    // The level-0 pyray from `point` (rays start at distance tMin, to leave
    // the shaded surface) to the whole light. Empty when the point lies in
    // the light's plane (the light is seen edge on and sends it nothing).
    // Throws std::invalid_argument for a light of zero area.
    static std::optional<RectShadowPyray> make(const Vec3& point, const RectangleLight& light,
                                               double tMin = 0.0);

    // The four level K+1 quarters of the rectangle: bit 0 the upper s half,
    // bit 1 the upper t half.
    std::array<RectShadowPyray, 4> split() const;

    // Toward the centre of the (sub-)rectangle; distance: to the light.
    BeamRay central() const { return toward(0.5, 0.5); }
    // Toward the point (s0 + xi1 (s1 - s0), t0 + xi2 (t1 - t0)), uniform over
    // the rectangle's area for uniform xi1, xi2 in [0, 1).
    BeamRay sample(double xi1, double xi2) const { return toward(xi1, xi2); }

    // The share of the whole light's area: 4^-level, exactly.
    double weight() const;
    // The area of the (sub-)rectangle: weight() times the light's area.
    double area() const;
    // |cos theta| between the light's normal and the central ray (the
    // paper's I A cos(theta)).
    double cosTheta() const;
    // The solid angle the (sub-)rectangle subtends at the point.
    double solidAngle() const;
    Vec3 lightNormal() const;
    std::array<Vec3, 4> corners() const;  // (s0,t0), (s1,t0), (s1,t1), (s0,t1)
    const RectRegion& region() const { return region_; }
    const Vec3& point() const { return point_; }
    int level() const { return level_; }
    // The nearest distance from the point to the (sub-)rectangle: no ray of
    // the pyray reaches the light before it.
    double nearestLightDistance() const;

    // The smallest cone holding the four corner rays (and so the pyray),
    // from the point, for t in [tMin, the farthest corner].
    const Cone& cone() const { return cone_; }

private:
    RectShadowPyray(const Vec3& point, const RectangleLight& light, const RectRegion& region,
                    int level, double tMin);
    Vec3 lightPoint(double s, double t) const {
        return light_.corner + s * light_.edgeA + t * light_.edgeB;
    }
    BeamRay toward(double xi1, double xi2) const;

    Vec3 point_{0.0};
    RectangleLight light_;
    RectRegion region_;
    int level_ = 0;
    double tMin_ = 0.0;
    Cone cone_;
};

}  // namespace asos
