#pragma once
// POV-Ray's box { corner1, corner2 } (corners in any order), axis-aligned in
// its local frame, which is the object frame.
#include <cmath>
#include <optional>

#include "asos/geometry/bounds.hpp"
#include "asos/geometry/cone.hpp"
#include "asos/geometry/ray.hpp"
#include "asos/shapes/local_cone.hpp"
#include "asos/shapes/local_hit.hpp"

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

private:
    template <class SetRange, class Finish>
    ConeClass classifyWith(const LocalCone& cone, SetRange&& setRange, Finish&& finish) const;
    ConeClass classifyOutside(const LocalCone& cone) const;
    ConeClass classifyInside(const LocalCone& cone) const;
    ConeClass classifyOnSurface(const LocalCone& cone, double tol) const;

    Vec3 lo_, hi_;
    // |lo| + |hi| summed over the axes: the box's part of classify's
    // positional tolerance, once per box instead of a chain of six
    // dependent additions per cone.
    double cornerAbsSum_;
};

}  // namespace asos
