#pragma once
// The bounding cone of a pyramidal ray (paper: "Adaptive Supersampling in
// Object-Space", Figure 1) or a shadow cone (Figure 5b), and the answer a
// primitive gives about it (paper: "Detection Phase").
#include <cmath>

#include "asos/geometry/vec.hpp"

namespace asos {

// The points apex + t d with |d| = 1, angle(d, axis) <= halfAngle and
// t in [tMin, tMax]: t is distance from the apex along each ray of the cone.
struct Cone {
    Vec3 apex{0.0};
    Vec3 axis{0.0, 0.0, 1.0};  // unit
    double halfAngle = 0.0;    // radians, in [0, pi)
    double tMin = 0.0;
    double tMax = kInfinity;

    double cosHalf() const { return std::cos(halfAngle); }
    double sinHalf() const { return std::sin(halfAngle); }
};

enum class Coverage {
    Miss,      // no ray of the cone meets the object within [tMin, tMax]
    Full,      // every ray of the cone meets the object within [tMin, tMax]
    Marginal,  // the object's boundary (as seen from the apex) lies inside the cone
};

// A primitive's answer for a cone. Conservative: never Miss when some ray of
// the cone hits, never Full when some ray misses.
struct ConeClass {
    Coverage coverage = Coverage::Miss;
    // Bounds on the hit distance t of the rays of the cone that hit (valid
    // unless Miss): every such ray's nearest hit within [tMin, tMax] lies in
    // [tNear, tFar].
    double tNear = kInfinity;
    double tFar = -kInfinity;
    // Marginal only: the boundary inside the cone is a single straight edge
    // (the paper's "Proximity to One Edge" criterion may be used).
    bool singleEdge = false;
};

}  // namespace asos
