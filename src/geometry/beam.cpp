#include "asos/geometry/beam.hpp"

#include <algorithm>
#include <cmath>

namespace asos {

double angleBetween(const Vec3& a, const Vec3& b) {
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

namespace {

double largestAngle(const Vec3& axis, std::span<const Vec3> directions) {
    double largest = 0.0;
    for (const Vec3& d : directions) largest = std::max(largest, angleBetween(axis, d));
    return largest;
}

}  // namespace

DirectionCone smallestEnclosingCone(std::span<const Vec3> directions) {
    DirectionCone best;
    if (directions.empty()) return best;
    if (directions.size() == 1) {
        best.axis = glm::normalize(directions[0]);
        best.halfAngle = kConeAnglePad;
        return best;
    }
    // The smallest spherical cap holding points of an open hemisphere is
    // fixed by two of them (a diameter) or three (a circumcircle), as for
    // the smallest enclosing circle in the plane; the beams give at most a
    // handful of directions, so every pair and triple is tried.
    const std::size_t n = directions.size();
    double bestAngle = kInfinity;
    Vec3 bestAxis(0.0);
    // Each candidate axis is judged by its actual widest angle, so the
    // winner holds every direction whatever the rounding in its making.
    const auto consider = [&](const Vec3& axis) {
        const double widest = largestAngle(axis, directions);
        if (widest < bestAngle) {
            bestAngle = widest;
            bestAxis = axis;
        }
    };
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = i + 1; j < n; ++j) {
            const Vec3 sum = directions[i] + directions[j];
            const double length = glm::length(sum);
            if (length > 0.0) {
                consider(sum / length);
            }
            for (std::size_t k = j + 1; k < n; ++k) {
                // The circumcircle of three points of the sphere lies in the
                // plane through them; its centre is along that plane's normal.
                Vec3 normal = glm::cross(directions[j] - directions[i], directions[k] - directions[i]);
                const double normalLength = glm::length(normal);
                if (!(normalLength > 0.0)) continue;
                normal /= normalLength;
                if (glm::dot(normal, directions[i]) < 0.0) normal = -normal;
                consider(normal);
            }
        }
    }
    if (bestAngle < 0.5 * kPi) {
        best.axis = bestAxis;
        best.halfAngle = bestAngle + kConeAnglePad;
        return best;
    }
    // Not within an open hemisphere: no cone narrower than everything holds
    // the pyramid they span.
    Vec3 mean(0.0);
    for (const Vec3& d : directions) mean += d;
    best.axis = glm::length(mean) > 0.0 ? glm::normalize(mean) : Vec3(0, 0, 1);
    best.halfAngle = kPi;
    return best;
}

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
