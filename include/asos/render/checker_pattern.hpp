#pragma once
// POV-Ray 3.7's checker pattern, in pattern space: unit cubes of alternate
// colours, 1 (the pattern's second colour) where floor(x + e) + floor(y + e)
// + floor(z + e) is odd, e = kPovEpsilon (measured with povray:
// docs/rendering.md). Its edges are the planes where a coordinate plus e is
// an integer.
#include "asos/geometry/vec.hpp"
#include "asos/render/pattern_planes.hpp"

namespace asos {

class CheckerPattern {
public:
    // 0 or 1 at a pattern-space point.
    int value(const Vec3& patternPoint) const;

    // How many of the pattern's edge planes the pattern-space box [lo, hi]
    // straddles (0: one value over the box).
    double edgesCrossed(const Vec3& lo, const Vec3& hi) const;

    // The edge planes along `axis` (0, 1, 2): the cell boundaries.
    PatternPlanes planes(int axis) const;

    // The share of the box [lo, hi] where the value is 1, in closed form:
    // with s(t) = (-1)^floor(t + e) the value is (1 - s(x) s(y) s(z)) / 2, so
    // over a box it is (1 - <s(x)> <s(y)> <s(z)>) / 2, each mean taken from
    // the antiderivative of s, a triangle wave (pbrt-v3's closed-form
    // checkerboard in three dimensions). An axis of no width is taken at its
    // point.
    double boxShare(const Vec3& lo, const Vec3& hi) const;
};

}  // namespace asos
