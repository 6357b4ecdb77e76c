#include "asos/render/brick_pattern.hpp"

#include <algorithm>
#include <cmath>

#include "asos/render/shading.hpp"

namespace asos {

namespace {

// POV-Ray takes the fraction as t - trunc(t), plus 1 below zero; that is
// t - floor(t) to the bit (the same real number, rounded once), without the
// integer conversion that overflows on far coordinates.
double fraction(double t) { return t - std::floor(t); }

// The band's rank along its axis: the joint of a cell, then its brick.
double rank(bool joint, double cell) { return 2.0 * cell + (joint ? 0.0 : 1.0); }

// The mean over [a, b] of the brick part of a pulse train of period 1 whose
// joints are frac(t + offset) <= share: the antiderivative counts (1 -
// share) per whole period and the part of the last beyond its joint.
double pulseMean(double a, double b, double offset, double share) {
    const double s = std::clamp(share, 0.0, 1.0);
    auto integral = [&](double t) {
        const double u = t + offset;
        return std::floor(u) * (1.0 - s) + std::max(fraction(u) - s, 0.0);
    };
    auto at = [&](double t) { return fraction(t + offset) > share ? 1.0 : 0.0; };
    return averageOverInterval(a, b, integral, at);
}

// The mean over [a, b] of the brick part of the courses of one parity (0:
// floor(t) even, 1: odd), period 2, joints frac(t) <= share.
double courseMean(double a, double b, int parity, double share) {
    const double s = std::clamp(share, 0.0, 1.0);
    auto integral = [&](double t) {
        const double pairs = std::floor(0.5 * t);
        return pairs * (1.0 - s) + std::clamp(t - 2.0 * pairs - parity - s, 0.0, 1.0 - s);
    };
    auto at = [&](double t) {
        const bool odd = fraction(0.5 * t) > 0.5;
        return fraction(t) > share && odd == (parity == 1) ? 1.0 : 0.0;
    };
    return averageOverInterval(a, b, integral, at);
}

}  // namespace

BrickPattern::BrickPattern(const Vec3& brickSize, double mortar)
    : size_(brickSize),
      mortar_(static_cast<float>(mortar - 2.0 * kPovEpsilon)),
      jointShare_(mortar_ / brickSize) {}

BrickPattern::Bands BrickPattern::locate(const Vec3& patternPoint) const {
    // POV-Ray moves the pattern by the mortar (plus its EPSILON, as the
    // checker's): a joint ends at each multiple of the size.
    const Vec3 units = (patternPoint + (kPovEpsilon + mortar_)) / size_;
    auto band = [](double t, double share) { return Band{std::floor(t), fraction(t) <= share}; };
    Bands b;
    b.bed = band(units.y, jointShare_.y);
    b.oddCourse = fraction(units.y * 0.5) > 0.5;
    // Even courses: head joints at whole bricks along x, half bricks along z;
    // odd courses the other way round.
    b.head[0][0] = band(units.x, jointShare_.x);
    b.head[0][1] = band(units.z + 0.5, jointShare_.z);
    b.head[1][0] = band(units.x + 0.5, jointShare_.x);
    b.head[1][1] = band(units.z, jointShare_.z);
    return b;
}

int BrickPattern::value(const Vec3& patternPoint) const {
    const Bands b = locate(patternPoint);
    if (b.bed.joint) return 0;
    const Band* head = b.head[b.oddCourse ? 1 : 0];
    return head[0].joint || head[1].joint ? 0 : 1;
}

double BrickPattern::edgesCrossed(const Vec3& lo, const Vec3& hi) const {
    // Each band moves one way along its own axis only, so over the box it
    // stays between its values at the two corners lo and hi.
    const Bands a = locate(lo);
    const Bands b = locate(hi);
    auto crossed = [](const Band& s, const Band& t) {
        return std::abs(rank(t.joint, t.cell) - rank(s.joint, s.cell));
    };
    const bool oneCourse = crossed(a.bed, b.bed) == 0.0 && a.oddCourse == b.oddCourse;
    if (oneCourse) {
        if (a.bed.joint) return 0.0;  // inside one bed joint: mortar all over
        const int c = a.oddCourse ? 1 : 0;
        return crossed(a.head[c][0], b.head[c][0]) + crossed(a.head[c][1], b.head[c][1]);
    }
    double n = crossed(a.bed, b.bed) + (a.oddCourse != b.oddCourse ? 1.0 : 0.0);
    for (int c = 0; c < 2; ++c) n += crossed(a.head[c][0], b.head[c][0]) + crossed(a.head[c][1], b.head[c][1]);
    return n;
}

PatternPlanes BrickPattern::planes(int axis) const {
    const double share = jointShare_[axis];
    // Planes at size (k + side) - shift; a negative size counts its sides
    // the other way along a positive period.
    const double size = size_[axis];
    PatternPlanes p{std::fabs(size), kPovEpsilon + mortar_, {}, 0};
    // A joint spans frac in [0, share]: the planes at its two sides, for the
    // head joints of both parities of course (moved by half a brick).
    auto offset = [&](double side) { return fraction(size > 0.0 ? side : -side); };
    if (axis == 1) {
        const double foot = offset(0.0), top = offset(share);
        p.offsets = {std::min(foot, top), std::max(foot, top)};
        p.count = 2;
    } else {
        p.offsets = {offset(0.0), offset(share), offset(0.5), offset(0.5 + share)};
        std::sort(p.offsets.begin(), p.offsets.end());
        p.count = 4;
    }
    return p;
}

double BrickPattern::boxShare(const Vec3& lo, const Vec3& hi) const {
    const Vec3 a = (lo + (kPovEpsilon + mortar_)) / size_;
    const Vec3 b = (hi + (kPovEpsilon + mortar_)) / size_;
    const Vec3 from = glm::min(a, b), to = glm::max(a, b);  // a size may be negative
    const Vec3& m = jointShare_;
    const double even = courseMean(from.y, to.y, 0, m.y) * pulseMean(from.x, to.x, 0.0, m.x) *
                        pulseMean(from.z, to.z, 0.5, m.z);
    const double odd = courseMean(from.y, to.y, 1, m.y) * pulseMean(from.x, to.x, 0.5, m.x) *
                       pulseMean(from.z, to.z, 0.0, m.z);
    return std::clamp(even + odd, 0.0, 1.0);
}

}  // namespace asos
