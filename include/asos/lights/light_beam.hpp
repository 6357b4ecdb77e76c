#pragma once
// POV-Ray's spotlights, cylinder lights and parallel lights
// (lightsource.cpp, Attenuate_Light; trace.cpp, ComputeOneWhiteLightRay):
// the factor by which the light's colour is scaled on its way to a point,
// and, for a parallel light, where the light stands for that point.
//
//   spotlight   cos theta = the cosine between the axis (position toward
//               point_at) and the direction from the light to the point:
//               0 behind the light (cos theta <= 0), else
//               cos^tightness theta, times, outside the radius cone,
//               s((cos theta - cos falloff) / (cos radius - cos falloff)),
//               s(t) = (3 - 2t) t^2 clamped to [0, 1] (POV-Ray's
//               cubic_spline: the smooth step is in the cosine);
//   cylinder    d = the point's distance from the axis, for points in front
//               of the light (0 behind it, or at d >= falloff):
//               (1 - d / falloff)^tightness, times, beyond the radius,
//               s((1 - d / falloff) / (1 - radius / falloff)).
//
// A parallel light (and every cylinder light) sends its light along the
// axis: a point is lit from the plane through the light's position square
// to the axis, at the distance to that plane, so its shadow ray runs along
// the axis. A parallel spotlight is not narrowed (POV-Ray turns the light
// direction to the axis, where its cosine is 1).
#include <optional>

#include "asos/geometry/vec.hpp"
#include "asos/scene/description.hpp"

namespace asos {

// POV-Ray's cubic_spline(low, high, pos): 0 below low, 1 from high on, the
// smooth step (3 - 2t) t^2 of t = (pos - low) / (high - low) between.
double povCubicSpline(double low, double high, double pos);

// The spotlight's factor at cosine `cosTheta` from its axis, with the
// cosines of its radius and falloff angles.
double spotlightFactor(double cosTheta, double cosRadius, double cosFalloff, double tightness);

// The cylinder light's factor at distance `d` from its axis (the point in
// front of the light).
double cylinderFactor(double d, double radius, double falloff, double tightness);

// A light's cone or beam, made once per light.
struct LightBeam {
    LightType type = LightType::Point;
    bool parallel = false;
    Vec3 position{0.0};
    Vec3 axis{0.0, 0.0, 1.0};  // unit, position toward point_at (POV-Ray: 0 when they coincide)
    double radius = 0.0, falloff = 0.0;  // cosines for a spotlight, distances for a cylinder
    double tightness = 0.0;

    static LightBeam of(const Light& light);

    // Nothing narrows or turns the light: a plain point light.
    bool plain() const { return type == LightType::Point && !parallel; }

    // Where the light stands for `point`: its position, or for a parallel
    // light the foot of the axis-parallel line through `point` on the plane
    // through the position square to the axis. A point on or behind that
    // plane: a parallel spotlight or cylinder light does not reach it (none);
    // a parallel point light lights it along the axis without a shadow test
    // (POV-Ray's shadow ray has no length there): a source one unit up the
    // axis, `unshadowed`.
    struct Source {
        Vec3 position{0.0};
        bool unshadowed = false;
    };
    std::optional<Source> sourceFor(const Vec3& point) const;

    // The factor on the light's colour at `point`, for light arriving along
    // `toLight` (unit, from the point toward the light's point or sample).
    double factor(const Vec3& point, const Vec3& toLight) const;
};

// LightBeam::sourceFor without making the beam for a light that is not
// parallel: where a point light stands for `point`.
inline std::optional<LightBeam::Source> lightSourceFor(const Light& light, const Vec3& point) {
    if (!light.parallel && light.type != LightType::Cylinder) return LightBeam::Source{light.position, false};
    return LightBeam::of(light).sourceFor(point);
}

}  // namespace asos
