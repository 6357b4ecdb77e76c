#pragma once
// Where the shadow beams toward an area light start: the apex (the shaded
// point, or a point behind the surface) and the distance their rays start
// at. Every light form's beam makes its rays toward the light's points and
// the cones about its pieces here, alike.
#include <cmath>

#include "asos/geometry/beam.hpp"

namespace asos {

// A piece's bounding cone and the tangent of its half-angle before padding
// (NaN for the cone of all directions): LightPiece::cone and tanHalf.
struct PieceCone {
    Cone cone;
    double tanHalf;
};

struct BeamApex {
    Vec3 point{0.0};
    double tMin = 0.0;

    // The ray toward a point of the light, and the distance to it. Inline:
    // the tracer makes one per point sample.
    __attribute__((always_inline)) BeamRay toward(const Vec3& target) const {
        const Vec3 offset = target - point;
        // glm::length's sqrt(dot) written out: GCC left glm::length a call.
        const double distance = std::sqrt(dot3(offset, offset));
        return {Ray{point, offset / distance}, distance};
    }

    // The cone about unit `axis` through the widest of `directions` (of any
    // length, each within a right angle of the axis, or the cone is of all
    // directions), reaching `farthest`: one square root and one arctangent.
    // A cone about a piece's central ray holds the piece when the piece's
    // corner rays lie within it (the cone is convex, its half-angle below
    // pi/2).
    PieceCone coneAbout(const Vec3& axis, const Vec3* directions, int count, double farthest) const;
};

// The ray from `origin` toward `target` and the distance to it, with no
// direction where the two coincide: a grid point of a light seen from a
// shaded point (render/grid_light.hpp).
inline BeamRay rayToward(const Vec3& origin, const Vec3& target) {
    const Vec3 offset = target - origin;
    const double distance = glm::length(offset);
    return {Ray{origin, distance > 0.0 ? offset / distance : Vec3(0.0)}, distance};
}

}  // namespace asos
