#include "asos/testing/direction_cone.hpp"

#include <algorithm>

namespace asos {

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

}  // namespace asos
