#pragma once
// The bounding cone of a pyramidal ray (paper: "Adaptive Supersampling in
// Object-Space", Figure 1) or a shadow cone (Figure 5b), and the answer a
// primitive gives about it (paper: "Detection Phase").
#include <cmath>
#include <cstdint>

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
    // Marginal: the boundary inside the cone is a single straight edge (the
    // paper's "Proximity to One Edge" criterion may be used). Full with a
    // crease: the crease inside the cone is a single straight edge.
    bool singleEdge = false;
    // Full only, for a cone that asks (PreparedCone::creases): a crease of
    // the object, where its normal jumps (a box's edge between two faces, a
    // capped cylinder's or cone's rim, a cone's tip), may lie inside the
    // cone, so that its rays see different parts of the surface. Bit i: the rays may see part i (SurfaceHit::part)
    // beside such a crease; kTipCrease: a tip, around which the normal turns
    // all round, may lie inside the cone. 0: every ray sees the same part.
    std::uint8_t creaseParts = 0;
    static constexpr std::uint8_t kTipCrease = 0x80;
};

}  // namespace asos
