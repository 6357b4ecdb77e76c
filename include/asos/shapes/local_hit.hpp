#pragma once
#include "asos/geometry/vec.hpp"

namespace asos {

// A ray hit in a primitive's local frame: the ray parameter (the same t as
// the world ray's), the local point and the local outward normal (not
// necessarily unit).
struct LocalHit {
    double t = kInfinity;
    Vec3 point{0.0};
    Vec3 normal{0.0, 0.0, 1.0};
};

// A sphere holding the whole primitive, in its local frame.
struct BoundingSphere {
    Vec3 center{0.0};
    double radius = 0.0;
};

}  // namespace asos
