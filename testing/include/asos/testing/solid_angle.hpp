#pragma once
// Exact solid angles, for the tests' integrals over the reference beams.
#include <span>

#include "asos/geometry/vec.hpp"

namespace asos {

// The solid angle of the spherical triangle spanned by three directions (Van
// Oosterom and Strackee), and of the pyramid over a planar convex polygon's
// corners as seen from `apex`.
double solidAngle(const Vec3& a, const Vec3& b, const Vec3& c);
double solidAngleOfPolygon(const Vec3& apex, std::span<const Vec3> corners);

}  // namespace asos
