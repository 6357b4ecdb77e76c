#pragma once
// A closed outline swept along y (ExtrusionShape: POV-Ray's prism with
// linear_sweep, and each glyph of its text): the points (x, y, z) with
// y0 <= y <= y1 whose (x, z) lies inside the outline by the even-odd rule.
// Its surface is the caps (y = y0, y1) over that region and the sides swept
// by the contours' Bezier pieces. A ray meets a side where the piece crosses
// the ray's line in the plane (a polynomial of the piece's degree in its
// parameter, solved on monotone stretches); see docs/geometry.md,
// "Extrusion".
#include <memory>
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

class Extrusion {
public:
    // One piece, ready for the ray tests: power-basis coefficients of x(s)
    // and z(s) (s in [0, 1]), its control points' box, and the sign that
    // turns the tangent's right-hand normal (dz, -dx) outward.
    struct Piece {
        int degree = 1;
        double ax[4]{}, az[4]{};
        double px[4]{}, pz[4]{};  // control points
        double lo[2]{}, hi[2]{};  // x, z box of the control points
        double outward = 1.0;
    };

    // Contours as ExtrusionShape's (closed, not crossing each other), y0 < y1.
    // `open`: without its caps (POV-Ray's open prism); its inside is the
    // closed one's.
    Extrusion(const std::vector<OutlineContour>& contours, double y0, double y1, bool open = false);

    BoundingSphere boundingSphere() const { return {center_, radius_}; }
    Bounds3 worldBounds(const Mat3& worldFromLocal, const Vec3& offset) const;
    Vec3 lo() const { return lo_; }
    Vec3 hi() const { return hi_; }

    std::optional<LocalHit> intersect(const Ray& ray, double tMin, double tMax) const;
    bool intersectAny(const Ray& ray, double tMin, double tMax) const {
        return intersect(ray, tMin, tMax).has_value();
    }
    // Miss by the bounding ball (angle and range); Marginal otherwise,
    // between the ball's depths (never Full: conservative).
    ConeClass classify(const LocalCone& cone) const;
    ConeClass classifyRanging(LocalCone& cone, double t0, double t1, const RigidBounds& back) const {
        return classifyAfterRange(*this, cone, t0, t1, back);
    }
    // Inside the slab and the outline (even-odd), the surface included to
    // rounding.
    bool inside(const Vec3& p) const;
    // Whether (x, z) lies inside the outline by the even-odd rule.
    bool insideOutline(double x, double z) const;
    bool convex() const { return false; }
    bool canShadowItself() const { return true; }
    HoldingPlanes holdingPlanes(const Vec3&) const { return {}; }
    double support(const Vec3& dir) const;
    // The rays start outside the bounding ball and move away from its centre.
    bool raysLeave(const LocalRays& rays) const;
    template <class User>
    decltype(auto) withAnyTestFrom(const Vec3& origin, User&& user) const {
        return user(exactAnyTestFrom(*this, origin));
    }

private:
    std::vector<Piece> pieces_;
    double y0_, y1_;
    bool open_ = false;
    Vec3 lo_{0.0}, hi_{0.0}, center_{0.0};
    double radius_ = 0.0;
};

// At least one contour, each closed (every piece starting where the one
// before it ends) with finite points, y0 < y1 finite.
std::vector<ShapeIssue> validate(const ExtrusionShape& record);
Placed<Extrusion> place(const ExtrusionShape& record, const Transform& worldFromObject);

}  // namespace asos
