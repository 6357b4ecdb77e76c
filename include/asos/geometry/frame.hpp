#pragma once
// An orthonormal frame around a unit vector: the shadow cones' frames toward
// a light (geometry/tangent_cone.hpp) and the primitives' local frames
// (shapes/local_frame.hpp) are built by the same formula.
#include "asos/geometry/vec.hpp"

namespace asos {

// u, v, w orthonormal and right-handed, w the given unit vector;
// deterministic in w and exact for the coordinate axes.
struct Frame {
    Vec3 u, v, w;
    static Frame around(const Vec3& w);
    Vec3 toWorld(double x, double y, double z) const { return x * u + y * v + z * w; }
};

// The same frame as a rotation taking +z to the unit vector n (columns u, v, n).
Mat3 frameAroundAxis(const Vec3& n);

}  // namespace asos
