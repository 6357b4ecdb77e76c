#pragma once
// A conservative test of whether a cone (asos/geometry/cone.hpp) may touch an
// axis-aligned box: the BVH's cone traversal rests on it, so that the list of
// objects a pyray or shadow cone may meet (paper: "Detection Phase") is never
// short of one. It answers "may touch" whenever some point of the cone lies in
// the box; a "may touch" for a box the cone misses only costs a classification.
//
// It is NOT the widely copied AABB-cone test (squareys blog), which tests the
// cone against the box's corners and edges in a way that can reject a box the
// cone touches. Here a box is rejected only when one of five simpler sets that
// contain the cone is disjoint from the box or from its bounding sphere; each
// of those disjointness checks is exact up to a slack far above rounding. The
// proof is written out beside the code (src/accel/cone_box.cpp) and in
// docs/accel.md.
#include "asos/geometry/bounds.hpp"
#include "asos/geometry/cone.hpp"

namespace asos {

class ConeBoxTest {
public:
    explicit ConeBoxTest(const Cone& cone);

    // False only when no point of the cone (rays within halfAngle of the
    // axis, distances in [tMin, tMax]) lies in the closed box.
    bool mayTouch(const Bounds3& box) const { return entryDistance(box) < kInfinity; }

    // kInfinity when the box is rejected (as mayTouch); otherwise a lower
    // bound on the distance from the apex of every cone point in the box, so
    // that a traversal can visit boxes near-first and drop those beyond a
    // shrinking tMax.
    double entryDistance(const Bounds3& box) const;

    // The distance from a point to the cone's solid (zero inside it), exact
    // up to rounding. The sphere test uses it; exposed for tests.
    double distanceTo(const Vec3& point) const;

    // Whether a point lies in the cone's solid (exact predicate up to
    // rounding; for tests and callers that sample).
    bool contains(const Vec3& point) const;

    // Moves the far end of the cone nearer (a traversal that has found a
    // full blocker at distance t need not look past it).
    void setTMax(double tMax);

    const Cone& cone() const { return cone_; }
    // The exact axis-aligned bounds of the cone's solid (may be infinite).
    const Bounds3& coneBounds() const { return coneBounds_; }

private:
    void updateFarEnd();

    Cone cone_;
    double cos_ = 1.0;
    double sin_ = 0.0;
    double cosWide_ = 1.0;    // cos(θ + kAngleSlack), lowered by a rounding slack (-1 past π)
    bool valid_ = true;       // false: NaN input, the test then accepts every box
    bool empty_ = false;      // tMin > tMax: the cone has no point
    double axialLo_ = 0.0;    // bounds on (x - apex) . axis over the cone
    double axialHi_ = 0.0;
    double apexScale_ = 0.0;  // max |apex component|, for the rounding slack
    Vec3 orthogonal_{1.0, 0.0, 0.0};  // a unit vector orthogonal to the axis
    Vec3 dirLo_{0.0};         // per axis: min and max of u_i over the cone's unit rays u
    Vec3 dirHi_{0.0};
    Bounds3 coneBounds_;
};

}  // namespace asos
