#pragma once
// The patterns whose value runs over [0, 1] and picks a colour from a colour
// map (gradient, radial, onion, marble, wood, leopard, bozo, spotted,
// granite, agate; bumps, dents, wrinkles, ripples, waves), with POV-Ray
// 3.7's arithmetic: turbulence displacing the point (marble and wood apply
// it themselves), the pattern's value, the wave (frequency, phase,
// ramp/triangle/sine), then the map's linear blend between its entries. Their colour varies continuously, with no edge
// planes: ASOS samples them at a leaf's point (docs/algorithm.md, "Map
// patterns").
#include <span>

#include "asos/scene/description.hpp"

namespace asos {

// Whether the pigment's kind is one of these patterns.
bool isMapPattern(Pigment::Kind kind);

// The pattern's value in [0, 1] at a pattern-space point, after the wave.
double mapPatternValue(const Pigment& pigment, const Vec3& patternPoint);

// POV-Ray's two steps of it, which a normal's slope needs apart: where
// classic turbulence moves a pattern-space point (nowhere without
// turbulence, and for marble and wood, which use it their own way), and the
// value at a point already moved so.
Vec3 turbulatedPoint(const Pigment& pigment, const Vec3& patternPoint);
double mapPatternValueAt(const Pigment& pigment, const Vec3& turbulatedPoint);

// The colour map's colour at a value: the pigment's own map, or POV-Ray's
// default map for the pattern.
Color colourMapAt(std::span<const ColourMapEntry> map, double value);
std::span<const ColourMapEntry> colourMapOf(const Pigment& pigment);

}  // namespace asos
