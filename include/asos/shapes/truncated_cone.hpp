#pragma once
// POV-Ray's cone { base, base radius, cap, cap radius [open] }: a truncated
// cone (or a pointed one when a radius is 0), capped unless open. The local
// frame runs the axis along +z from the base at the origin to the cap at
// z = length. Equal radii make a Cylinder instead (as in POV-Ray).
#include <optional>

#include "asos/geometry/bounds.hpp"
#include "asos/geometry/cone.hpp"
#include "asos/geometry/ray.hpp"
#include "asos/shapes/frustum.hpp"
#include "asos/shapes/local_cone.hpp"
#include "asos/shapes/local_hit.hpp"

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
    const Frustum& frustum() const { return frustum_; }

private:
    Frustum frustum_;
};

}  // namespace asos
