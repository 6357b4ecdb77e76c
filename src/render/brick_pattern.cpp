#include "asos/render/brick_pattern.hpp"

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

}  // namespace asos
