#pragma once
// The eye pyray (paper: "Adaptive Supersampling in Object-Space", Figures 1
// and 2): the rays from the camera through a square of the image plane (a
// pixel, or a sub-pixel at level K), its bounding cone, and its four
// sub-pyrays, the quarters of the square.
//
// The camera belongs to the renderer; a pyray only needs its map from image
// plane coordinates (u, v) to a world ray with a unit direction, a callable
// `Ray rayAt(double u, double v)`. Two kinds of map are accepted:
//   perspective:  every ray starts at one point (bitwise the same origin) and
//                 its direction is a positive multiple of a function affine
//                 in (u, v) (a pinhole camera: forward + u right + v up);
//   orthographic: every ray has one direction (bitwise the same) and its
//                 origin is affine in (u, v).
// Under those maps the pyray of a square holds exactly the rays through the
// square, and the four sub-squares' pyrays tile it.
#include <array>
#include <stdexcept>

#include "asos/geometry/beam.hpp"

namespace asos {

// [u0, u1] x [v0, v1] of the image plane.
struct ImageSquare {
    double u0 = 0.0, v0 = 0.0, u1 = 1.0, v1 = 1.0;

    double uMid() const { return 0.5 * (u0 + u1); }
    double vMid() const { return 0.5 * (v0 + v1); }
    // The image point at fractions f of the square (a jittered ray's).
    Vec2 pointAt(const Vec2& f) const { return {u0 + f.x * (u1 - u0), v0 + f.y * (v1 - v0)}; }
    // Quarter q: bit 0 picks the upper u half, bit 1 the upper v half. The
    // quarters share their edges exactly (the same midpoints).
    ImageSquare quarter(int q) const {
        const double um = uMid(), vm = vMid();
        return {(q & 1) ? um : u0, (q & 2) ? vm : v0, (q & 1) ? u1 : um, (q & 2) ? v1 : vm};
    }
};

enum class Projection { Perspective, Orthographic };

class EyePyray {
public:
    // The level-`level` pyray of `square`; rays cover distances [tMin, tMax]
    // from their origins. Throws std::invalid_argument if the map's corner
    // rays share neither their origin nor their direction, or (perspective)
    // if the square spans half the sphere of directions or more.
    template <class RayAt>
    static EyePyray make(const RayAt& rayAt, const ImageSquare& square, int level = 0,
                         double tMin = 0.0, double tMax = kInfinity) {
        const std::array<Ray, 4> corners = {rayAt(square.u0, square.v0), rayAt(square.u1, square.v0),
                                            rayAt(square.u1, square.v1), rayAt(square.u0, square.v1)};
        return EyePyray(square, level, rayAt(square.uMid(), square.vMid()), corners, tMin, tMax);
    }

    // The four level K+1 sub-pyrays, in ImageSquare::quarter order.
    template <class RayAt>
    std::array<EyePyray, 4> split(const RayAt& rayAt) const {
        return {make(rayAt, square_.quarter(0), level_ + 1, tMin_, tMax_),
                make(rayAt, square_.quarter(1), level_ + 1, tMin_, tMax_),
                make(rayAt, square_.quarter(2), level_ + 1, tMin_, tMax_),
                make(rayAt, square_.quarter(3), level_ + 1, tMin_, tMax_)};
    }

    // The ray through the point (u0 + xi1 (u1 - u0), v0 + xi2 (v1 - v0)) of
    // the square, for xi1, xi2 in [0, 1): a jittered ray inside the pyray,
    // determined by the two numbers.
    template <class RayAt>
    Ray sampleRay(const RayAt& rayAt, double xi1, double xi2) const {
        return rayAt(square_.u0 + xi1 * (square_.u1 - square_.u0),
                     square_.v0 + xi2 * (square_.v1 - square_.v0));
    }

    // The K-ray: through the centre of the square.
    const Ray& centralRay() const { return central_; }
    // Through the corners (u0,v0), (u1,v0), (u1,v1), (u0,v1).
    const std::array<Ray, 4>& cornerRays() const { return corners_; }
    const ImageSquare& square() const { return square_; }
    int level() const { return level_; }
    // The share of the level-0 square: 4^-level, exactly (the paper's area
    // 1/2^2K of a K-pyray).
    double weight() const;
    Projection projection() const { return projection_; }
    double tMin() const { return tMin_; }
    double tMax() const { return tMax_; }

    // The bounding cone. Perspective: apex at the eye, axis the central ray,
    // half-angle the largest angle to a corner ray (the smallest cone about
    // the central ray holding the pyray; its rim touches a corner ray), t in
    // [tMin, tMax]. Orthographic: the pyray is a prism (apex at infinity); the
    // cone has its apex on the central ray far behind the origins and holds
    // the prism's points for t in [tMin, tMax] (docs/accel.md: within 1/16 of
    // the prism's width over a finite depth, and a half-angle of 2^-12 rad
    // when tMax is infinite).
    const Cone& cone() const { return cone_; }

private:
    EyePyray(const ImageSquare& square, int level, const Ray& central,
             const std::array<Ray, 4>& corners, double tMin, double tMax);

    ImageSquare square_;
    int level_ = 0;
    Ray central_;
    std::array<Ray, 4> corners_;
    double tMin_ = 0.0;
    double tMax_ = kInfinity;
    Projection projection_ = Projection::Perspective;
    Cone cone_;
};

}  // namespace asos
