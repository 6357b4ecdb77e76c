#pragma once
// POV-Ray 3.7's brick pattern, in pattern space. Bricks of brick_size
// <w, h, d> are laid in courses along y; `mortar` is the joint's thickness.
// After POV-Ray shifts every coordinate by mortar + 1e-10, with X = x / w,
// Y = y / h, Z = z / d and frac(t) = t - floor(t), a point is mortar
//  - in a bed joint: frac(Y) <= mortar / h (one layer at the foot of each
//    course);
//  - in a head joint of its course: in even courses (floor(Y) even) where
//    frac(X) <= mortar / w or frac(Z + 1/2) <= mortar / d, in odd courses
//    where frac(X + 1/2) <= mortar / w or frac(Z) <= mortar / d: the joints
//    move by half a brick from one course to the next;
// and brick elsewhere. POV-Ray keeps the mortar as a float less 2e-10 (the
// default 0.5 stays 0.5); so do we. Measured against povray's renders in
// tests/golden/povray/brick.pov.
#include "asos/geometry/vec.hpp"
#include "asos/render/pattern_planes.hpp"

namespace asos {

class BrickPattern {
public:
    // brick_size and mortar as the scene gives them (no component of the
    // size is 0: POV-Ray divides by them).
    BrickPattern(const Vec3& brickSize, double mortar);

    // 0 (mortar, the pattern's first colour) or 1 (brick, its second) at a
    // pattern-space point.
    int value(const Vec3& patternPoint) const;

    // How many of the pattern's edge planes the pattern-space box [lo, hi]
    // straddles, counted generously: 0 only when the pattern is the same all
    // over the box, 1 only when the box straddles one plane (which meets a
    // plane through the box in one straight line). The edges are planes of
    // constant y (two per course: the top and the foot of its bed joint) and,
    // within a course, planes of constant x and of constant z (two per head
    // joint); where the box meets more than one course, the head joints of
    // both parities count.
    double edgesCrossed(const Vec3& lo, const Vec3& hi) const;

    // The edge planes along `axis` (0, 1, 2): along y the foot and top of
    // each bed joint, along x and z the sides of the head joints of both
    // parities of course (a plane where a course has no joint is a harmless
    // extra cut).
    PatternPlanes planes(int axis) const;

    // The share of the box [lo, hi] in brick (value 1), in closed form. The
    // brick indicator is a sum of two products of one-coordinate pulse
    // trains, one per parity of course:
    //   [frac(Y) > m_y] ([even Y] [frac(X) > m_x] [frac(Z + 1/2) > m_z]
    //                  + [odd Y]  [frac(X + 1/2) > m_x] [frac(Z) > m_z])
    // (X, Y, Z, m as above), so over a box it is the same sum of products of
    // the factors' means, each from its antiderivative. An axis of no width
    // is taken at its point.
    double boxShare(const Vec3& lo, const Vec3& hi) const;

private:
    // Where a point lies along the axes, as numbers that change only across
    // an edge and move one way along each axis (value's own arithmetic, so
    // that two points with equal bands have the same value).
    struct Band {
        double cell = 0.0;   // floor of the coordinate in brick units
        bool joint = false;  // in the mortar at the foot of that cell
    };
    struct Bands {
        Band bed;                // along y
        bool oddCourse = false;  // POV-Ray's test: frac(Y / 2) > 1/2
        Band head[2][2];         // [course parity][x, z]
    };
    Bands locate(const Vec3& patternPoint) const;

    Vec3 size_;
    double mortar_;    // POV-Ray's: a float, less 2e-10
    Vec3 jointShare_;  // mortar / size, per axis
};

}  // namespace asos
