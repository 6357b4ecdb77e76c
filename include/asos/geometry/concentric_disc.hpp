#pragma once
// Shirley and Chiu's equal-area concentric map from the unit square onto the
// unit disc, and the polar bounds of the images of the square's cells. A
// spherical light's apparent disc is cut by it into pieces of equal area
// (lights/sphere_light.hpp): the images of the quadtree's cells, the grid's
// points at the images of the cells' centres.
#include "asos/geometry/vec.hpp"

namespace asos {

// The map from [0, 1]^2 onto the unit disc: equal areas to equal areas,
// square rings to circles, rays from the square's centre to rays from the
// disc's.
Vec2 concentricDisc(double s, double t);

// A cell of the unit square, s in [s0, s1], t in [t0, t1].
struct DiscCell {
    double s0 = 0.0, s1 = 1.0, t0 = 0.0, t1 = 1.0;
};

// The polar rectangle r in [r0, r1], phi in [phi0, phi1] (phi1 - phi0 <=
// pi / 2) that holds the concentric image of a cell lying in one quadrant of
// the square (every cell but the whole square); the whole square's is the
// whole disc, phi in [0, 2 pi]. The radius of the image of (s, t) is
// max(|2s - 1|, |2t - 1|), and its angle grows with the angle of (2s - 1,
// 2t - 1): the bounds are exact (the cell's corners and its nearest point to
// the centre attain them).
struct PolarBounds {
    double r0 = 0.0, r1 = 1.0, phi0 = 0.0, phi1 = 2.0 * kPi;
};
PolarBounds polarBounds(const DiscCell& cell);
// Its r0 alone: the least radius of the cell's image.
double innerRadius(const DiscCell& cell);

}  // namespace asos
