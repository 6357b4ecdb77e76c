#pragma once
// POV-Ray's quadric { <A, B, C>, <D, E, F>, <G, H, I>, J }: the surface
// f(x) = x.Q x + g.x + J = 0 with the symmetric Q = [[A, D/2, E/2],
// [D/2, B, F/2], [E/2, F/2, C]] and g = <G, H, I>, its inside where f < 0
// (POV-Ray's quadric.cpp). The local frame is the object frame.
//
// In general unbounded; an ellipsoid (Q definite) is bounded by the box of
// its extents, which puts it in the BVH like any bounded shape. An unbounded
// one is kept, like a plane, beside the BVH.
#include <optional>
#include <vector>

#include "asos/geometry/bounds.hpp"
#include "asos/geometry/cone.hpp"
#include "asos/geometry/ray.hpp"
#include "asos/geometry/transform.hpp"
#include "asos/scene/description.hpp"
#include "asos/shapes/holding_planes.hpp"
#include "asos/shapes/local_cone.hpp"
#include "asos/shapes/local_hit.hpp"
#include "asos/shapes/local_rays.hpp"
#include "asos/shapes/placed.hpp"
#include "asos/shapes/shape_issue.hpp"

namespace asos {

class Quadric {
public:
    static constexpr const char* kName = "quadric";

    Quadric(const Mat3& q, const Vec3& g, double j);

    // f and its gradient 2 Q x + g.
    double value(const Vec3& p) const { return glm::dot(p, q_ * p) + glm::dot(g_, p) + j_; }
    Vec3 gradient(const Vec3& p) const { return 2.0 * (q_ * p) + g_; }

    BoundingSphere boundingSphere() const { return sphere_; }
    Bounds3 worldBounds(const Mat3& worldFromLocal, const Vec3& offset) const;

    // The nearer root of f along the ray in [tMin, tMax] (a robust quadratic:
    // the root of larger size from the formula, the other from their
    // product, so that neither loses its digits; a linear equation where the
    // ray's direction has d.Q d = 0). The normal is the gradient, or +y where
    // it vanishes (as POV-Ray's Quadric_Normal).
    std::optional<LocalHit> intersect(const Ray& ray, double tMin, double tMax) const;
    bool intersectAny(const Ray& ray, double tMin, double tMax) const {
        return intersect(ray, tMin, tMax).has_value();
    }
    // Conservative, from bounds of f over balls that hold the cone's pieces
    // (docs/geometry.md, "Quadric"): Miss where f keeps one sign over every
    // piece (and, for an unbounded range, beyond the last), Full where it
    // changes sign between two pieces and its gradient cannot vanish between
    // them, Marginal otherwise, with the depths the signs allow.
    ConeClass classify(const LocalCone& cone) const;
    ConeClass classifyRanging(LocalCone& cone, double t0, double t1, const RigidBounds& back) const {
        return classifyAfterRange(*this, cone, t0, t1, back);
    }

    // Not taken as a convex occluder, nor shown to be left by rays.
    bool convex() const { return false; }
    bool raysLeave(const LocalRays&) const { return false; }
    bool canShadowItself() const { return true; }  // curved, and in general not convex
    // POV-Ray's inside: where f is negative (a CSG member; `inverse` flips it).
    bool inside(const Vec3& p) const { return value(p) < 0.0; }
    // No plane known to hold it.
    HoldingPlanes holdingPlanes(const Vec3&) const { return {}; }
    double support(const Vec3&) const { return kInfinity; }
    template <class User>
    decltype(auto) withAnyTestFrom(const Vec3& origin, User&& user) const {
        return user(exactAnyTestFrom(*this, origin));
    }

private:
    // A bound on the rounding of f computed at points within `reach` of the origin.
    double valueSlack(double reach) const;
    // +1 or -1 where f has that sign over the whole ball, else 0.
    int signOver(const Vec3& centre, double radius) const;
    // Whether the gradient cannot vanish in the ball.
    bool regularOver(const Vec3& centre, double radius) const;

    Mat3 q_;
    Vec3 g_;
    double j_;
    double qNorm_;  // Frobenius norm of Q, >= its spectral norm
    double gNorm_;
    BoundingSphere sphere_;
    Bounds3 box_;  // an ellipsoid's extents (empty for an unbounded quadric)
};

// POV-Ray's quadric record: finite coefficients, some term in x, y or z.
std::vector<ShapeIssue> validate(const QuadricShape& record);
// Its Quadric, in the object frame.
Placed<Quadric> place(const QuadricShape& record, const Transform& worldFromObject);

}  // namespace asos
