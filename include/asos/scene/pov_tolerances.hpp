#pragma once
// POV-Ray's tolerances, kept so that scenes mean and render what they mean
// there: modelling choices, not bounds on rounding (those are in
// asos/geometry/margins.hpp).

namespace asos {

// POV-Ray's EPSILON. The language's = != <= >= compare within it and a
// condition is true when its magnitude exceeds it; two area-light axes whose
// lengths differ by less are equal; a sub-polygon closes where a point comes
// within it of its first in every coordinate; the checker pattern adds it
// before flooring; a light at a cosine below it to the surface lights nothing.
inline constexpr double kPovEpsilon = 1e-10;
// POV-Ray's intersection tolerances, which a tracer matching its images uses:
// hits nearer than MIN_ISECT_DEPTH along any ray are ignored, and shadow rays
// ignore hits within SHADOW_TOLERANCE of the shaded point or the light.
inline constexpr double kPovMinIsectDepth = 1e-4;
inline constexpr double kPovShadowTolerance = 1e-3;

}  // namespace asos
