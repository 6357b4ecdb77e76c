#pragma once
// The shadow pyray of a point light (paper: "Antialiased Point Light
// Sources", Figure 4): from the light through the footprint of an eye
// (sub-)pyray on the surface it hit, a quadrilateral (for instance where the
// eye pyray's corner rays meet the surface's tangent plane). It starts at the
// level of the eye pyray that made it and splits into the four bilinear
// quarters of the quadrilateral; a tracer that prefers the footprints of the
// eye sub-pyrays themselves makes those with make(..., level + 1). A
// reference for the tests: the renderer's point-light shadows
// (render/point_light_shadow.hpp) make their own pyrays.
#include <array>

#include "asos/geometry/beam.hpp"

namespace asos {

class QuadPyray {
public:
    // From `apex` to the quadrilateral corners[0..3] (in order around it),
    // rays starting at distance tMin. The cone is the smallest holding the
    // four corner rays; where they do not lie in an open hemisphere (the apex
    // in the quadrilateral's plane) it is the cone of all directions.
    static QuadPyray make(const Vec3& apex, const std::array<Vec3, 4>& corners, int level = 0,
                          double tMin = 0.0);

    // The four bilinear quarters, at level + 1: quarter q holds the corner
    // corners[q] (0: (0,0), 1: (1,0), 2: (1,1), 3: (0,1) in the bilinear
    // parameters), so they tile a planar quadrilateral.
    std::array<QuadPyray, 4> split() const;

    // Toward the bilinear centre; distance: to the quadrilateral (its plane
    // through the bilinear point, exact for a planar quadrilateral).
    BeamRay central() const { return toward(0.5, 0.5); }
    // Toward the bilinear point (xi1, xi2), xi in [0, 1).
    BeamRay sample(double xi1, double xi2) const { return toward(xi1, xi2); }

    // The share of the level-0 pyray's parameter square: 4^-level, exactly
    // (the share of the footprint's area when it is a parallelogram).
    double weight() const;
    int level() const { return level_; }
    const Vec3& apex() const { return apex_; }
    const std::array<Vec3, 4>& corners() const { return corners_; }
    // The bounding cone, for t in [tMin, the farthest corner].
    const Cone& cone() const { return cone_; }

private:
    QuadPyray(const Vec3& apex, const std::array<Vec3, 4>& corners, int level, double tMin);
    Vec3 bilinear(double s, double t) const;
    BeamRay toward(double s, double t) const;

    Vec3 apex_{0.0};
    std::array<Vec3, 4> corners_{};
    int level_ = 0;
    double tMin_ = 0.0;
    Cone cone_;
};

}  // namespace asos
