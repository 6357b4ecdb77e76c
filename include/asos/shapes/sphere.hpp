#pragma once
// POV-Ray's sphere, in a local frame centred on it.
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "asos/geometry/bounds.hpp"
#include "asos/geometry/cone.hpp"
#include "asos/geometry/ray.hpp"
#include "asos/shapes/local_cone.hpp"
#include "asos/shapes/local_frame.hpp"
#include "asos/shapes/local_hit.hpp"

namespace asos {

namespace sphere_detail {
// The roots of |o + t d|^2 = r^2, computed without cancellation: the
// discriminant from the closest-approach vector (Haines et al., "Precision
// improvements for ray/sphere intersection", Ray Tracing Gems, 2019).
struct Roots {
    bool real;
    double near, far;
};

inline Roots sphereRoots(const Ray& ray, double r) {
    const Vec3& o = ray.origin;
    const Vec3& d = ray.dir;
    const double a = glm::dot(d, d);
    const double b = glm::dot(o, d);
    const Vec3 f = o - (b / a) * d;
    const double disc = a * (r * r - glm::dot(f, f));
    if (disc < 0.0) return {false, 0.0, 0.0};
    const double c = glm::dot(o, o) - r * r;
    const double q = -(b + std::copysign(std::sqrt(disc), b));
    if (q == 0.0) return {true, 0.0, 0.0};
    double t0 = q / a, t1 = c / q;
    if (t0 > t1) std::swap(t0, t1);
    return {true, t0, t1};
}
}  // namespace sphere_detail

class Sphere {
public:
    static constexpr const char* kName = "sphere";

    explicit Sphere(double radius) : radius_(radius) {}  // radius >= 0; 0 is empty

    double radius() const { return radius_; }
    BoundingSphere boundingSphere() const { return {Vec3(0.0), radius_}; }
    Bounds3 worldBounds(const Mat3& worldFromLocal, const Vec3& offset) const;

    // Inline: the scene's ray search calls them directly for spheres that
    // are only translated (Scene's leaf records), without a Primitive.
    std::optional<LocalHit> intersect(const Ray& ray, double tMin, double tMax) const {
        return intersect(ray, radius_, tMin, tMax);
    }
    bool intersectAny(const Ray& ray, double tMin, double tMax) const {
        return intersectAny(ray, radius_, tMin, tMax);
    }
    static std::optional<LocalHit> intersect(const Ray& ray, double radius, double tMin,
                                             double tMax) {
        const double t = nearestRoot(ray, radius, tMin, tMax);
        if (std::isnan(t)) return std::nullopt;
        const Vec3 p = ray.at(t);
        return LocalHit{t, p, p};
    }
    // The t of intersect's hit, or NaN when there is none: a nearest-hit
    // search keeps only t and makes the hit (ray.at(t)) for the winner.
    static double nearestRoot(const Ray& ray, double radius, double tMin, double tMax) {
        constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
        if (!(radius > 0.0)) return kNone;
        const sphere_detail::Roots roots = sphere_detail::sphereRoots(ray, radius);
        if (!roots.real) return kNone;
        if (roots.near >= tMin && roots.near <= tMax) return roots.near;
        if (roots.far >= tMin && roots.far <= tMax) return roots.far;
        return kNone;
    }
    static bool intersectAny(const Ray& ray, double radius, double tMin, double tMax) {
        if (!(radius > 0.0)) return false;
        const sphere_detail::Roots roots = sphere_detail::sphereRoots(ray, radius);
        return roots.real && ((roots.near >= tMin && roots.near <= tMax) ||
                              (roots.far >= tMin && roots.far <= tMax));
    }
    // Full iff the cone lies inside the sphere's tangent cone (seen from
    // outside) and every front hit is in range; see docs/geometry.md.
    ConeClass classify(const LocalCone& cone) const;
    // Under a non-uniform scale or shear (an ellipsoid in the world), the
    // commonest answers without carrying the cone into the local frame: Miss
    // or Full for a world cone whose apex is outside, from bounds on u.d and
    // |A d| over the cone (A = localFromWorld); nullopt where those bounds
    // cannot decide, for the bounding-cone path. See docs/geometry.md.
    std::optional<ConeClass> classifyAcrossScale(const PreparedCone& cone,
                                                 const LocalFrame& frame) const;

private:
    double radius_;
};

}  // namespace asos
