#pragma once
// Two maps from the unit square onto the unit disc, and the polar bounds of
// the images of the square's cells under either:
//   - Shirley and Chiu's equal-area concentric map: a spherical light's
//     apparent disc is cut by it into pieces of equal area
//     (lights/sphere_light.hpp), the grid's points at the images of the
//     cells' centres;
//   - POV-Ray's map of a `circular` area light's lattice (trace.cpp,
//     TraceAreaLightSubsetShadowRay): each point moved along its ray from
//     the centre so that square rings become circles, not equal-area (twice
//     as dense toward the square's diagonals as along its axes); its cells'
//     images are the pieces of POV-Ray's oriented disc
//     (lights/oriented_disc_light.hpp), so that equal shares of the square
//     are POV-Ray's density.
// Both take the point (a, b) = (2s - 1, 2t - 1) to radius max(|a|, |b|).
#include "asos/geometry/vec.hpp"

namespace asos {

enum class DiscMap { Concentric, Povray };

// The map from [0, 1]^2 onto the unit disc: equal areas to equal areas,
// square rings to circles, rays from the square's centre to rays from the
// disc's.
Vec2 concentricDisc(double s, double t);
// POV-Ray's: (a, b) max(|a|, |b|) / |(a, b)|, the angle kept.
Vec2 povrayDisc(double s, double t);
inline Vec2 discPoint(DiscMap map, double s, double t) {
    return map == DiscMap::Povray ? povrayDisc(s, t) : concentricDisc(s, t);
}

// A cell of the unit square, s in [s0, s1], t in [t0, t1].
struct DiscCell {
    double s0 = 0.0, s1 = 1.0, t0 = 0.0, t1 = 1.0;
};

// The polar rectangle r in [r0, r1], phi in [phi0, phi1] (phi1 - phi0 <=
// pi / 2) that holds the image of a cell lying in one quadrant of the square
// (every cell but the whole square) under either map; the whole square's is
// the whole disc, phi in [0, 2 pi]. The radius of the image of (s, t) is
// max(|2s - 1|, |2t - 1|), and its angle grows with the angle of (2s - 1,
// 2t - 1) (POV-Ray's map keeps it): the bounds are exact (the cell's corners
// and its nearest point to the centre attain them).
struct PolarBounds {
    double r0 = 0.0, r1 = 1.0, phi0 = 0.0, phi1 = 2.0 * kPi;
};
PolarBounds polarBounds(const DiscCell& cell, DiscMap map = DiscMap::Concentric);
// Its r0 alone: the least radius of the cell's image.
double innerRadius(const DiscCell& cell);

}  // namespace asos
