#pragma once
// The pigment averaged over an eye pyray's footprint (docs/algorithm.md,
// "Pattern filter"): the share of the pyray's image square whose footprint
// point shows the pattern's second colour, computed exactly for the tangent
// plane by clipping the square along the images of the pattern's edge
// planes (render/pattern_footprint.hpp): each piece lies in one cell of
// those planes, so it has one value, and its image area is its weight under
// the pixel's box filter. A footprint over more pieces than is worth
// clipping is split into quarters, and a quarter of a quarter still too
// rich takes the closed-form average over its pattern-space bounding box
// (CheckerPattern::boxShare, BrickPattern::boxShare), which is close to the
// pattern's mean there.
#include "asos/render/pattern_footprint.hpp"
#include "asos/scene/description.hpp"

namespace asos {

// The share of the footprint, by image area, where the pigment has its
// second colour (checker: value 1; brick: the brick), in [0, 1]. 0 for a
// solid pigment.
double patternShare(const Pigment& pigment, const PatternFootprint& footprint);

// The pigment's colour averaged over the footprint: its two colours mixed by
// patternShare.
Color filteredPigment(const Pigment& pigment, const PatternFootprint& footprint);

}  // namespace asos
