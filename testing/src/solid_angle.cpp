#include "asos/testing/solid_angle.hpp"

#include <cmath>

namespace asos {

double solidAngle(const Vec3& a, const Vec3& b, const Vec3& c) {
    const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
    // a . (b x c), from the edge vectors so that small triangles keep their
    // relative precision.
    const double numerator = glm::dot(a, glm::cross(b - a, c - a));
    const double denominator =
        la * lb * lc + glm::dot(a, b) * lc + glm::dot(a, c) * lb + glm::dot(b, c) * la;
    return std::abs(2.0 * std::atan2(numerator, denominator));
}

double solidAngleOfPolygon(const Vec3& apex, std::span<const Vec3> corners) {
    double total = 0.0;
    for (std::size_t i = 1; i + 1 < corners.size(); ++i) {
        total += solidAngle(corners[0] - apex, corners[i] - apex, corners[i + 1] - apex);
    }
    return total;
}

}  // namespace asos
