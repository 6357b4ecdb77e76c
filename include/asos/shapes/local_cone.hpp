#pragma once
// Cones as the primitives see them (paper: "Detection Phase").
//
// PreparedCone is a world cone with its trigonometry done once, since the
// tracer asks one cone about many objects. Its half-angle is already widened
// by kConeAngleMargin (asos/geometry/margins.hpp): every primitive classifies
// that slightly larger cone, which keeps both Miss and Full conservative for
// the real one under rounding.
//
// LocalCone is the same cone carried into a primitive's local frame, where t
// is local distance, with [tMin, tMax] also kept in a widened (outer) and a
// narrowed (inner) form: "no hit can lie in the range" is proved against the
// outer range, "every hit lies in the range" against the inner one.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "asos/geometry/cone.hpp"
#include "asos/geometry/margins.hpp"
#include "asos/geometry/vec.hpp"

namespace asos {

struct PreparedCone {
    Vec3 apex{0.0};
    Vec3 axis{0.0, 0.0, 1.0};  // unit
    double cosHalf = 1.0;      // of the widened half-angle
    double sinHalf = 0.0;
    double tMin = 0.0;  // clamped to >= 0
    double tMax = kInfinity;
    // False for input that is not a cone (NaN, zero axis): such a cone is
    // answered Marginal over its whole range, which is always conservative.
    bool valid = true;
    // Whether a Full answer should name the creases in the cone
    // (ConeClass::creaseParts): eye pyrays ask, shadow cones need not.
    bool creases = false;

    PreparedCone() = default;
    explicit PreparedCone(const Cone& cone, bool withCreases = false) : creases(withCreases) {
        apex = cone.apex;
        tMin = std::max(cone.tMin, 0.0);
        tMax = cone.tMax;
        const double len = glm::length(cone.axis);
        valid = std::isfinite(len) && len > 0.0 && std::isfinite(apex.x) &&
                std::isfinite(apex.y) && std::isfinite(apex.z) && !std::isnan(tMin) &&
                !std::isnan(tMax) && !std::isnan(cone.halfAngle) && cone.halfAngle >= 0.0;
        if (!valid) return;
        axis = cone.axis / len;
        const double widened =
            cone.halfAngle + kConeAngleMargin * (1.0 + cone.halfAngle);
        if (widened >= kPi) {
            cosHalf = -1.0;
            sinHalf = 0.0;
        } else {
            cosHalf = std::cos(widened);
            sinHalf = std::sin(widened);
        }
    }
};

// `yes ? a : b` without a branch, for answers that are as good as random
// from one cone to the next (a mispredicted branch costs more than both).
inline double selectDouble(bool yes, double a, double b) {
    const std::uint64_t mask = -static_cast<std::uint64_t>(yes);
    return std::bit_cast<double>((std::bit_cast<std::uint64_t>(a) & mask) |
                                 (std::bit_cast<std::uint64_t>(b) & ~mask));
}

// A rigid frame's answer in world units: the local bounds padded by the
// distance tolerances (absTol in local units), scaled by worldPerLocal and
// clipped to the world range [tMin, tMax]. No branch on the answer: a Miss's
// bounds (+inf, -inf) come through unchanged, so a Miss needs none of this.
struct RigidBounds {
    double absTol, worldPerLocal, tMin, tMax;
    __attribute__((always_inline)) ConeClass operator()(ConeClass out) const {
        out.tNear = std::max(tMin, nearWorld(out.tNear));
        out.tFar = std::min(tMax, farWorld(out.tFar));
        return out;
    }
    // The range tests of LocalCone for local depths, made against the world
    // range (the depths padded and scaled as above), and the Full and
    // Marginal answers in world units: a fast path may answer through these
    // (and conegeom::rangedClass on them) before the local range is set. The
    // same answers as LocalCone's tests on the ranged cone and
    // this(fullClass(...)) or this(marginalClass(...)), with one padding
    // rather than two (the tolerances are the same).
    bool surelyAfter(double tNearBound) const { return nearWorld(tNearBound) > tMax; }
    bool surelyBefore(double tFarBound) const { return farWorld(tFarBound) < tMin; }
    bool surelyWithin(double lo, double hi) const {
        return (nearWorld(lo) >= tMin) & (farWorld(hi) <= tMax);
    }
    // Every hit at lo or later is past the range's start (LocalCone's
    // lo >= tMinInner).
    bool startsWithin(double lo) const { return nearWorld(lo) >= tMin; }
    ConeClass full(double tNear, double tFar) const {
        return {Coverage::Full, nearWorld(tNear), farWorld(tFar), false};
    }
    ConeClass marginal(double tNear, double tFar, bool singleEdge = false) const {
        return {Coverage::Marginal, std::max(tMin, nearWorld(tNear)), std::min(tMax, farWorld(tFar)),
                singleEdge};
    }

private:
    double nearWorld(double t) const {
        return (t * (1.0 - kConeDistanceTolerance) - absTol) * worldPerLocal;
    }
    double farWorld(double t) const {
        return (t * (1.0 + kConeDistanceTolerance) + absTol) * worldPerLocal;
    }
};

struct LocalCone {
    Vec3 apex{0.0};
    Vec3 axis{0.0, 0.0, 1.0};  // unit
    double cosHalf = 1.0;
    double sinHalf = 0.0;
    double tMin = 0.0;
    double tMax = kInfinity;
    double tMinOuter = 0.0, tMinInner = 0.0;
    double tMaxOuter = kInfinity, tMaxInner = kInfinity;
    double absTol = 0.0;  // absolute distance tolerance in local units
    bool creases = false;  // PreparedCone::creases

    // Sets the range and its tolerant forms; absTol covers rounding of
    // distances of the size of the scene around the apex.
    void setRange(double t0, double t1, double tolerance) {
        tMin = t0;
        tMax = t1;
        absTol = tolerance;
        // Written so that an infinite t1 stays infinite without a branch.
        tMinOuter = t0 * (1.0 - kConeDistanceTolerance) - absTol;
        tMinInner = t0 * (1.0 + kConeDistanceTolerance) + absTol;
        tMaxOuter = t1 * (1.0 + kConeDistanceTolerance) + absTol;
        tMaxInner = t1 * (1.0 - kConeDistanceTolerance) - absTol;
    }

    // Every hit is at t <= tFarBound and that is provably before the range.
    bool surelyBefore(double tFarBound) const { return tFarBound < tMinOuter; }
    // Every hit is at t >= tNearBound and that is provably after the range.
    bool surelyAfter(double tNearBound) const { return tNearBound > tMaxOuter; }
    // [lo, hi] provably lies inside the range.
    bool surelyWithin(double lo, double hi) const { return lo >= tMinInner && hi <= tMaxInner; }
    bool rangeEmpty() const { return tMin > tMax; }
};

// classifyRanging of a shape without a fast path before the range: the
// range set, then its classify (inline, so that a rigid frame's
// classification keeps the cone in registers).
template <class S>
__attribute__((always_inline)) inline ConeClass classifyAfterRange(const S& shape, LocalCone& cone, double t0,
                                                                  double t1, const RigidBounds& back) {
    cone.setRange(t0, t1, cone.absTol);
    return back(shape.classify(cone));
}

}  // namespace asos
