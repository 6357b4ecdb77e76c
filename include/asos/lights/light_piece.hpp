#pragma once
// A piece of an area light's shadow beam (paper: "Distributed Light
// Sources", Figure 5): the whole light at level 0, and at level K + 1 one of
// the pieces a level-K piece splits into (four quarters of a rectangle, two
// halves of a segment, four equal-area pieces of a sphere's apparent disc).
// Every light form's beam makes and splits pieces of this one type
// (lights/light_form.hpp), so that the tracer's buffers hold any of them.
#include <bit>
#include <cstdint>
#include <limits>

#include "asos/geometry/beam.hpp"

namespace asos {

// One piece of the light: its region in the light's coordinates, its
// level (its share of the light is the beam's share(level)), its position
// among the pieces of that level (for random numbers), its central ray and
// its cone.
struct LightPiece {
    // Rectangle: s in [a0, a1], t in [b0, b1]; segment: s in [a0, a1];
    // sphere: the concentric map's cell s in [a0, a1], t in [b0, b1].
    double a0 = 0.0, b0 = 0.0, a1 = 1.0, b1 = 1.0;
    int level = 0;
    std::uint64_t path = 0;
    BeamRay central;
    Cone cone;
    // The tangent of the cone's half-angle before its padding, when the cone
    // was made through its widest corner (rectangle pieces, sphere pieces
    // below level 0); NaN otherwise. Spares its users the trigonometry.
    double tanHalf = std::numeric_limits<double>::quiet_NaN();
};

// Where a piece lies against the plane through the apex with a given normal
// (a beam's horizonSide): every direction above it, every direction at or
// below it, across it, or not known without rays.
enum class HorizonSide { Above, Below, Across, Unknown };

// 2^-exponent, exactly, without a library call (a piece's share is asked for
// every sample); 0 far below the smallest normal double.
inline double exactShare(int exponent) {
    return exponent < 1000 ? std::bit_cast<double>(std::uint64_t(1023 - exponent) << 52) : 0.0;
}

}  // namespace asos
