#pragma once
// POV-Ray's torus { R, r }: the points at distance r from the circle of
// radius R about the y axis in the plane y = 0, in a local frame that is the
// object's own. A ray meets it up to four times (the roots of a quartic);
// see docs/geometry.md, "Torus".
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

// The roots of the torus' quartic along a ray within the swept sphere, in
// increasing order: they depend on the ray only, never on a range.
struct TorusRoots {
    double t[4];
    int count = 0;
};

class Torus {
public:
    static constexpr const char* kName = "torus";

    Torus(double major, double minor) : major_(major), minor_(minor) {}  // major >= minor > 0

    double major() const { return major_; }
    double minor() const { return minor_; }
    BoundingSphere boundingSphere() const { return {Vec3(0.0), major_ + minor_}; }
    Bounds3 worldBounds(const Mat3& worldFromLocal, const Vec3& offset) const;

    // Every crossing of the ray's line with the surface (t of the ray, whose
    // direction need not be unit).
    TorusRoots roots(const Ray& ray) const;
    std::optional<LocalHit> intersect(const Ray& ray, double tMin, double tMax) const;
    bool intersectAny(const Ray& ray, double tMin, double tMax) const {
        return intersect(ray, tMin, tMax).has_value();
    }
    // Miss by the swept sphere (radius R + r) or the slab |y| <= r; Full
    // where the cone lies in the tangent cone of a ball of radius r about a
    // point of the core circle (a ball inside the solid) seen from outside
    // the solid; Marginal otherwise, between the swept sphere's depths.
    ConeClass classify(const LocalCone& cone) const;
    ConeClass classifyRanging(LocalCone& cone, double t0, double t1, const RigidBounds& back) const {
        return classifyAfterRange(*this, cone, t0, t1, back);
    }

    // POV-Ray's: within r of the core circle, the surface included.
    bool inside(const Vec3& p) const;
    bool convex() const { return false; }
    bool canShadowItself() const { return true; }
    // The slab |y| <= r, which the surface touches along circles only.
    HoldingPlanes holdingPlanes(const Vec3&) const {
        HoldingPlanes h;
        h.add(Vec3(0.0, 1.0, 0.0), minor_);
        h.add(Vec3(0.0, -1.0, 0.0), minor_);
        h.thinContact = true;
        return h;
    }
    double support(const Vec3& dir) const;
    // The plane across the swept sphere facing the origin (as Sphere's).
    bool raysLeave(const LocalRays& rays) const;
    template <class User>
    decltype(auto) withAnyTestFrom(const Vec3& origin, User&& user) const {
        return user(exactAnyTestFrom(*this, origin));
    }

private:
    double major_, minor_;
};

// POV-Ray's torus record: finite radii, 0 < r <= R (POV-Ray's spindle torus,
// r > R, is refused).
std::vector<ShapeIssue> validate(const TorusShape& record);
// Its Torus, in the object frame.
Placed<Torus> place(const TorusShape& record, const Transform& worldFromObject);

}  // namespace asos
