#pragma once
// POV-Ray's sphere, in a local frame centred on it.
#include <optional>

#include "asos/geometry/bounds.hpp"
#include "asos/geometry/cone.hpp"
#include "asos/geometry/ray.hpp"
#include "asos/shapes/local_cone.hpp"
#include "asos/shapes/local_hit.hpp"

namespace asos {

class Sphere {
public:
    static constexpr const char* kName = "sphere";

    explicit Sphere(double radius) : radius_(radius) {}  // radius >= 0; 0 is empty

    double radius() const { return radius_; }
    BoundingSphere boundingSphere() const { return {Vec3(0.0), radius_}; }
    Bounds3 worldBounds(const Mat3& worldFromLocal, const Vec3& offset) const;

    std::optional<LocalHit> intersect(const Ray& ray, double tMin, double tMax) const;
    bool intersectAny(const Ray& ray, double tMin, double tMax) const;
    // Full iff the cone lies inside the sphere's tangent cone (seen from
    // outside) and every front hit is in range; see docs/geometry.md.
    ConeClass classify(const LocalCone& cone) const;

private:
    double radius_;
};

}  // namespace asos
