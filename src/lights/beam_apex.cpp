#include "asos/lights/beam_apex.hpp"

#include <algorithm>
#include <limits>

#include "asos/geometry/margins.hpp"

namespace asos {

PieceCone BeamApex::coneAbout(const Vec3& axis, const Vec3* directions, int count, double farthest) const {
    // The widest direction by the tangent of its angle, from directions of
    // any length (the tangent |d x axis| / (d . axis) does not depend on it):
    // no normalisation, one square root and one arctangent.
    double widest2 = 0.0;
    bool hemisphere = true;
    for (int i = 0; i < count; ++i) {
        const double along = glm::dot(directions[i], axis);
        // along > 1e-6 |d|: within a right angle of the axis, with margin.
        if (!(along > 0.0) || !(along * along > 1e-12 * glm::dot(directions[i], directions[i]))) {
            hemisphere = false;
            break;
        }
        const Vec3 off = glm::cross(directions[i], axis);
        widest2 = std::max(widest2, glm::dot(off, off) / (along * along));
    }
    // A piece reaching a right angle from its central ray has no convex cone
    // about it: the cone of all directions holds it.
    const double widest = std::sqrt(widest2);
    const double halfAngle = hemisphere ? std::atan(widest) + kConeAnglePad : kPi;
    return {{point, axis, halfAngle, tMin, padUp(farthest)},
            hemisphere ? widest : std::numeric_limits<double>::quiet_NaN()};
}

}  // namespace asos
