#pragma once
// Where a shadow beam's rays run: the convex hull of its apex and a convex
// polygon at the light (a rectangle's corners; a segment's ends, the hull then
// a triangle; the square about a sphere's tangent circle), each base point
// drawn toward the apex by the fraction of the beam's length its rays stop
// short of the light. Every stretch of a ray the tracer tests lies inside, so
// an object shown to lie outside is no occluder of the beam. The beam's cone
// (up to a spherical cap at the light's farthest point, and round about a
// pyramid) reaches farther: beyond the light, and beside the beam
// (docs/lights.md, "Where a beam ends").
//
// Two proofs that an object lies outside, for two uses:
//   - Whole: any face of the hull, or its box, separates the object's box
//     (or a plane misses every point of the hull). For the point samples of
//     a piece: leaving out an occluder their rays cannot meet changes no
//     answer.
//   - BeyondLight: a plane at the light alone (a rectangle's own, the
//     sphere's tangent circle's; for a segment, any plane through it within
//     60 degrees of square to the triangle, never near the triangle's own
//     plane, which would show objects beside the beam), for the part of the
//     object inside a given box that holds the beam's cone: the object lies
//     beyond the light wherever the cone reaches it. For detection: a beam's
//     verdict then changes only where an object lies beyond the light.
#include <array>
#include <optional>

#include "asos/geometry/bounds.hpp"

namespace asos {

class BeamHull {
public:
    static constexpr int kMaxBase = 4;

    // The hull of `apex` and base[0..count), 2 <= count <= kMaxBase, the base
    // a convex polygon (its points in order around it) or a segment, for a
    // beam whose rays reach points y of the light inside the hull of the apex
    // and the base, |y - apex| <= reach, and stop endGap before them. Each
    // base point b is taken as apex + (1 - endGap / reach) (b - apex): a ray
    // toward y stops at apex + (1 - endGap / |y - apex|) (y - apex), inside
    // that smaller hull. None where the base is degenerate as seen from the
    // apex (the apex in its plane or on its line, below rounding) or the gap
    // reaches the apex.
    static std::optional<BeamHull> over(const Vec3& apex, const Vec3* base, int count, double reach,
                                        double endGap);

    // The same hull, its answers proved by a plane at the light alone, for
    // the part of an object inside `reach` (a finite box that holds the
    // beam's cone).
    BeamHull beyondLight(const Bounds3& reach) const;

    // Whether the box lies outside, past rounding.
    bool missesBox(const Bounds3& box) const;
    // Whether the plane through `point` with unit `normal` misses the hull,
    // past rounding: no stretch of a ray in it crosses the plane.
    bool missesPlane(const Vec3& normal, const Vec3& point) const;

private:
    // The points x with dot(normal, x) <= offset; `size` is the normal's
    // L1 norm (normals are left as computed: no square root).
    struct Face {
        Vec3 normal;
        double offset;
        double size;
    };
    // The face across `normal` that holds every point: its offset is the
    // points' largest, so that it holds them however rounding turned the
    // normal.
    void addFace(const Vec3& normal);
    // The margin past which a side of a plane with a unit normal is known,
    // for coordinates up to `magnitude` besides the hull's.
    double margin(double magnitude) const;
    // Whether points[0..count) lie beyond the light: past the base's face
    // (a pyramid), or past one plane through the segment (a triangle).
    bool beyondLight(const Vec3* points, int count, double magnitude) const;

    std::array<Vec3, kMaxBase + 1> points_{};
    int count_ = 0;
    std::array<Face, kMaxBase + 2> faces_{};  // faces_[0]: the base's, or the segment's square to the triangle
    int faceCount_ = 0;
    bool triangle_ = false;
    Vec3 across_{0.0};  // a triangle's unit normal
    Bounds3 box_;
    double scale_ = 0.0;  // the largest coordinate's magnitude: the rounding margins' unit
    std::optional<Bounds3> reach_;  // BeyondLight: the box the proof is confined to
};

}  // namespace asos
