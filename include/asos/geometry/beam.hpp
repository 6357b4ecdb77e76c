#pragma once
// What every beam (pyramidal ray or shadow cone) shares: the rays it hands the
// tracer and the cones that bound it. The beams themselves: beam_eye.hpp (eye
// pyrays), and the light forms' shadow beams toward rectangular, linear and
// spherical lights (lights/rectangle_light.hpp, segment_light.hpp,
// sphere_light.hpp). docs/accel.md describes them; the paper's "Adaptive
// Supersampling in Object-Space" and "Distributed Light Sources" sections are
// what they serve.
#include <span>

#include "asos/geometry/cone.hpp"
#include "asos/geometry/ray.hpp"
#include "asos/geometry/vec.hpp"

namespace asos {

// A ray of a beam, with the distance at which the beam ends along it (the
// light's surface for a shadow beam; kInfinity for an eye beam).
struct BeamRay {
    Ray ray;                      // unit direction
    double distance = kInfinity;
};

// An orthonormal frame around a unit vector w (deterministic in w).
struct Frame {
    Vec3 u, v, w;
    static Frame around(const Vec3& w);
    Vec3 toWorld(double x, double y, double z) const { return x * u + y * v + z * w; }
};

// The angle between two nonzero vectors, accurate at 0 and pi (atan2 of the
// cross and dot products, not acos).
double angleBetween(const Vec3& a, const Vec3& b);

// Cones of beams are widened by this many radians beyond the largest angle
// computed for a ray of the beam, so that rounding in those angles (~1e-16)
// never leaves a ray of the beam outside its cone.
inline constexpr double kConeAnglePad = 1e-13;

// The axis and half-angle of the smallest circular cone (apex at the origin)
// holding every given unit direction. The directions must lie in an open
// hemisphere (then the cone also holds every positive combination of them,
// i.e. the whole pyramid they span, since its half-angle is below pi/2);
// otherwise the result is a cone about their mean of half-angle pi (all
// directions). The half-angle is the largest angle from the axis to a
// direction plus kConeAnglePad, so the directions are inside despite rounding.
struct DirectionCone {
    Vec3 axis{0.0, 0.0, 1.0};
    double halfAngle = 0.0;
};
DirectionCone smallestEnclosingCone(std::span<const Vec3> directions);

// The solid angle of the spherical triangle spanned by three directions (Van
// Oosterom and Strackee), and of the pyramid over a planar convex polygon's
// corners as seen from `apex`.
double solidAngle(const Vec3& a, const Vec3& b, const Vec3& c);
double solidAngleOfPolygon(const Vec3& apex, std::span<const Vec3> corners);

}  // namespace asos
