#pragma once
// POV-Ray's cylinder { base, cap, radius [open] }. The local frame runs the
// axis along +z from the base at the origin to the cap at z = length. It
// also stands in for a cone whose radii are equal (truncated_cone.hpp).
#include <optional>
#include <vector>

#include "asos/geometry/bounds.hpp"
#include "asos/geometry/cone.hpp"
#include "asos/geometry/ray.hpp"
#include "asos/geometry/transform.hpp"
#include "asos/scene/description.hpp"
#include "asos/shapes/frustum.hpp"
#include "asos/shapes/frustum_from_origin.hpp"
#include "asos/shapes/local_cone.hpp"
#include "asos/shapes/local_hit.hpp"
#include "asos/shapes/local_rays.hpp"
#include "asos/shapes/placed.hpp"
#include "asos/shapes/shape_issue.hpp"

namespace asos {

class Cylinder {
public:
    static constexpr const char* kName = "cylinder";

    Cylinder(double radius, double length, bool open)
        : radius_(radius), length_(length), open_(open), frustum_(radius, radius, length, !open) {}

    BoundingSphere boundingSphere() const { return frustum_.boundingSphere(); }
    Bounds3 worldBounds(const Mat3& m, const Vec3& offset) const {
        return frustum_.worldBounds(m, offset);
    }
    std::optional<LocalHit> intersect(const Ray& ray, double tMin, double tMax) const;
    bool intersectAny(const Ray& ray, double tMin, double tMax) const {
        return intersect(ray, tMin, tMax).has_value();
    }
    ConeClass classify(const LocalCone& cone) const { return frustum_.classify(cone); }
    ConeClass classifyRanging(LocalCone& cone, double t0, double t1, const RigidBounds& back) const {
        return classifyAfterRange(*this, cone, t0, t1, back);
    }
    // The same solid (capped unless open).
    const Frustum& frustum() const { return frustum_; }
    // Capped, a convex solid; open, a tube that can shadow its inside.
    bool convex() const { return frustum_.capped(); }
    bool canShadowItself() const { return open_; }
    bool raysLeave(const LocalRays& rays) const { return frustum_.raysLeave(rays); }
    bool inside(const Vec3& p) const { return frustum_.inside(p); }
    HoldingPlanes holdingPlanes(const Vec3& point) const { return frustum_.holdingPlanes(point); }
    double support(const Vec3& dir) const { return frustum_.support(dir); }
    template <class User>
    decltype(auto) withAnyTestFrom(const Vec3& origin, User&& user) const {
        return frustumAnyTestFrom(frustum_, *this, origin, user);
    }

private:
    double radius_, length_;
    bool open_;
    Frustum frustum_;
};

// POV-Ray's cylinder record: finite base and cap points apart, a positive
// radius.
std::vector<ShapeIssue> validate(const CylinderShape& record);
// Its Cylinder, on the axis from base to cap (frustumAxis).
Placed<Cylinder> place(const CylinderShape& record, const Transform& worldFromObject);

}  // namespace asos
