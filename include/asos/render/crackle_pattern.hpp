#pragma once
// POV-Ray 3.7's crackle pattern, in pattern space: one point in each unit
// cube (placed by POV-Ray's lattice hash and its table of 32768 random
// numbers), and at a point the distances to the nearest three of them,
// weighted by `form` and clipped to [0, 1]. The default form <-1, 1, 0> is
// the second distance less the first: 0 on the walls between cells (a 3D
// Voronoi diagram). `metric` is the exponent of the distance (2 Euclidean,
// 1 the sum of the coordinates' differences), `offset` is added to each
// distance, and `solid` gives each cell one value, the noise at its point.
// The candidates are the points of the point's cube and its 80 neighbours
// that differ by at most 2 on one axis and 1 on the others, as POV-Ray
// searches them (docs/algorithm.md, "Map patterns").
#include <array>

#include "asos/geometry/vec.hpp"

namespace asos {

struct Pigment;

class CracklePattern {
public:
    // The tables, built once and then only read.
    static const CracklePattern& tables();

    // The value in [0, 1] at a pattern-space point (after any turbulence),
    // under the pigment's form, metric, offset and solid; `generator`: the
    // noise generator a solid crackle's cells take their values from.
    double value(const Pigment& p, const Vec3& q, int generator) const;

    // The point POV-Ray places in the unit cube whose lowest corner is
    // (x, y, z) (its IntPickInCube).
    Vec3 pointInCube(int x, int y, int z) const;

private:
    CracklePattern();

    // POV-Ray's PatternRands: Boost's mt19937 (default seed) through
    // uniform_real(0, 1), 32768 values.
    std::array<double, 32768> randoms_{};
    // The offsets of the 81 cubes searched, in POV-Ray's order.
    std::array<std::array<int, 3>, 81> cubes_{};
};

}  // namespace asos
