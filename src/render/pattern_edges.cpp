#include "asos/render/pattern_edges.hpp"

#include <cmath>

#include "asos/render/shading.hpp"

namespace asos {

namespace {
Vec3 patternPoint(const Pigment& pigment, const Vec3& worldPoint) {
    return Vec3(pigment.worldFromPattern.inverseMatrix() * Vec4(worldPoint, 1.0));
}
}  // namespace

bool hasPattern(const Pigment& pigment) {
    return pigment.kind == Pigment::Kind::Checker && !(pigment.color1 == pigment.color2);
}

int pigmentIndex(const Pigment& pigment, const Vec3& worldPoint) {
    if (pigment.kind != Pigment::Kind::Checker) return 0;
    return checkerValue(patternPoint(pigment, worldPoint));
}

PatternChange pigmentMayChange(const Pigment& pigment, const Footprint& footprint) {
    if (!hasPattern(pigment)) return {};
    if (!footprint.onTangentPlane()) return {true, false};
    Vec3 lo(kInfinity), hi(-kInfinity);
    for (const Vec3& corner : footprint.corners()) {
        const Vec3 p = patternPoint(pigment, corner);
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    // The checker's cells as checkerValue floors them (x + kPovEpsilon).
    double crossings = 0.0;
    for (int axis = 0; axis < 3; ++axis)
        crossings += std::floor(hi[axis] + kPovEpsilon) - std::floor(lo[axis] + kPovEpsilon);
    return {crossings > 0.0, crossings == 1.0};
}

}  // namespace asos
