#pragma once
// POV-Ray's disc { centre, normal, radius [, hole radius] }: the annulus
// hole <= |x - centre| <= radius in the plane through the centre. The local
// frame puts it in z = 0, centred on the origin, the normal along +z.
#include <optional>

#include "asos/geometry/bounds.hpp"
#include "asos/geometry/cone.hpp"
#include "asos/geometry/ray.hpp"
#include "asos/shapes/local_cone.hpp"
#include "asos/shapes/local_frame.hpp"
#include "asos/shapes/local_hit.hpp"

namespace asos {

class Disc {
public:
    static constexpr const char* kName = "disc";

    Disc(double radius, double holeRadius) : radius_(radius), hole_(holeRadius) {}

    bool empty() const { return !(radius_ > hole_); }
    BoundingSphere boundingSphere() const { return {Vec3(0.0), radius_}; }
    Bounds3 worldBounds(const Mat3& worldFromLocal, const Vec3& offset) const;

    std::optional<LocalHit> intersect(const Ray& ray, double tMin, double tMax) const;
    // intersect(ray, tMin, tMax).has_value(), inline and without the hit
    // record (the inner loop of an area light's point samples).
    bool intersectAny(const Ray& ray, double tMin, double tMax) const {
        if (empty()) return false;
        const auto hit = crossZPlane(ray, tMin, tMax);
        if (!hit) return false;
        const double r2 = hit->x * hit->x + hit->y * hit->y;
        return !(r2 > radius_ * radius_ || r2 < hole_ * hole_);
    }
    // The two circles are the boundary, tested against the cone's elliptic
    // footprint in the disc's plane; see docs/geometry.md.
    ConeClass classify(const LocalCone& cone) const;
    // A rigid frame's answer in world units (Primitive::classifyRigid), for
    // a cone whose range is not set yet (apex, axis, angle and absTol are):
    // the range [t0, t1] is set and `back` applied only past the fast path's
    // Miss, which needs neither (docs/geometry.md, "Disc").
    ConeClass classifyRanging(LocalCone& cone, double t0, double t1,
                              const RigidBounds& back) const;

    // Under a non-uniform frame (Primitive::classifyGeneral): the fast path
    // in world terms, the cone as it is and the disc's plane mapped, its
    // in-plane reach scaled by the frame's largest singular value; a Miss or
    // a Full in world units, or nullopt for the bounding-cone path
    // (docs/geometry.md, "Disc").
    std::optional<ConeClass> classifyAcrossScale(const PreparedCone& cone,
                                                 const LocalFrame& frame) const;

private:
    // The fast paths' reach, scaled by an k as their crossing is: every point
    // of the footprint lies within it of the axis' crossing (footprintReach's
    // bound, without its divisions), padded by absTol.
    static double scaledReach(double depth, double an, double g2, double c, double s,
                              double absTol, double ank) {
        return depth * s * (c * an + 0.5 * (1.0 + g2) * s) * (1.0 + 1e-12) + absTol * ank;
    }
    struct ReachAnswer {
        bool miss, full;
    };
    // The fast paths' answer: every point of the footprint lies within
    // `radius` of the axis' crossing q (|q|^2 = q2), all scaled by `ank`:
    // Miss when that reach stays off the annulus, Full when inside it.
    ReachAnswer circlesAgainstReach(double q2, double ank, double radius) const {
        const double outerFar = ank * radius_ + radius, outerNear = ank * radius_ - radius;
        const double holeFar = ank * hole_ + radius, holeNear = ank * hole_ - radius;
        const bool miss = (q2 > outerFar * outerFar) | ((holeNear > 0.0) & (q2 < holeNear * holeNear));
        const bool full = (outerNear > 0.0) & (q2 < outerNear * outerNear) &
                          ((hole_ == 0.0) | (q2 > holeFar * holeFar));
        return {miss, full};
    }

    template <class SetRange, class Finish>
    ConeClass classifyWith(const LocalCone& cone, SetRange&& setRange, Finish&& finish) const;
    // The fast path's cones near a circle: the footprint ellipse against both
    // circles; nullopt within a few tolerances of tangency. Out of line, so
    // that the commoner Miss and Full answers do not carry its registers.
    [[gnu::noinline]] std::optional<ConeClass> bandClass(const LocalCone& cone, double depth,
                                                         double an, double k, double tNear,
                                                         double tFar) const;
    // Both circles against the cone (the fast path's fallback near tangency).
    ConeClass classifyExactly(const LocalCone& cone) const;

    double radius_;
    double hole_;
};

}  // namespace asos
