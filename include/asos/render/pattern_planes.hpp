#pragma once
// The edge planes of a pattern along one axis of pattern space: the planes of
// constant coordinate p = period (k + offset) - shift, for every integer k and
// each of a few offsets in [0, 1). checker and brick have all their edges on
// such planes (CheckerPattern::planes, BrickPattern::planes), so the pattern
// is one colour in each cell they cut space into; the pattern filter
// (render/pattern_filter.hpp) clips a footprint along them.
#include <array>
#include <cmath>

namespace asos {

struct PatternPlanes {
    double period = 1.0;  // positive
    double shift = 0.0;
    std::array<double, 4> offsets{};  // ascending, in [0, 1); `count` of them are used
    int count = 0;

    // The number of planes strictly inside (lo, hi), or `limit` + 1 once it
    // exceeds `limit` (without visiting a far range plane by plane), or where
    // the range lies too far out for whole periods to be told apart (2^50
    // periods: forEachInside steps by one period). forEachInside is only
    // called on ranges this has counted.
    int countInside(double lo, double hi, int limit) const {
        constexpr double kFarthest = 0x1p50;
        const double tlo = units(lo), thi = units(hi);
        if (!(std::fabs(tlo) < kFarthest && std::fabs(thi) < kFarthest)) return limit + 1;
        const double periods = std::floor(thi) - std::floor(tlo);
        if (!(periods * count <= limit)) return limit + 1;
        int n = 0;
        forEachInside(lo, hi, [&](double) { ++n; });
        return n;
    }

    // Calls visit(p) for each plane strictly inside (lo, hi), in ascending p
    // (a range within one that countInside counted).
    template <class Visit>
    void forEachInside(double lo, double hi, Visit&& visit) const {
        const double tlo = units(lo), thi = units(hi);
        for (double cell = std::floor(tlo); cell <= thi; cell += 1.0)
            for (int i = 0; i < count; ++i) {
                const double t = cell + offsets[i];
                if (t > tlo && t < thi) visit(t * period - shift);
            }
    }

private:
    double units(double p) const { return (p + shift) / period; }
};

// The average over [a, b] of a function of one coordinate, given its
// antiderivative `integral` and its value `at` a point: (F(b) - F(a)) /
// (b - a), or the value at the middle where the interval is too short for
// that difference to mean anything (a surface in a plane of constant
// coordinate, as a floor in the checker's y = 0).
template <class Integral, class At>
double averageOverInterval(double a, double b, Integral&& integral, At&& at) {
    constexpr double kShortest = 1e-9;  // relative to the coordinates' size
    if (!(b - a > kShortest * (1.0 + std::fabs(a) + std::fabs(b)))) return at(0.5 * (a + b));
    return (integral(b) - integral(a)) / (b - a);
}

}  // namespace asos
