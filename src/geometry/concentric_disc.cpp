#include "asos/geometry/concentric_disc.hpp"

#include <algorithm>
#include <cmath>

namespace asos {

Vec2 concentricDisc(double s, double t) {
    const double a = 2.0 * s - 1.0, b = 2.0 * t - 1.0;
    if (a == 0.0 && b == 0.0) return Vec2(0.0);
    double r, phi;
    if (std::abs(a) > std::abs(b)) {
        r = a;
        phi = 0.25 * kPi * (b / a);
    } else {
        r = b;
        phi = 0.5 * kPi - 0.25 * kPi * (a / b);
    }
    return {r * std::cos(phi), r * std::sin(phi)};
}

Vec2 povrayDisc(double s, double t) {
    const double a = 2.0 * s - 1.0, b = 2.0 * t - 1.0;
    if (a == 0.0 && b == 0.0) return Vec2(0.0);
    const double scale = std::max(std::abs(a), std::abs(b)) / std::sqrt(a * a + b * b);
    return {a * scale, b * scale};
}

double innerRadius(const DiscCell& c) {
    // The radius is the largest coordinate's size (square rings to circles),
    // least at the cell's nearest point to the centre.
    const auto gap = [](double lo, double hi) { return lo > 0.0 ? lo : (hi < 0.0 ? -hi : 0.0); };
    return std::max(gap(2.0 * c.s0 - 1.0, 2.0 * c.s1 - 1.0), gap(2.0 * c.t0 - 1.0, 2.0 * c.t1 - 1.0));
}

PolarBounds polarBounds(const DiscCell& c, DiscMap map) {
    const double a[2] = {2.0 * c.s0 - 1.0, 2.0 * c.s1 - 1.0}, b[2] = {2.0 * c.t0 - 1.0, 2.0 * c.t1 - 1.0};
    PolarBounds p;
    p.r0 = innerRadius(c);
    p.r1 = std::max(std::max(std::abs(a[0]), std::abs(a[1])), std::max(std::abs(b[0]), std::abs(b[1])));
    // A cell across an axis (the whole square): every angle.
    if ((a[0] < 0.0 && a[1] > 0.0) || (b[0] < 0.0 && b[1] > 0.0)) return p;
    // The quadrant, and the corners turned into the first one by quarter
    // turns (both maps commute with them); there the concentric map's angle
    // is (pi/4) y/x below the diagonal and pi/2 - (pi/4) x/y above it,
    // growing with atan2(y, x), and POV-Ray's is atan2(y, x) itself, so a
    // convex cell's angles lie between its corners' (the centre, where it is
    // a corner, has none).
    const double ac = a[0] + a[1], bc = b[0] + b[1];
    const int quadrant = ac > 0.0 ? (bc > 0.0 ? 0 : 3) : (bc > 0.0 ? 1 : 2);
    p.phi0 = 2.0 * kPi;
    p.phi1 = 0.0;
    for (int i = 0; i < 4; ++i) {
        const double u = a[i & 1], v = b[i >> 1];
        double x = u, y = v;
        switch (quadrant) {
            case 1: x = v, y = -u; break;
            case 2: x = -u, y = -v; break;
            case 3: x = -v, y = u; break;
            default: break;
        }
        if (x == 0.0 && y == 0.0) continue;
        const double within = map == DiscMap::Povray ? std::atan2(y, x)
                              : x >= y               ? 0.25 * kPi * (y / x)
                                                     : 0.5 * kPi - 0.25 * kPi * (x / y);
        const double phi = 0.5 * kPi * quadrant + within;
        p.phi0 = std::min(p.phi0, phi);
        p.phi1 = std::max(p.phi1, phi);
    }
    return p;
}

}  // namespace asos
