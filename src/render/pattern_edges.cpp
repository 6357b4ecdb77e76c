#include "asos/render/pattern_edges.hpp"

#include <cmath>

#include "asos/render/brick_pattern.hpp"
#include "asos/render/checker_pattern.hpp"
#include "asos/render/shading.hpp"

namespace asos {

namespace {
Vec3 patternPoint(const Pigment& pigment, const Vec3& worldPoint) {
    return Vec3(pigment.worldFromPattern.inverseMatrix() * Vec4(worldPoint, 1.0));
}

// How many of the pattern's edge planes the pattern-space box [lo, hi]
// straddles (0: none, the pattern is the same all over it).
double edgesCrossed(const Pigment& pigment, const Vec3& lo, const Vec3& hi) {
    switch (pigment.kind) {
        case Pigment::Kind::Solid: return 0.0;
        case Pigment::Kind::Checker: return CheckerPattern().edgesCrossed(lo, hi);
        case Pigment::Kind::Brick:
            // The mortar's faces: planes of constant y at the foot and top of
            // each bed joint, and within a course planes of constant x and z at
            // the sides of its head joints.
            return BrickPattern(pigment.brickSize, pigment.mortar).edgesCrossed(lo, hi);
        default:
            // The map patterns have no edge planes: hasPattern is false for
            // them and a leaf samples them at its point.
            return 0.0;
    }
}
}  // namespace

bool hasPattern(const Pigment& pigment) {
    // A checker or brick of pigments varies inside its cells as its pigments
    // do: it is sampled at points, as the map patterns (no edges, no filter).
    return (pigment.kind == Pigment::Kind::Checker || pigment.kind == Pigment::Kind::Brick) &&
           !pigment.pigmentMap && !(pigment.color1 == pigment.color2);
}

int pigmentIndex(const Pigment& pigment, const Vec3& worldPoint) {
    switch (pigment.kind) {
        case Pigment::Kind::Solid: return 0;
        case Pigment::Kind::Checker: return CheckerPattern().value(patternPoint(pigment, worldPoint));
        case Pigment::Kind::Brick:
            return BrickPattern(pigment.brickSize, pigment.mortar).value(patternPoint(pigment, worldPoint));
        default: return 0;  // the map patterns: no colour index (hasPattern is false)
    }
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
    const double crossings = edgesCrossed(pigment, lo, hi);
    return {crossings > 0.0, crossings == 1.0};
}

}  // namespace asos
