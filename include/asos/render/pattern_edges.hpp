#pragma once
// Edges of pigment patterns, for ASOS (docs/algorithm.md, "Pattern edges").
// The paper's detection finds object outlines only: a pyray that one object
// covers is shaded with one ray, however its texture varies inside ("If
// there is aliasing from other sources, such as texture maps ..., any
// image-space method ... can be used to reduce it at this point"). asos
// finds those edges in object space instead, like the outlines: a pyray is
// marginal on its object's pattern when the pattern may change inside the
// pyray's footprint.
#include "asos/render/point_light_shadow.hpp"
#include "asos/scene/description.hpp"

namespace asos {

// Whether the pigment is a pattern of two different colours with edge
// planes (checker, brick; not of two pigments): the patterns ASOS finds
// edges of and filters. The
// map patterns (gradient, marble, ...) are not: a leaf samples them at its
// point (docs/algorithm.md, "Map patterns").
bool hasPattern(const Pigment& pigment);

// Which of the pattern's colours is at a world point: 0 (color1) or 1
// (color2); 0 for a solid pigment. Agrees with evaluatePigment.
int pigmentIndex(const Pigment& pigment, const Vec3& worldPoint);

// Whether the pattern may change inside the footprint: when the
// pattern-space bounds of the footprint's corners straddle one of the
// pattern's edge planes (the footprint is a planar quadrilateral, so its
// pattern-space image, an affine image, lies within those bounds): for a
// checker a cell boundary on some axis, for brick a face of the mortar
// (BrickPattern::edgesCrossed). Always
// so for a footprint that is not on the tangent plane (a grazing view,
// where the pixel covers an unknown stretch of the surface). `singleEdge`:
// only one boundary plane is straddled, which meets the footprint's plane in
// one straight line (the paper's "Proximity to One Edge").
struct PatternChange {
    bool mayChange = false;
    bool singleEdge = false;
};
PatternChange pigmentMayChange(const Pigment& pigment, const Footprint& footprint);

}  // namespace asos
