#pragma once
// What every beam (pyramidal ray or shadow cone) shares: the rays it hands the
// tracer and the cones that bound it. The beams themselves: beam_eye.hpp (eye
// pyrays), and the light forms' shadow beams toward rectangular, linear and
// spherical lights (lights/rectangle_light.hpp, segment_light.hpp,
// sphere_light.hpp). docs/accel.md describes them; the paper's "Adaptive
// Supersampling in Object-Space" and "Distributed Light Sources" sections are
// what they serve.
#include "asos/geometry/cone.hpp"
#include "asos/geometry/margins.hpp"  // kConeAnglePad, with which beams widen their cones
#include "asos/geometry/ray.hpp"
#include "asos/geometry/vec.hpp"

namespace asos {

// A ray of a beam, with the distance at which the beam ends along it (the
// light's surface for a shadow beam; kInfinity for an eye beam).
struct BeamRay {
    Ray ray;                      // unit direction
    double distance = kInfinity;
};

// Where a disc-shaped beam's rays end, along its axis w (lights/disc_beam.hpp):
// every end lies on the apex's side of the plane at `distance` along w (or on
// it), inside the circle of `radius` about the axis there as seen from the
// apex, and within `reach` of the apex.
struct EndCircle {
    double distance = 0.0;
    double radius = 0.0;
    double reach = 0.0;
};

// The angle between two nonzero vectors, accurate at 0 and pi (atan2 of the
// cross and dot products, not acos).
double angleBetween(const Vec3& a, const Vec3& b);

}  // namespace asos
