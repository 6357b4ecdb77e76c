#include "asos/geometry/beam.hpp"

#include <cmath>

namespace asos {

double angleBetween(const Vec3& a, const Vec3& b) {
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

}  // namespace asos
