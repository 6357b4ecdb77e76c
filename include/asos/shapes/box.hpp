#pragma once
// POV-Ray's box { corner1, corner2 } (corners in any order), axis-aligned in
// its local frame, which is the object frame.
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "asos/geometry/bounds.hpp"
#include "asos/geometry/cone.hpp"
#include "asos/geometry/ray.hpp"
#include "asos/geometry/transform.hpp"
#include "asos/scene/description.hpp"
#include "asos/shapes/box_from_origin.hpp"
#include "asos/shapes/holding_planes.hpp"
#include "asos/shapes/local_cone.hpp"
#include "asos/shapes/local_hit.hpp"
#include "asos/shapes/local_rays.hpp"
#include "asos/shapes/placed.hpp"
#include "asos/shapes/shape_issue.hpp"

namespace asos {

class Box {
public:
    static constexpr const char* kName = "box";

    Box(const Vec3& corner1, const Vec3& corner2)
        : lo_(glm::min(corner1, corner2)),
          hi_(glm::max(corner1, corner2)),
          cornerAbsSum_(std::abs(lo_.x) + std::abs(lo_.y) + std::abs(lo_.z) + std::abs(hi_.x) +
                        std::abs(hi_.y) + std::abs(hi_.z)) {}

    const Vec3& lo() const { return lo_; }
    const Vec3& hi() const { return hi_; }
    BoundingSphere boundingSphere() const { return {0.5 * (lo_ + hi_), 0.5 * glm::length(hi_ - lo_)}; }
    Bounds3 worldBounds(const Mat3& worldFromLocal, const Vec3& offset) const;

    std::optional<LocalHit> intersect(const Ray& ray, double tMin, double tMax) const;
    bool intersectAny(const Ray& ray, double tMin, double tMax) const;
    // From outside: the silhouette edges (between a face turned to the apex
    // and one turned away) tested against the cone; see docs/geometry.md.
    ConeClass classify(const LocalCone& cone) const;
    // A rigid frame's answer in world units (Primitive::classifyRigid), for
    // a cone whose range is not set yet (apex, axis, angle and absTol are):
    // the fast path holds its depths against the world range through `back`
    // (RigidBounds); the range [t0, t1] is set only past it.
    ConeClass classifyRanging(LocalCone& cone, double t0, double t1, const RigidBounds& back) const;

    // POV-Ray's: the closed box, its faces included.
    bool inside(const Vec3& p) const {
        return p.x >= lo_.x && p.x <= hi_.x && p.y >= lo_.y && p.y <= hi_.y && p.z >= lo_.z && p.z <= hi_.z;
    }
    bool convex() const { return true; }
    bool canShadowItself() const { return false; }
    // Its six face planes (a flat box's plane first); a solid seen from
    // outside.
    HoldingPlanes holdingPlanes(const Vec3& point) const;
    double support(const Vec3& dir) const {
        return std::max(dir.x * lo_.x, dir.x * hi_.x) + std::max(dir.y * lo_.y, dir.y * hi_.y) +
               std::max(dir.z * lo_.z, dir.z * hi_.z);
    }
    // The plane of a face the origin is on or beyond.
    bool raysLeave(const LocalRays& rays) const;
    // BoxFromOrigin: the slabs' offsets from the origin found once.
    template <class User>
    decltype(auto) withAnyTestFrom(const Vec3& origin, User&& user) const {
        const BoxFromOrigin fast(lo_, hi_, origin);
        return user([&fast](const Vec3& dir, double tMin, double tMax) { return fast.intersectAny(dir, tMin, tMax); });
    }

private:
    template <class SetRange, class Finish>
    ConeClass classifyWith(const LocalCone& cone, SetRange&& setRange, Finish&& finish) const;
    ConeClass classifyOutside(const LocalCone& cone) const;
    ConeClass classifyInside(const LocalCone& cone) const;
    ConeClass classifyOnSurface(const LocalCone& cone, double tol) const;
    // A Full answer with the creases the cone may hold where the apex sees
    // every edge as one (inside the box).
    ConeClass withEveryCrease(const LocalCone& cone, ConeClass full) const;

    Vec3 lo_, hi_;
    // |lo| + |hi| summed over the axes: the box's part of classify's
    // positional tolerance, once per box instead of a chain of six
    // dependent additions per cone.
    double cornerAbsSum_;
};

// POV-Ray's box record: two finite corners.
std::vector<ShapeIssue> validate(const BoxShape& record);
// Its Box, in the object frame.
Placed<Box> place(const BoxShape& record, const Transform& worldFromObject);

}  // namespace asos
