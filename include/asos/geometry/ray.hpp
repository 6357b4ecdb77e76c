#pragma once
#include "asos/geometry/vec.hpp"

namespace asos {

// A ray origin + t * dir. World-space rays have a unit direction, so t is a
// distance; rays carried into object space keep t and lose unit length.
struct Ray {
    Vec3 origin{0.0};
    Vec3 dir{0.0, 0.0, 1.0};

    Vec3 at(double t) const { return origin + t * dir; }
};

}  // namespace asos
