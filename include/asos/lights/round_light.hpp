#pragma once
// What the round light forms share (lights/sphere_light.hpp, the paper's
// sphere; lights/oriented_disc_light.hpp, POV-Ray's disc that faces each
// point): a centre and a radius, the area of the disc of that radius, and
// the ball that holds every position of it.
#include "asos/geometry/bounds.hpp"
#include "asos/geometry/vec.hpp"

namespace asos {

struct RoundLight {
    Vec3 centre{0.0};
    double radius = 1.0;

    // The area of the disc of its radius (the paper's A in I A; POV-Ray's
    // disc's own).
    double size() const { return kPi * radius * radius; }
    double halfWidth() const { return radius; }
    Bounds3 bounds() const {
        Bounds3 b = Bounds3::of(centre - Vec3(radius));
        b.extend(centre + Vec3(radius));
        return b;
    }
};

}  // namespace asos
