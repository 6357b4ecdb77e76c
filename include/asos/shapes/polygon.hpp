#pragma once
// POV-Ray's polygon: a list of points forming one or more sub-polygons, each
// closed by repeating its first point (the last is closed if it is not), all
// in one plane; a point is inside under the even-odd rule over every edge.
// The local frame puts the plane at z = 0 with the first point at the origin
// and POV-Ray's normal (from the first two independent edges) along +z.
#include <cstdint>
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

class Polygon {
public:
    static constexpr const char* kName = "polygon";

    // Vertices of each closed loop (without the repeated closing point) in
    // the local plane; no loops makes an empty polygon (collinear points).
    Polygon(std::vector<Vec2> vertices, std::vector<std::uint32_t> loopEnds);

    bool empty() const { return loopEnds_.empty(); }
    // One loop, convex (Primitive::convex): its turns all go one way and add
    // up to one full turn (repeated and collinear points aside).
    bool convex() const { return convex_; }
    bool canShadowItself() const { return false; }  // flat
    // None: POV-Ray's polygon is a non-solid object (and `inverse` leaves
    // it so).
    bool inside(const Vec3&) const { return false; }
    bool raysLeave(const LocalRays& rays) const { return rays.leaveZPlane(); }
    HoldingPlanes holdingPlanes(const Vec3&) const { return zPlaneHolding(); }
    // The farthest vertex.
    double support(const Vec3& dir) const;
    template <class User>
    decltype(auto) withAnyTestFrom(const Vec3& origin, User&& user) const {
        return user(exactAnyTestFrom(*this, origin));
    }
    const std::vector<Vec2>& vertices() const { return vertices_; }
    const std::vector<std::uint32_t>& loopEnds() const { return loopEnds_; }
    BoundingSphere boundingSphere() const { return {Vec3(center_, 0.0), radius_}; }
    Bounds3 worldBounds(const Mat3& worldFromLocal, const Vec3& offset) const;

    // The even-odd rule at a point of the plane.
    bool contains(double x, double y) const;
    std::optional<LocalHit> intersect(const Ray& ray, double tMin, double tMax) const;
    // intersect(ray, tMin, tMax).has_value(), inline and without the hit
    // record (the inner loop of an area light's point samples).
    bool intersectAny(const Ray& ray, double tMin, double tMax) const {
        if (empty()) return false;
        const auto hit = crossZPlane(ray, tMin, tMax);
        if (!hit) return false;
        const double x = hit->x, y = hit->y;
        return !(x < lo_.x || x > hi_.x || y < lo_.y || y > hi_.y) && contains(x, y);
    }
    // The edges are the boundary: Marginal iff one meets the cone; else the
    // cone's footprint is wholly inside or outside, as its axis point.
    ConeClass classify(const LocalCone& cone) const;
    // The same, for a rigid frame's cone whose range is not set yet (apex,
    // axis, angle and absTol are): the edge pass's answers (off the box or
    // no edge near) hold their depths against the world range through
    // `back` (RigidBounds); the range [t0, t1] is set only past them (as
    // Disc::classifyRanging).
    ConeClass classifyRanging(LocalCone& cone, double t0, double t1, const RigidBounds& back) const;

private:
    template <class SetRange, class Finish>
    ConeClass classifyWith(const LocalCone& cone, SetRange&& setRange, Finish&& finish) const;
    // Every edge against the cone (the fast path's fallback near an edge).
    ConeClass classifyExactly(const LocalCone& cone) const;

    // Every edge of every loop, from v0 to v0 + e, for the cone's pass.
    struct Edge {
        Vec2 v0;
        Vec2 e;
        double v1y;  // (v0 + e).y as given
        double ee;   // |e|^2
    };

    // The same edges two at a time, lane by lane (GCC/Clang vector
    // extensions: each lane's arithmetic is the scalar one), padded to a
    // whole pair with an edge that neither crosses q's line (both ends at
    // y = 0) nor is near (|e|^2 = -inf), for the cone's edge pass.
    using Double2 = double __attribute__((vector_size(16)));
    struct EdgePair {
        Double2 v0x, v0y, ex, ey, v1y, ee;
    };

    std::vector<Vec2> vertices_;
    std::vector<std::uint32_t> loopEnds_;  // exclusive end of each loop in vertices_
    std::vector<Edge> edges_;
    std::vector<EdgePair> edgePairs_;
    Vec2 lo_{0.0}, hi_{0.0};               // 2D bounding box
    Vec2 center_{0.0};
    double radius_ = 0.0;
    bool convex_ = false;
};

// POV-Ray's polygon record: at least three finite points, not all on one
// line, all in one plane.
std::vector<ShapeIssue> validate(const PolygonShape& record);
// Its Polygon, in the plane of the points, its loops closed as POV-Ray
// closes them; under a frame that is not a similarity, the image polygon
// laid out in a rigid frame.
Placed<Polygon> place(const PolygonShape& record, const Transform& worldFromObject);

}  // namespace asos
