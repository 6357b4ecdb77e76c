#pragma once
#include "asos/geometry/vec.hpp"

namespace asos {

// The half-space {x : normal.x <= offset} (normal of any length unless its
// user says otherwise).
struct HalfSpace {
    Vec3 normal{0.0, 0.0, 1.0};
    double offset = 0.0;
};

}  // namespace asos
