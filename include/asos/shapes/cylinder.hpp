#pragma once
// POV-Ray's cylinder { base, cap, radius [open] }. The local frame runs the
// axis along +z from the base at the origin to the cap at z = length.
#include <optional>

#include "asos/geometry/bounds.hpp"
#include "asos/geometry/cone.hpp"
#include "asos/geometry/ray.hpp"
#include "asos/shapes/frustum.hpp"
#include "asos/shapes/local_cone.hpp"
#include "asos/shapes/local_hit.hpp"

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
    // The same solid (capped unless open): FrustumFromOrigin decides its rays.
    const Frustum& frustum() const { return frustum_; }

private:
    double radius_, length_;
    bool open_;
    Frustum frustum_;
};

}  // namespace asos
