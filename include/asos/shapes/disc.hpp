#pragma once
// POV-Ray's disc { centre, normal, radius [, hole radius] }: the annulus
// hole <= |x - centre| <= radius in the plane through the centre. The local
// frame puts it in z = 0, centred on the origin, the normal along +z.
// Under a non-uniform scale, a shear or a matrix the disc's record is placed
// as an EllipticDisc instead (place, below): the disc's room is this file,
// disc.cpp and elliptic_disc.hpp/.cpp.
#include <cmath>
#include <optional>
#include <variant>
#include <vector>

#include "asos/geometry/bounds.hpp"
#include "asos/geometry/cone.hpp"
#include "asos/geometry/ray.hpp"
#include "asos/geometry/transform.hpp"
#include "asos/scene/description.hpp"
#include "asos/shapes/cone_geometry.hpp"
#include "asos/shapes/elliptic_disc.hpp"
#include "asos/shapes/holding_planes.hpp"
#include "asos/shapes/local_cone.hpp"
#include "asos/shapes/local_hit.hpp"
#include "asos/shapes/local_rays.hpp"
#include "asos/shapes/placed.hpp"
#include "asos/shapes/shape_issue.hpp"

namespace asos {

class Disc {
public:
    static constexpr const char* kName = "disc";

    Disc(double radius, double holeRadius) : radius_(radius), hole_(holeRadius) {}

    bool empty() const { return !(radius_ > hole_); }
    // Without a hole, a convex region.
    bool convex() const { return !(hole_ > 0.0); }
    bool canShadowItself() const { return false; }  // flat
    // POV-Ray's: the side below the normal, z < 0.
    bool inside(const Vec3& p) const { return p.z < 0.0; }
    bool raysLeave(const LocalRays& rays) const { return rays.leaveZPlane(); }
    HoldingPlanes holdingPlanes(const Vec3&) const { return zPlaneHolding(); }
    double support(const Vec3& dir) const { return radius_ * std::sqrt(dir.x * dir.x + dir.y * dir.y); }
    template <class User>
    decltype(auto) withAnyTestFrom(const Vec3& origin, User&& user) const {
        return user(exactAnyTestFrom(*this, origin));
    }
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
    const conegeom::ZPlaneApproach z = conegeom::zPlaneApproach(cone);
    const auto f = conegeom::annulusFastPath(cone, z, radius_, hole_, {});
    // These answers need no local range (absTol only): `finish` holds their
    // depths against the range (RigidBounds: the world's), which is set
    // only past them.
    if (f.settled) return conegeom::rangedClass(finish, f.miss, f.full, f.tNear, f.tFar);
    if (!z.crosses && conegeom::turnedAwayFromPlane(cone, z.h, z.g2)) return conegeom::missClass();
    setRange();
    if (z.crosses) {
        // A circle near q: the ellipse itself against both circles.
        if (const auto out = bandClass(cone, z.depth, z.an, z.k, f.tNear, f.tFar)) return finish(*out);
        // Within a few tolerances of tangency: the exact test below.
    }
    return finish(classifyExactly(cone));
}

// POV-Ray's disc record: a finite centre, a finite normal that is not zero,
// a positive radius and a hole radius from 0 up to it.
std::vector<ShapeIssue> validate(const DiscShape& record);
// Its Disc in the plane through the centre across the normal, or, where
// worldFromObject is not a similarity, the EllipticDisc that is its image,
// in a rigid frame.
std::variant<Placed<Disc>, Placed<EllipticDisc>> place(const DiscShape& record,
                                                       const Transform& worldFromObject);

}  // namespace asos
