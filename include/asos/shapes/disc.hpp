#pragma once
// POV-Ray's disc { centre, normal, radius [, hole radius] }: the annulus
// hole <= |x - centre| <= radius in the plane through the centre. The local
// frame puts it in z = 0, centred on the origin, the normal along +z.
#include <optional>

#include "asos/geometry/bounds.hpp"
#include "asos/geometry/cone.hpp"
#include "asos/geometry/ray.hpp"
#include "asos/shapes/cone_geometry.hpp"
#include "asos/shapes/local_cone.hpp"
#include "asos/shapes/local_hit.hpp"

namespace asos {

class Disc {
public:
    static constexpr const char* kName = "disc";

    Disc(double radius, double holeRadius) : radius_(radius), hole_(holeRadius) {}

    bool empty() const { return !(radius_ > hole_); }
    // Without a hole, a convex region.
    bool convex() const { return !(hole_ > 0.0); }
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
                              const RigidBounds& back) const {
        return classifyWith(cone, [&] { cone.setRange(t0, t1, cone.absTol); }, back);
    }

private:
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

// Inline, as is classifyRanging: a rigid frame's classification
// (Primitive) then keeps the local cone in registers.
template <class SetRange, class Finish>
inline ConeClass Disc::classifyWith(const LocalCone& cone, SetRange&& setRange, Finish&& finish) const {
    if (empty()) return conegeom::missClass();
    const Vec3& p = cone.apex;
    const Vec3& axis = cone.axis;
    const double c = cone.cosHalf, s = cone.sinHalf;
    const auto [crosses, h, g2, k, an, depth, ank] = conegeom::zPlaneApproach(cone);
    // The fast path's answers are computed for every cone and settled by
    // one branch, taken by most: whether a cone misses, covers or straddles
    // the disc is as good as random from one cone to the next, and a branch
    // per answer would be mispredicted about once a cone (docs/geometry.md,
    // "Disc"). Where the axis does not cross the plane the crossing's
    // values are meaningless (even inf or NaN) and are not selected.
    //
    // Crossing: every ray crosses the plane, at depths [tNear, tFar], and
    // the footprint lies within `reach` of the axis' crossing q (see
    // footprintReach): against the two circles that is a comparison of |q|
    // with their radii, one each way. Scaled by an k (an = |axis.z|), q and
    // reach need no division; |q| is one root.
    const double g = std::sqrt(g2);
    const double qx = an * p.x + depth * axis.x, qy = an * p.y + depth * axis.y;
    const double q = std::sqrt(qx * qx + qy * qy) * k;
    const double reach = conegeom::scaledReach(depth, an, g2, c, s, cone.absTol, ank);
    // The footprint holds the disc of radius L s / (c + s) >= L s (1 - s)
    // about the crossing (L = depth / an, the axis' depth): a circle
    // through that disc has footprint points on both sides, in the annulus
    // and off it, so the cone is Marginal without the ellipse.
    const double inner = depth * k * s * (1.0 - s) * (1.0 - 1e-12) - cone.absTol * ank;
    const auto [miss, full, nearCircle] = conegeom::annulusAgainstFootprint(
        q, reach, inner, ank * radius_, ank * (hole_ > 0.0 ? hole_ : -kInfinity));
    const auto [tNear, tFar] = conegeom::planeDepthsWithG(depth, an, g2, g, c, s);
    // No crossing: the axis turned away from the plane, and every ray with
    // it, is a Miss.
    const bool away = conegeom::turnedAwayFromPlane(cone, h, g2);
    // These answers need no local range (absTol only): `finish` holds their
    // depths against the range (RigidBounds: the world's), which is set
    // only past them.
    if ((crosses & (miss | full | nearCircle)) | (!crosses & away))
        return conegeom::rangedClass(finish, miss | !crosses, full & crosses, tNear, tFar);
    setRange();
    if (crosses) {
        // A circle near q: the ellipse itself against both circles.
        if (const auto out = bandClass(cone, depth, an, k, tNear, tFar)) return finish(*out);
        // Within a few tolerances of tangency: the exact test below.
    }
    return finish(classifyExactly(cone));
}

}  // namespace asos
