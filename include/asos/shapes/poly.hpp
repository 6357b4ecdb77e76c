#pragma once
// POV-Ray's poly { N, <coefficients> } (and quartic, cubic): the surface
// f(x, y, z) = 0 of a polynomial of order N (2 to 35) in the object frame,
// its inside where f < 1e-4 (POV-Ray's Inside_Poly), its normal the gradient.
// A line meets it up to N times; the roots are isolated by the derivatives'
// roots and refined on f itself (docs/geometry.md, "Poly").
//
// Unbounded unless the polynomial proves otherwise: where the top-degree part
// keeps one strict sign over every direction, f keeps that sign beyond a radius
// R, and the surface lies in the ball of radius R about the origin.
#include <array>
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

// Every crossing of a line with a poly's surface, ascending (t of the ray).
struct PolyRoots {
    std::array<double, PolyShape::kMaxOrder> t{};
    int count = 0;
};

class Poly {
public:
    static constexpr const char* kName = "poly";

    // One term c x^i y^j z^k.
    struct Term {
        double c;
        int i, j, k;
    };

    // order in [2, PolyShape::kMaxOrder], coefficients in POV-Ray's order.
    Poly(int order, const std::vector<double>& coefficients);

    int order() const { return order_; }
    double value(const Vec3& p) const;
    Vec3 gradient(const Vec3& p) const;
    // Whether the surface was shown to lie in the ball of radius R.
    bool bounded() const { return bounded_; }

    BoundingSphere boundingSphere() const { return {centre_, radius_}; }
    Bounds3 worldBounds(const Mat3& worldFromLocal, const Vec3& offset) const;

    // Every crossing of the ray's line (the roots of f along it, which do not
    // depend on a range); a root is lost only where the line grazes the surface
    // within rounding.
    PolyRoots roots(const Ray& ray) const;
    std::optional<LocalHit> intersect(const Ray& ray, double tMin, double tMax) const;
    bool intersectAny(const Ray& ray, double tMin, double tMax) const {
        return intersect(ray, tMin, tMax).has_value();
    }
    // Conservative, from interval bounds of f and of its slope along the rays
    // over balls holding the cone's depth pieces (docs/geometry.md, "Poly").
    ConeClass classify(const LocalCone& cone) const;
    ConeClass classifyRanging(LocalCone& cone, double t0, double t1, const RigidBounds& back) const {
        return classifyAfterRange(*this, cone, t0, t1, back);
    }

    bool convex() const { return false; }
    // The plane across the bounding ball facing the origin (as Torus's).
    bool raysLeave(const LocalRays& rays) const;
    bool canShadowItself() const { return true; }
    // POV-Ray's: f below its INSIDE_TOLERANCE, 1e-4.
    bool inside(const Vec3& p) const { return value(p) < kInsideTolerance; }
    HoldingPlanes holdingPlanes(const Vec3&) const { return {}; }
    double support(const Vec3& dir) const;
    template <class User>
    decltype(auto) withAnyTestFrom(const Vec3& origin, User&& user) const {
        return user(exactAnyTestFrom(*this, origin));
    }

    static constexpr double kInsideTolerance = 1e-4;

private:
    struct Interval {
        double lo, hi;
    };
    // The top-degree part over the box (its sign far away).
    Interval topOver(const Vec3& lo, const Vec3& hi) const;
    // f about a ball's centre: its value and gradient there, a bound on how
    // far f strays from that value over the ball (rounding included), and on
    // how far the gradient strays (per axis), with a rounding pad for it.
    struct Local {
        double value = 0.0, spread = 0.0;
        Vec3 grad{0.0}, stray{0.0};
        double slopePad = 0.0;
    };
    Local about(const Vec3& centre, double radius, std::vector<double>& room) const;
    // Shows the surface bounded (sets radius_, farSign_) where it can.
    void proveBounded();

    int order_;
    std::vector<Term> terms_;  // the non-zero ones
    std::vector<double> dense_;  // every coefficient, at ((i (N+1)) + j) (N+1) + k
    std::vector<double> degreeNorm_;  // the sum of |c| over the terms of each degree
    double coefficientNorm_ = 0.0;
    bool bounded_ = false;
    // Bounded: the surface lies in box_, and in the ball about centre_ of
    // radius radius_ (its half-diagonal).
    Bounds3 box_;
    Vec3 centre_{0.0};
    double radius_ = kInfinity;
    int farSign_ = 0;  // f's sign beyond the ball (bounded only)
};

// POV-Ray's poly record: order 2 to 35, as many finite coefficients as the
// order has terms, some term of degree at least one.
std::vector<ShapeIssue> validate(const PolyShape& record);
// Its Poly, in the object frame.
Placed<Poly> place(const PolyShape& record, const Transform& worldFromObject);

}  // namespace asos
