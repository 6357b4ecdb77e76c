#pragma once
// The numeric types shared by every stage. Geometry is double precision;
// acceleration structures may store floats internally (rounded outward).
#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/glm.hpp>

namespace asos {

using Vec2 = glm::dvec2;
using Vec3 = glm::dvec3;
using Vec4 = glm::dvec4;
using Mat3 = glm::dmat3;
using Mat4 = glm::dmat4;

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

// glm::dot of two Vec3, always inlined (GCC leaves glm::dot a call in large
// functions): the same products and sums in the same order, so the same
// value bit for bit.
__attribute__((always_inline)) inline double dot3(const Vec3& a, const Vec3& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

// |x| + |y| + |z|, summed in that order: the scale of a point's coordinates
// in the rounding tolerances of the shapes and caches.
inline double l1Norm(const Vec3& v) { return std::abs(v.x) + std::abs(v.y) + std::abs(v.z); }

// max(|x|, |y|, |z|).
inline double maxNorm(const Vec3& v) {
    return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}

}  // namespace asos
