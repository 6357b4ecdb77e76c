#pragma once
// POV-Ray's cone { base, base radius, cap, cap radius [open] }: a truncated
// cone (or a pointed one when a radius is 0), capped unless open. The local
// frame runs the axis along +z from the base at the origin to the cap at
// z = length. Equal radii make a Cylinder instead (as in POV-Ray): the
// cone's record is placed here as either (place, below), so the cone's room
// is this file and truncated_cone.cpp, with the Cylinder standing in.
#include <optional>
#include <variant>
#include <vector>

#include "asos/geometry/bounds.hpp"
#include "asos/geometry/cone.hpp"
#include "asos/geometry/ray.hpp"
#include "asos/geometry/transform.hpp"
#include "asos/scene/description.hpp"
#include "asos/shapes/cylinder.hpp"
#include "asos/shapes/frustum.hpp"
#include "asos/shapes/frustum_from_origin.hpp"
#include "asos/shapes/local_cone.hpp"
#include "asos/shapes/local_hit.hpp"
#include "asos/shapes/local_rays.hpp"
#include "asos/shapes/placed.hpp"
#include "asos/shapes/shape_issue.hpp"

namespace asos {

class TruncatedCone {
public:
    static constexpr const char* kName = "cone";

    TruncatedCone(double baseRadius, double capRadius, double length, bool open)
        : frustum_(baseRadius, capRadius, length, !open) {}

    BoundingSphere boundingSphere() const { return frustum_.boundingSphere(); }
    Bounds3 worldBounds(const Mat3& m, const Vec3& offset) const {
        return frustum_.worldBounds(m, offset);
    }
    std::optional<LocalHit> intersect(const Ray& ray, double tMin, double tMax) const {
        return frustum_.intersect(ray, tMin, tMax);
    }
    bool intersectAny(const Ray& ray, double tMin, double tMax) const {
        return frustum_.intersectAny(ray, tMin, tMax);
    }
    ConeClass classify(const LocalCone& cone) const { return frustum_.classify(cone); }
    ConeClass classifyRanging(LocalCone& cone, double t0, double t1, const RigidBounds& back) const {
        return classifyAfterRange(*this, cone, t0, t1, back);
    }
    const Frustum& frustum() const { return frustum_; }
    // Capped, a convex solid; open, a surface that can shadow its inside.
    bool convex() const { return frustum_.capped(); }
    bool canShadowItself() const { return !frustum_.capped(); }
    bool raysLeave(const LocalRays& rays) const { return frustum_.raysLeave(rays); }
    bool inside(const Vec3& p) const { return frustum_.inside(p); }
    HoldingPlanes holdingPlanes(const Vec3& point) const { return frustum_.holdingPlanes(point); }
    double support(const Vec3& dir) const { return frustum_.support(dir); }
    template <class User>
    decltype(auto) withAnyTestFrom(const Vec3& origin, User&& user) const {
        return frustumAnyTestFrom(frustum_, *this, origin, user);
    }

private:
    Frustum frustum_;
};

// POV-Ray's cone record: finite base and cap points apart, finite radii not
// below 0, not both 0.
std::vector<ShapeIssue> validate(const ConeShape& record);
// Its TruncatedCone on the axis from base to cap (frustumAxis), or a
// Cylinder where the radii are equal; either is named "cone".
std::variant<Placed<TruncatedCone>, Placed<Cylinder>> place(const ConeShape& record,
                                                            const Transform& worldFromObject);

}  // namespace asos
