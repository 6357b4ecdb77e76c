#pragma once
// Floating-point margins: the pads that stand for a bound on rounding, each
// stated once with the bound it covers (docs/geometry.md, "Robustness:
// margins and tolerances", lists these and the tolerances that are modelling
// choices, which stay beside their users).
//
// roundingGamma(n) = n u / (1 - n u), u = 2^-53 the unit roundoff, bounds
// the relative error of n rounded operations (Higham, "Accuracy and Stability
// of Numerical Algorithms", 3.1; pbrt-v4's gamma(n)). The pads are round
// decimals rather than gamma itself, each far above roundingGamma(n) for the
// operations it covers (checked below): a computed bound is padded by a fixed
// value, so a bound and every test against it keep their value.
#include <limits>

namespace asos {

inline constexpr double kUnitRoundoff = 0.5 * std::numeric_limits<double>::epsilon();

constexpr double roundingGamma(int n) {
    return n * kUnitRoundoff / (1.0 - n * kUnitRoundoff);
}

// Relative rounding pads, named by their size in ulps of the value they
// multiply (an ulp of x is 2^-53 to 2^-52 of |x|). A site says what it
// covers: the pad exceeds roundingGamma(n) for its n operations on the
// magnitudes it multiplies.
//
// A few ulps (1e-15: 4.5 to 9): a handful of operations, up to nine (a dot
// product and a difference, a division, a short closed form).
inline constexpr double kFewUlps = 1e-15;
// Tens of ulps (1e-14): up to ninety operations (a Gram matrix's trace less
// a quadratic form, a bound summed from a dozen rounded terms).
inline constexpr double kTensOfUlps = 1e-14;
// Hundreds of ulps (1e-13): up to nine hundred (a discriminant from rounded
// coefficients, a quadratic's coefficients summed over a box's corners).
inline constexpr double kHundredsOfUlps = 1e-13;
// Thousands of ulps (1e-12): the general pad of a computed bound. Any closed
// form here is a few dozen operations (roundingGamma(50) = 5.6e-15), so
// 1e-12 covers it with a factor above 100 to spare; a quantity within it of
// zero, relative to the magnitudes it is computed from, is zero to rounding
// (a degenerate axis, edge, transform or camera).
inline constexpr double kThousandsOfUlps = 1e-12;

static_assert(kFewUlps > roundingGamma(9));
static_assert(kTensOfUlps > roundingGamma(90));
static_assert(kHundredsOfUlps > roundingGamma(900));
static_assert(kThousandsOfUlps > 100.0 * roundingGamma(50));

// A computed bound moved outward by kThousandsOfUlps: an upper bound up, a
// lower bound down. Written x (1 +- pad), one rounding after the bound's own.
constexpr double padUp(double x) { return x * (1.0 + kThousandsOfUlps); }
constexpr double padDown(double x) { return x * (1.0 - kThousandsOfUlps); }

// Positions (a cone's apex in a primitive's local frame, a frame's offset)
// are known to 1e-11 of the size of their coordinates: mapping a point to a
// local frame is a matrix product and an offset, a few operations on values
// that come through a few dozen from the scene's numbers (roundingGamma(50)
// = 5.6e-15 of the largest magnitude involved); 1e-11 is 1800 times that.
// A cone's absolute distance tolerance (absTol) is this times the size of
// the local coordinates.
inline constexpr double kPositionTolerance = 1e-11;

// Cones. Every half-angle is widened by kConeAngleMargin radians plus that
// fraction of the angle before a primitive classifies it (PreparedCone):
// both Miss and Full are then proved for a slightly larger cone, which
// absorbs the rounding of the ray test and of the classification (a few
// dozen operations on unit vectors, roundingGamma(50) = 5.6e-15 rad) many
// times over, and a half-angle of 0 (a ray) gets an answer valid for a
// 1e-9 rad cone.
inline constexpr double kConeAngleMargin = 1e-9;
// Distances compared with a cone's t-range are widened (or narrowed) by this
// fraction and by absTol: the same generous cover of rounding as the angle's.
inline constexpr double kConeDistanceTolerance = 1e-9;
// Cones of beams are widened by this many radians beyond the largest angle
// computed for a ray of the beam, so that rounding in those angles (~1e-16)
// never leaves a ray of the beam outside its cone.
inline constexpr double kConeAnglePad = 1e-13;

// Not a rounding bound: a floor that keeps a quantity positive (a divisor, a
// slack, a standoff), far below any value it stands in for.
inline constexpr double kPositiveFloor = 1e-300;

}  // namespace asos
