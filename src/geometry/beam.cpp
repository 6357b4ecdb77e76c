#include "asos/geometry/beam.hpp"

#include <cmath>

namespace asos {

Frame Frame::around(const Vec3& w) {
    // Duff et al., "Building an Orthonormal Basis, Revisited" (2017):
    // branch on the sign only, continuous elsewhere, exact for axis vectors.
    const double sign = std::copysign(1.0, w.z);
    const double a = -1.0 / (sign + w.z);
    const double b = w.x * w.y * a;
    return {Vec3(1.0 + sign * w.x * w.x * a, sign * b, -sign * w.x),
            Vec3(b, sign + w.y * w.y * a, -w.y), w};
}

double angleBetween(const Vec3& a, const Vec3& b) {
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

}  // namespace asos
