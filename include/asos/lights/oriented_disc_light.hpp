#pragma once
// POV-Ray's `circular orient` area light (trace.cpp, TraceAreaLightShadowRay):
// a flat disc of `radius` (half the first axis's length) about `centre`,
// turned to face each shaded point: perpendicular to the direction from the
// point to the centre, its first axis cross(w, z) (cross(w, y) where w is
// within 0.01 of the z axis) and its second cross(w, first), both of the
// first axis's length. POV-Ray's lattice of n1 x n2 points, from edge to edge
// of the square of those axes, is squeezed onto the disc by POV-Ray's map
// (geometry/concentric_disc.hpp: square rings to circles, angles kept, a
// thousandth of the square shifted toward +u, +v). As every light form
// (lights/light_form.hpp) it answers:
//   - its beam from a point: the disc's directions, cut into the images of
//     the square's quadtree cells under POV-Ray's map (so that equal shares
//     are POV-Ray's density without the shift), lights/disc_beam.hpp;
//   - its grid's points seen from a point: POV-Ray's lattice, exactly;
//   - its emitted radiance: the same along every direction (POV-Ray's
//     points are isotropic).
// With `asos { emitter panel }` a `circular orient` light is the paper's
// sphere instead (lights/sphere_light.hpp).
#include <cmath>
#include <optional>

#include "asos/geometry/bounds.hpp"
#include "asos/geometry/concentric_disc.hpp"
#include "asos/geometry/facing_disc.hpp"
#include "asos/geometry/frame.hpp"
#include "asos/lights/beam_apex.hpp"
#include "asos/lights/disc_beam.hpp"
#include "asos/lights/round_light.hpp"

namespace asos {

// POV-Ray's axes of an oriented area light seen along unit `w` (toward the
// light's centre): u and v of unit length, w the given direction.
Frame povrayOrientFrame(const Vec3& w);

// The disc turns with the point: its bounds are the ball's.
struct OrientedDiscLight : RoundLight {
    static constexpr const char* kName = "oriented disc";

    // The ray from the apex through p meets the disc facing the apex.
    bool beamHolds(const Vec3& apex, const Vec3& p) const;
    // The answers of an AreaLightBeam (lights/light_form.hpp): the disc
    // facing the apex, cut by POV-Ray's map. None, and no grid, where the
    // point is the centre.
    using Beam = DiscBeam<FacingDisc, DiscMap::Povray>;
    std::optional<Beam> beamFrom(const Vec3& apex, double tMin) const;
    class GridPoints;
    std::optional<GridPoints> gridFrom(const Vec3& point) const;
};

// The answers of AreaLightGridPoints (lights/light_form.hpp) for POV-Ray's
// oriented disc.
class OrientedDiscLight::GridPoints {
public:
    // POV-Ray's point (s, t) of its lattice's square (s = i / (n1 - 1) for
    // lattice column i), by its own operations: (s - 1/2 + 1/1000, t - 1/2 +
    // 1/1000) squeezed onto the disc, along the axes.
    BeamRay toward(double s, double t) const {
        double u = s - 0.5 + 0.001, v = t - 0.5 + 0.001;
        const double scale = std::max(std::abs(u), std::abs(v)) / std::sqrt(u * u + v * v);
        u *= scale;
        v *= scale;
        return rayToward(point_, centre_ + (axis1_ * u + axis2_ * v));
    }
    double emission(const Vec3&) const { return 1.0; }

private:
    friend struct OrientedDiscLight;
    GridPoints(const OrientedDiscLight& light, const Vec3& point, const Frame& frame)
        : centre_(light.centre),
          point_(point),
          axis1_(frame.u * (2.0 * light.radius)),
          axis2_(frame.v * (2.0 * light.radius)) {}

    Vec3 centre_, point_;
    Vec3 axis1_, axis2_;  // POV-Ray's, of the first axis's length
};

}  // namespace asos
