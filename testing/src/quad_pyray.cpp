#include "asos/testing/quad_pyray.hpp"

#include <algorithm>
#include <cmath>

#include "asos/geometry/margins.hpp"
#include "asos/testing/direction_cone.hpp"

namespace asos {

QuadPyray QuadPyray::make(const Vec3& apex, const std::array<Vec3, 4>& corners, int level,
                          double tMin) {
    return QuadPyray(apex, corners, level, tMin);
}

QuadPyray::QuadPyray(const Vec3& apex, const std::array<Vec3, 4>& corners, int level, double tMin)
    : apex_(apex), corners_(corners), level_(level), tMin_(tMin) {
    std::array<Vec3, 4> directions;
    double farthest = 0.0;
    int count = 0;
    for (const Vec3& c : corners_) {
        const Vec3 offset = c - apex_;
        const double distance = glm::length(offset);
        farthest = std::max(farthest, distance);
        if (distance > 0.0) directions[count++] = offset / distance;
    }
    const DirectionCone bound = count > 0 ? smallestEnclosingCone(std::span(directions.data(), count))
                                          : DirectionCone{Vec3(0, 0, 1), kPi};
    cone_ = {apex_, bound.axis, bound.halfAngle, tMin_, padUp(farthest)};
}

Vec3 QuadPyray::bilinear(double s, double t) const {
    return (1.0 - t) * ((1.0 - s) * corners_[0] + s * corners_[1]) +
           t * ((1.0 - s) * corners_[3] + s * corners_[2]);
}

std::array<QuadPyray, 4> QuadPyray::split() const {
    // The edge midpoints and the centre, shared exactly by the quarters.
    const Vec3 m01 = 0.5 * (corners_[0] + corners_[1]), m12 = 0.5 * (corners_[1] + corners_[2]);
    const Vec3 m23 = 0.5 * (corners_[2] + corners_[3]), m30 = 0.5 * (corners_[3] + corners_[0]);
    const Vec3 centre = 0.5 * (m01 + m23);
    const int next = level_ + 1;
    return {QuadPyray(apex_, {corners_[0], m01, centre, m30}, next, tMin_),
            QuadPyray(apex_, {m01, corners_[1], m12, centre}, next, tMin_),
            QuadPyray(apex_, {centre, m12, corners_[2], m23}, next, tMin_),
            QuadPyray(apex_, {m30, centre, m23, corners_[3]}, next, tMin_)};
}

BeamRay QuadPyray::toward(double s, double t) const {
    const Vec3 offset = bilinear(s, t) - apex_;
    const double distance = glm::length(offset);
    return {Ray{apex_, distance > 0.0 ? offset / distance : cone_.axis}, distance};
}

double QuadPyray::weight() const { return std::ldexp(1.0, -2 * level_); }

}  // namespace asos
