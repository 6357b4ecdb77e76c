#pragma once
// A disc under a non-uniform scale, a shear or a matrix: an elliptic annulus
// in a world plane, a local form of the disc's record (part of the disc's
// room: disc.hpp places it). It is laid out in a rigid frame
// (LocalFrame::flattened) whose x and y run along the ellipse's axes, so
// that it is hole <= |(x / ax, y / ay)| <= 1 in the plane z = 0 (the hole a
// fraction of the outer ellipse). Its cones then stay circular, and are
// classified in the stretched coordinates (x / ax, y / ay), where the annulus
// is circular and the cone's footprint is another ellipse; no bounding cone.
#include <cmath>
#include <optional>

#include "asos/geometry/bounds.hpp"
#include "asos/geometry/ray.hpp"
#include "asos/shapes/holding_planes.hpp"
#include "asos/shapes/local_cone.hpp"
#include "asos/shapes/local_hit.hpp"
#include "asos/shapes/local_rays.hpp"

namespace asos {

class EllipticDisc {
public:
    static constexpr const char* kName = "disc";

    // Semi-axes ax, ay > 0 along local x and y; 0 <= holeRatio < 1.
    EllipticDisc(double ax, double ay, double holeRatio);

    // Without a hole, a convex region.
    bool convex() const { return !(hole_ > 0.0); }
    bool canShadowItself() const { return false; }  // flat
    // The disc's (disc.hpp): below the plane, on the side away from the
    // normal, which the rigid frame keeps along +z.
    bool inside(const Vec3& p) const { return p.z < 0.0; }
    bool raysLeave(const LocalRays& rays) const { return rays.leaveZPlane(); }
    HoldingPlanes holdingPlanes(const Vec3&) const { return zPlaneHolding(); }
    double support(const Vec3& dir) const {
        const double x = ax_ * dir.x, y = ay_ * dir.y;
        return std::sqrt(x * x + y * y);
    }
    template <class User>
    decltype(auto) withAnyTestFrom(const Vec3& origin, User&& user) const {
        return user(exactAnyTestFrom(*this, origin));
    }
    BoundingSphere boundingSphere() const { return {Vec3(0.0), reach_}; }
    Bounds3 worldBounds(const Mat3& worldFromLocal, const Vec3& offset) const;

    std::optional<LocalHit> intersect(const Ray& ray, double tMin, double tMax) const {
        const auto hit = crossZPlane(ray, tMin, tMax);
        if (!hit || !contains(hit->x, hit->y)) return std::nullopt;
        return LocalHit{hit->t, Vec3(hit->x, hit->y, 0.0), Vec3(0.0, 0.0, 1.0)};
    }
    bool intersectAny(const Ray& ray, double tMin, double tMax) const {
        const auto hit = crossZPlane(ray, tMin, tMax);
        return hit && contains(hit->x, hit->y);
    }
    ConeClass classify(const LocalCone& cone) const;
    // As Disc::classifyRanging: the range set and `back` applied only past
    // the fast path's Miss.
    ConeClass classifyRanging(LocalCone& cone, double t0, double t1, const RigidBounds& back) const;

private:
    bool contains(double x, double y) const {
        const double u = x * dx_, v = y * dy_, r2 = u * u + v * v;
        return !(r2 > 1.0 || r2 < hole_ * hole_);
    }
    template <class SetRange, class Finish>
    ConeClass classifyWith(const LocalCone& cone, SetRange&& setRange, Finish&& finish) const;
    // The fast path's cones near a circle: the stretched footprint against
    // both circles, from its supports along and across the direction of its
    // centre; nullopt where those leave it undecided.
    [[gnu::noinline]] std::optional<ConeClass> bandClass(const LocalCone& cone, double depth,
                                                         double an, double k, double tNear,
                                                         double tFar) const;
    // Both circles of the stretched plane against the cone's stretched
    // footprint, exactly (the band's undecided cones, and the cones off the
    // fast path).
    [[gnu::noinline]] ConeClass classifyExactly(const LocalCone& cone) const;

    double ax_, ay_;
    double dx_, dy_;      // 1 / ax, 1 / ay: the stretch
    double dMax_, dMin_;  // max(dx, dy), rounded up; min(dx, dy), rounded down
    double hole_;
    double reach_;        // max(ax, ay)
};

}  // namespace asos
