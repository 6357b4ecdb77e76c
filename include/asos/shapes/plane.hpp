#pragma once
// POV-Ray's plane { normal, distance }: the points x with n.x = distance for
// the unit n along the given normal. The local frame is the object frame.
#include <optional>

#include "asos/geometry/bounds.hpp"
#include "asos/geometry/cone.hpp"
#include "asos/geometry/ray.hpp"
#include "asos/shapes/local_cone.hpp"
#include "asos/shapes/local_hit.hpp"

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

private:
    Vec3 normal_;
    double distance_;
};

}  // namespace asos
