#pragma once
// POV-Ray's plane { normal, distance }: the points x with n.x = distance for
// the unit n along the given normal. The local frame is the object frame.
#include <optional>
#include <vector>

#include "asos/geometry/bounds.hpp"
#include "asos/geometry/cone.hpp"
#include "asos/geometry/ray.hpp"
#include "asos/geometry/transform.hpp"
#include "asos/scene/description.hpp"
#include "asos/shapes/holding_planes.hpp"
#include "asos/shapes/local_cone.hpp"
#include "asos/shapes/local_hit.hpp"
#include "asos/shapes/local_rays.hpp"
#include "asos/shapes/placed.hpp"
#include "asos/shapes/shape_issue.hpp"

namespace asos {

class Plane {
public:
    static constexpr const char* kName = "plane";

    Plane(const Vec3& unitNormal, double distance) : normal_(unitNormal), distance_(distance) {}

    const Vec3& normal() const { return normal_; }
    double distance() const { return distance_; }
    BoundingSphere boundingSphere() const { return {distance_ * normal_, kInfinity}; }
    Bounds3 worldBounds(const Mat3&, const Vec3&) const {
        return {Vec3(-kInfinity), Vec3(kInfinity)};
    }

    std::optional<LocalHit> intersect(const Ray& ray, double tMin, double tMax) const;
    bool intersectAny(const Ray& ray, double tMin, double tMax) const {
        return intersect(ray, tMin, tMax).has_value();
    }
    // Exact: from the range of n.d over the cone and the apex height.
    ConeClass classify(const LocalCone& cone) const;
    ConeClass classifyRanging(LocalCone& cone, double t0, double t1, const RigidBounds& back) const {
        return classifyAfterRange(*this, cone, t0, t1, back);
    }

    // Unbounded: not taken as a convex occluder, nor shown to be left by rays.
    bool convex() const { return false; }
    bool raysLeave(const LocalRays&) const { return false; }
    bool canShadowItself() const { return false; }  // flat
    // POV-Ray's: strictly below, n.x < distance.
    bool inside(const Vec3& p) const { return glm::dot(normal_, p) < distance_; }
    // Its own plane, both ways; unbounded across its normal (and the
    // support along it is never asked for exactly).
    HoldingPlanes holdingPlanes(const Vec3&) const {
        HoldingPlanes h;
        h.add(normal_, distance_);
        h.add(-normal_, -distance_);
        h.flat = true;
        return h;
    }
    double support(const Vec3&) const { return kInfinity; }
    template <class User>
    decltype(auto) withAnyTestFrom(const Vec3& origin, User&& user) const {
        return user(exactAnyTestFrom(*this, origin));
    }

private:
    Vec3 normal_;
    double distance_;
};

// POV-Ray's plane record: a finite normal that is not zero, a finite
// distance.
std::vector<ShapeIssue> validate(const PlaneShape& record);
// Its Plane, in the object frame, the normal made unit.
Placed<Plane> place(const PlaneShape& record, const Transform& worldFromObject);

}  // namespace asos
