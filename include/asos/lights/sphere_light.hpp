#pragma once
// A spherical light (paper: "Spherical Light Sources", Figure 5b): a sphere
// of `radius` about `centre` (`area_light` with `circular orient` and the
// paper's emitter, `asos { emitter panel }`: the sphere of the diameter of
// POV-Ray's disc, lights/oriented_disc_light.hpp). As every light form
// (lights/light_form.hpp) it answers:
//   - its beam from a point: the cone tangent to the sphere, split into four
//     pieces of equal area of its apparent disc (the concentric images of a
//     square cell's quarters, geometry/concentric_disc.hpp), each bounded by
//     the cone about its central ray through the corners of the polar
//     rectangle that holds it (docs/accel.md, "Sphere pieces") and carrying
//     4^-level of the light;
//   - its grid's points seen from a point (render/grid_light.hpp): the
//     images of the grid's cells' centres, so that a piece's central ray at
//     level K is the point of the 2^K x 2^K grid, bit for bit;
//   - its emitted radiance: intensity colour / (pi r^2), the same along every
//     direction (a disc facing the point sends it the light's colour).
#include <optional>

#include "asos/geometry/beam_hull.hpp"
#include "asos/geometry/bounds.hpp"
#include "asos/geometry/concentric_disc.hpp"
#include "asos/geometry/tangent_cone.hpp"
#include "asos/lights/beam_apex.hpp"
#include "asos/lights/disc_beam.hpp"
#include "asos/lights/round_light.hpp"

namespace asos {

struct SphereLight : RoundLight {
    static constexpr const char* kName = "spherical";

    // The tangent cone from the apex holds p.
    bool beamHolds(const Vec3& apex, const Vec3& p) const;
    // The answers of an AreaLightBeam (lights/light_form.hpp): the tangent
    // cone's cross-section, cut by the concentric map. None, and no grid,
    // where the point lies on or inside the sphere.
    using Beam = DiscBeam<TangentCone, DiscMap::Concentric>;
    std::optional<Beam> beamFrom(const Vec3& apex, double tMin) const;
    class GridPoints;
    std::optional<GridPoints> gridFrom(const Vec3& point) const;
};

// The answers of AreaLightGridPoints (lights/light_form.hpp) for a sphere.
class SphereLight::GridPoints {
public:
    // Through the image of (s, t) on the apparent disc, to the sphere's near side.
    BeamRay toward(double s, double t) const { return tangent_.ray(point_, concentricDisc(s, t)); }
    double emission(const Vec3&) const { return 1.0; }

private:
    friend struct SphereLight;
    GridPoints(const TangentCone& tangent, const Vec3& point) : tangent_(tangent), point_(point) {}

    TangentCone tangent_;
    Vec3 point_;
};

}  // namespace asos
