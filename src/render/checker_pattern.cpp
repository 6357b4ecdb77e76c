#include "asos/render/checker_pattern.hpp"

#include <algorithm>
#include <cmath>

#include "asos/scene/pov_tolerances.hpp"

namespace asos {

namespace {

// (-1)^floor(t) and its antiderivative from 0, the triangle wave
// 1 - |(t mod 2) - 1|.
double squareWave(double t) { return std::fmod(std::floor(t), 2.0) == 0.0 ? 1.0 : -1.0; }
double triangleWave(double t) { return 1.0 - std::fabs(t - 2.0 * std::floor(0.5 * t) - 1.0); }

}  // namespace

int CheckerPattern::value(const Vec3& p) const {
    // POV-Ray 3.7 adds EPSILON (1e-10) before flooring, so that a surface on a
    // cell boundary (a plane at y = 0, hit at y = -1e-16) falls in one cell.
    // Measured with povray: a pattern point 1e-10 below an integer counts as
    // the integer, 1.1e-10 below does not (older versions used 0.001).
    const double sum = std::floor(p.x + kPovEpsilon) + std::floor(p.y + kPovEpsilon) +
                       std::floor(p.z + kPovEpsilon);
    // POV-Ray converts the sum to int and tests its low bit; fmod keeps huge
    // coordinates from overflowing the conversion.
    return std::fabs(std::fmod(sum, 2.0)) == 1.0 ? 1 : 0;
}

double CheckerPattern::edgesCrossed(const Vec3& lo, const Vec3& hi) const {
    double crossings = 0.0;
    for (int axis = 0; axis < 3; ++axis)
        crossings += std::floor(hi[axis] + kPovEpsilon) - std::floor(lo[axis] + kPovEpsilon);
    return crossings;
}

PatternPlanes CheckerPattern::planes(int) const { return {1.0, kPovEpsilon, {0.0}, 1}; }

double CheckerPattern::boxShare(const Vec3& lo, const Vec3& hi) const {
    double product = 1.0;
    for (int axis = 0; axis < 3; ++axis) {
        const double mean = averageOverInterval(lo[axis] + kPovEpsilon, hi[axis] + kPovEpsilon,
                                                triangleWave, squareWave);
        product *= std::clamp(mean, -1.0, 1.0);
    }
    return 0.5 * (1.0 - product);
}

}  // namespace asos
