#pragma once
// POV-Ray's sphere, in a local frame centred on it.
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "asos/geometry/bounds.hpp"
#include "asos/geometry/cone.hpp"
#include "asos/geometry/margins.hpp"
#include "asos/geometry/ray.hpp"
#include "asos/geometry/transform.hpp"
#include "asos/scene/description.hpp"
#include "asos/shapes/cone_geometry.hpp"
#include "asos/shapes/holding_planes.hpp"
#include "asos/shapes/local_cone.hpp"
#include "asos/shapes/local_frame.hpp"
#include "asos/shapes/local_hit.hpp"
#include "asos/shapes/local_rays.hpp"
#include "asos/shapes/placed.hpp"
#include "asos/shapes/shape_issue.hpp"

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
    ConeClass classify(const LocalCone& cone) const;  // inline, below
    ConeClass classifyRanging(LocalCone& cone, double t0, double t1, const RigidBounds& back) const {
        return classifyAfterRange(*this, cone, t0, t1, back);
    }
    // Under a non-uniform scale or shear (an ellipsoid in the world), the
    // commonest answers without carrying the cone into the local frame: Miss
    // or Full for a world cone whose apex is outside, from bounds on u.d and
    // |A d| over the cone (A = localFromWorld); nullopt where those bounds
    // cannot decide, for the bounding-cone path. See docs/geometry.md.
    std::optional<ConeClass> classifyAcrossScale(const PreparedCone& cone,
                                                 const LocalFrame& frame) const;

    // POV-Ray's: strictly within the radius.
    bool inside(const Vec3& p) const { return glm::dot(p, p) < radius_ * radius_; }
    bool convex() const { return true; }
    bool canShadowItself() const { return false; }
    // No plane holds it flat; curved, it touches a plane at one point.
    HoldingPlanes holdingPlanes(const Vec3&) const {
        HoldingPlanes h;
        h.thinContact = true;
        return h;
    }
    double support(const Vec3& dir) const { return radius_ * glm::length(dir); }
    // The plane across the ball facing the origin: n . x = r with
    // n = origin / |origin| holds the ball.
    bool raysLeave(const LocalRays& rays) const {
        return glm::dot(rays.origin, rays.origin) >= radius_ * radius_ && rays.awayFrom(rays.origin);
    }
    template <class User>
    decltype(auto) withAnyTestFrom(const Vec3& origin, User&& user) const {
        return user(exactAnyTestFrom(*this, origin));
    }

private:
    // classify's apex on or inside the sphere (to rounding), out of line;
    // the arguments are classify's own.
    ConeClass classifyApexNear(const LocalCone& cone, double d2, double p2, double sigma, double band) const;

    double radius_;
};

// Inline: a rigid frame's classification (Primitive) then keeps the local
// cone in registers. Full iff the cone lies inside the sphere's tangent cone
// (seen from outside) and every front hit is in range; see docs/geometry.md.
inline ConeClass Sphere::classify(const LocalCone& cone) const {
    if (!(radius_ > 0.0)) return conegeom::missClass();
    const double r = radius_, r2 = r * r;
    const Vec3 w = -cone.apex;  // centre - apex
    const double d2 = glm::dot(w, w);
    const double c = cone.cosHalf, s = cone.sinHalf;
    // How far d2 - r2 may be from its sign: the apex is "on" the sphere within
    // (their rounding is at most roundingGamma(4) (d2 + r2), a ninth of this).
    const double band = 4.0 * kFewUlps * (d2 + r2) + 2.0 * r * cone.absTol;
    const double sigma = glm::dot(w, cone.axis);
    const Vec3 perp = w - sigma * cone.axis;
    const double p2 = glm::dot(perp, perp);

    if (d2 - r2 > band) {
        // Apex outside. The Full test comes first, so that the commonest
        // answer skips the miss tests: a ball that covers the cone cannot lie
        // outside it, and the Full test is conservative on its own.
        const double t2 = d2 - r2;
        // Full: angle(axis, w) + theta <= alpha (the tangent half-angle), i.e.
        // sin(alpha - beta) = (r sigma - T |perp|) / d2 >= sin(theta), squared.
        const double lead = r * sigma - s * d2;
        if (c > 0.0 && lead >= 0.0 && lead * lead >= t2 * p2) {
            // Front hits t(x) = T^2 / (x + sqrt(x^2 - T^2)) decrease in
            // x = w.d, which ranges over [D cos(beta + theta), D cos(beta - theta)].
            const double dp = std::sqrt(p2);
            const double xLo = sigma * c - dp * s;
            const double xHi = s * sigma >= c * dp ? std::sqrt(d2) : sigma * c + dp * s;
            auto front = [&](double x) { return t2 / (x + std::sqrt(std::max(0.0, x * x - t2))); };
            const double tNear = front(xHi), tFar = front(xLo);
            if (cone.surelyWithin(tNear, tFar)) return conegeom::fullClass(tNear, tFar);
        }
        // Angular miss: the ball lies outside the cone.
        if (c >= 0.0) {
            if (sigma < 0.0 && sigma * sigma * c * c > p2 * s * s) return conegeom::missClass();
            const double rhs = sigma * s + r;
            if (rhs < 0.0 || p2 * c * c > rhs * rhs) return conegeom::missClass();
        } else {
            const double dp = std::sqrt(p2);
            if (s * sigma < c * dp && (sigma * c + dp * s < 0.0 || dp * c - sigma * s > r))
                return conegeom::missClass();
        }
        // The silhouette is inside the cone (or the range cuts the hits).
        // Every front hit lies in [D - r, T]; a ray whose front hit is before
        // the range may still hit the back, up to D + r.
        const double dist = std::sqrt(d2), tangent = std::sqrt(t2);
        const double nearest = t2 / (dist + r);  // dist - r
        if (cone.surelyAfter(nearest) || cone.surelyBefore(dist + r)) return conegeom::missClass();
        return conegeom::marginalClass(cone, nearest, nearest >= cone.tMinInner ? tangent : dist + r);
    }
    return classifyApexNear(cone, d2, p2, sigma, band);
}

// POV-Ray's sphere record: a finite centre, a positive radius.
std::vector<ShapeIssue> validate(const SphereShape& record);
// Its Sphere, about the centre.
Placed<Sphere> place(const SphereShape& record, const Transform& worldFromObject);

}  // namespace asos
