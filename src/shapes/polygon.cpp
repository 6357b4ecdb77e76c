#include "asos/shapes/polygon.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "asos/diag/format_number.hpp"
#include "asos/geometry/frame.hpp"
#include "asos/geometry/margins.hpp"
#include "asos/shapes/cone_geometry.hpp"
#include "asos/scene/pov_tolerances.hpp"
#include "asos/shapes/local_frame.hpp"

namespace asos {

using namespace conegeom;

namespace {

// How far a point may lie off the plane of the first ones (relative to the
// polygon's size), or the point that fixes that plane off the line of the
// first two (relative to its distance), and still count as in it: a modelling
// choice, far above the rounding of the scene's numbers, far below any
// visible tilt.
constexpr double kFlatness = 1e-9;

// Whether the closed loop of vertices [begin, end) bounds a convex region:
// its turns (repeated points left out) all go one way, none turns back on
// itself, and they add up to one full turn (a star's add up to more).
bool convexLoop(const std::vector<Vec2>& vertices, std::uint32_t begin, std::uint32_t end) {
    std::vector<Vec2> edges;
    for (std::uint32_t i = begin; i < end; ++i) {
        const Vec2 e = vertices[i + 1 < end ? i + 1 : begin] - vertices[i];
        if (e.x != 0.0 || e.y != 0.0) edges.push_back(e);
    }
    if (edges.size() < 3) return false;
    double turning = 0.0;
    int way = 0;
    for (std::size_t k = 0; k < edges.size(); ++k) {
        const Vec2 a = edges[k], b = edges[(k + 1) % edges.size()];
        const double cross = a.x * b.y - a.y * b.x, dot = a.x * b.x + a.y * b.y;
        if (cross == 0.0 && dot < 0.0) return false;
        const int sign = (cross > 0.0) - (cross < 0.0);
        if (sign != 0) {
            if (way != 0 && sign != way) return false;
            way = sign;
        }
        turning += std::atan2(cross, dot);
    }
    // One full turn to rounding (the atan2s' few ulps each); a star's is two or more.
    return way != 0 && std::abs(std::abs(turning) - 2.0 * kPi) < 1e-6;
}

// The plane of a polygon's points as POV-Ray finds it: through the first
// point, its normal from u, the first point away from the first, and the
// first later point not in line with u; no normal when the points are all
// on one line.
struct PointsPlane {
    Vec3 origin;
    double extent = 0.0;  // the largest distance of a point from the origin
    std::optional<Vec3> normal;  // unit
};

PointsPlane pointsPlane(const std::vector<Vec3>& points) {
    PointsPlane out{points[0], 0.0, std::nullopt};
    for (const Vec3& p : points) out.extent = std::max(out.extent, glm::length(p - out.origin));
    std::size_t i = 1;
    Vec3 u(0.0);
    for (; i < points.size(); ++i) {
        u = points[i] - out.origin;
        if (glm::length(u) > kThousandsOfUlps * out.extent) break;  // not the origin to rounding
    }
    for (++i; i < points.size(); ++i) {
        const Vec3 v = points[i] - out.origin;
        const Vec3 w = glm::cross(u, v);
        if (glm::length(w) > kFlatness * glm::length(u) * glm::length(v)) {
            out.normal = glm::normalize(w);
            break;
        }
    }
    return out;
}

}  // namespace

Polygon::Polygon(std::vector<Vec2> vertices, std::vector<std::uint32_t> loopEnds)
    : vertices_(std::move(vertices)), loopEnds_(std::move(loopEnds)) {
    if (vertices_.empty()) return;
    lo_ = hi_ = vertices_[0];
    for (const Vec2& v : vertices_) {
        lo_ = glm::min(lo_, v);
        hi_ = glm::max(hi_, v);
    }
    center_ = 0.5 * (lo_ + hi_);
    for (const Vec2& v : vertices_) radius_ = std::max(radius_, glm::length(v - center_));
    std::uint32_t begin = 0;
    for (const std::uint32_t end : loopEnds_) {
        for (std::uint32_t i = begin, i0 = end - 1; i < end; i0 = i++) {
            const Vec2 v0 = vertices_[i0], v1 = vertices_[i];
            const Vec2 e = v1 - v0;
            edges_.push_back({v0, e, v1.y, glm::dot(e, e)});
        }
        begin = end;
    }
    convex_ = loopEnds_.size() == 1 && convexLoop(vertices_, 0, loopEnds_[0]);
    const double inf = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < edges_.size(); i += 2) {
        const Edge& a = edges_[i];
        const Edge b = i + 1 < edges_.size() ? edges_[i + 1] : Edge{Vec2(0.0), Vec2(0.0), 0.0, -inf};
        EdgePair pair;
        pair.v0x = Double2{a.v0.x, b.v0.x};
        pair.v0y = Double2{a.v0.y, b.v0.y};
        pair.ex = Double2{a.e.x, b.e.x};
        pair.ey = Double2{a.e.y, b.e.y};
        pair.v1y = Double2{a.v1y, b.v1y};
        pair.ee = Double2{a.ee, b.ee};
        edgePairs_.push_back(pair);
    }
}

Bounds3 Polygon::worldBounds(const Mat3& m, const Vec3& offset) const {
    Bounds3 b;
    for (const Vec2& v : vertices_) b.extend(m * Vec3(v, 0.0) + offset);
    return b;
}

double Polygon::support(const Vec3& dir) const {
    double best = -kInfinity;
    for (const Vec2& v : vertices_) best = std::max(best, dir.x * v.x + dir.y * v.y);
    return best;
}

bool Polygon::contains(double x, double y) const {
    // Crossings of the ray +x from (x, y) with every edge of every loop.
    bool inside = false;
    std::uint32_t begin = 0;
    for (const std::uint32_t end : loopEnds_) {
        Vec2 v0 = vertices_[end - 1];
        for (std::uint32_t i = begin; i < end; ++i) {
            const Vec2 v1 = vertices_[i];
            if ((v0.y > y) != (v1.y > y)) {
                const double side = (v1.x - v0.x) * (y - v0.y) - (x - v0.x) * (v1.y - v0.y);
                if ((side > 0.0) == (v1.y > v0.y)) inside = !inside;
            }
            v0 = v1;
        }
        begin = end;
    }
    return inside;
}

std::optional<LocalHit> Polygon::intersect(const Ray& ray, double tMin, double tMax) const {
    if (empty()) return std::nullopt;
    const auto hit = crossZPlane(ray, tMin, tMax);
    if (!hit) return std::nullopt;
    const double x = hit->x, y = hit->y;
    if (x < lo_.x || x > hi_.x || y < lo_.y || y > hi_.y || !contains(x, y)) return std::nullopt;
    return LocalHit{hit->t, Vec3(x, y, 0.0), Vec3(0.0, 0.0, 1.0)};
}

ConeClass Polygon::classify(const LocalCone& cone) const {
    return classifyWith(cone, [] {}, LocalFinish{cone});
}

ConeClass Polygon::classifyRanging(LocalCone& cone, double t0, double t1, const RigidBounds& back) const {
    return classifyWith(cone, [&] { cone.setRange(t0, t1, cone.absTol); }, back);
}

template <class SetRange, class Finish>
ConeClass Polygon::classifyWith(const LocalCone& cone, SetRange&& setRange, Finish&& finish) const {
    if (empty()) return missClass();
    const Vec3& p = cone.apex;
    const Vec3& axis = cone.axis;
    const double c = cone.cosHalf, s = cone.sinHalf;
    const auto [crosses, h, g2, k, an, depth, ank] = zPlaneApproach(cone);
    if (crosses) {
        // Fast path. Every ray crosses, and the footprint lies within
        // `radius` of the axis' crossing q (footprintReach's bound); an edge
        // farther from q cannot meet the cone. One pass over the edges, like
        // the ray's own even-odd test, finds q's side and the few edges near
        // it, which alone are tested exactly. The pass works in lengths
        // multiplied by an k (an = |axis.z|), as the disc's fast path does:
        // q and radius then need no division, so the pass does not wait for
        // one (each edge's start is scaled in the pass instead).
        const double qx = (an * p.x + depth * axis.x) * k, qy = (an * p.y + depth * axis.y) * k;
        const double radius = scaledReach(depth, an, g2, c, s, cone.absTol, ank);
        const double radius2 = radius * radius;
        // The footprint wholly off the polygon's bounding box: a miss.
        const bool offBox = (qx + radius < ank * lo_.x) | (qx - radius > ank * hi_.x) |
                            (qy + radius < ank * lo_.y) | (qy - radius > ank * hi_.y);
        // The edges near q (a few at most, or the exact path runs): those
        // whose line passes within `radius` of q, a superset of those within
        // `radius` (rarely larger: only an edge whose line runs by q but
        // which ends short of it is too many, and costs one exact test). The loop has no data-dependent
        // branch: whether an edge crosses q's line or lies near q is as good
        // as random from one cone to the next, and a mispredicted branch per
        // edge would cost more than the arithmetic. The count is not
        // clamped: the slots wrap, and past kMaxNear the list is not used.
        constexpr std::uint32_t kMaxNear = 16;  // a power of 2, for the wrap
        std::uint32_t nearEdge[kMaxNear];
        std::uint32_t nearCount = 0;
        using Mask2 = std::int64_t __attribute__((vector_size(16)));
        const Double2 qx2 = {qx, qx}, qy2 = {qy, qy}, r2 = {radius2, radius2}, scale = {ank, ank};
        const Double2 zero = {0.0, 0.0};
        Mask2 insideLanes = {0, 0};
        const std::uint32_t pairCount = static_cast<std::uint32_t>(edgePairs_.size());
        for (std::uint32_t pair = 0; pair < pairCount; ++pair) {
            const EdgePair& e = edgePairs_[pair];
            const Double2 wx = qx2 - scale * e.v0x, wy = qy2 - scale * e.v0y;
            const Double2 side = e.ex * wy - wx * e.ey;
            // The edge crosses q's line with v0 below it exactly when e
            // points up (e.y = v1.y - v0.y rounds to the sign of the
            // difference), so the side is tested against where v1 lies.
            const Mask2 above1 = scale * e.v1y > qy2;
            insideLanes ^= ((wy < zero) ^ above1) & ~((side > zero) ^ above1);
            const Mask2 near = side * side <= r2 * e.ee;
            nearEdge[nearCount % kMaxNear] = 2 * pair;
            nearCount += static_cast<std::uint32_t>(near[0] & 1);
            nearEdge[nearCount % kMaxNear] = 2 * pair + 1;
            nearCount += static_cast<std::uint32_t>(near[1] & 1);
        }
        const bool inside = ((insideLanes[0] ^ insideLanes[1]) & 1) != 0;
        const auto [tNear, tFar] = planeDepths(depth, an, g2, c, s);
        // Off the box, or no edge near: the footprint is wholly off the
        // polygon, or wholly in or out as q is. Whether a cone misses,
        // covers or straddles is as good as random from one to the next:
        // these answers are computed for every cone and settled by one
        // branch (as the disc's, Disc::classifyWith), with no local range
        // (absTol only; `finish` holds the depths against the range).
        if (offBox | (nearCount == 0))
            return rangedClass(finish, offBox | !inside, true, tNear, tFar);
        setRange();
        if (nearCount >= kMaxNear) return finish(classifyExactly(cone));
        if (cone.surelyAfter(tNear) || cone.surelyBefore(tFar) ||
            ballOutsideRange(cone, Vec3(center_, 0.0), radius_))
            return missClass();
        // The near edges against the cone itself: in the plane, against
        // its elliptic footprint (built only here: a footprint far from
        // every edge needs neither its divisions nor its root).
        {
            const FootprintQuadric footprint(cone, depth, an, k);
            // Counted, not branched on: whether a near edge meets the
            // footprint is as good as random.
            int meeting = 0;
            std::uint32_t met = 0;
            for (std::uint32_t n = 0; n < nearCount; ++n) {
                const std::uint32_t i = nearEdge[n];
                const Edge& edge = edges_[i];
                const bool meets = footprint.segmentMeets(edge.v0, edge.v0 + edge.e);
                meeting += int(meets);
                met = meets ? i : met;
            }
            if (meeting > 0) {
                const Edge& edge = edges_[met];
                const bool single = meeting == 1 && cone.surelyWithin(tNear, tFar) &&
                                    !footprint.containsStrictly(edge.v0) &&
                                    !footprint.containsStrictly(edge.v0 + edge.e);
                return finish(marginalClass(cone, tNear, tFar, single));
            }
        }
        // No edge in the cone: the footprint is wholly in or out, as q.
        if (!inside) return missClass();
        if (cone.surelyWithin(tNear, tFar)) return finish(fullClass(tNear, tFar));
        return finish(marginalClass(cone, tNear, tFar));
    }
    // The axis turned away from the plane, and every ray with it: a Miss.
    if (turnedAwayFromPlane(cone, h, g2)) return missClass();
    setRange();
    return finish(classifyExactly(cone));
}

ConeClass Polygon::classifyExactly(const LocalCone& cone) const {
    const Vec3 center(center_, 0.0);
    if (ballOutside(cone, center, radius_)) return missClass();
    const Vec3& p = cone.apex;
    const Vec3& axis = cone.axis;
    const double h = -p.z;
    const DotRange range = dotRange(cone, axis.z, std::sqrt(axis.x * axis.x + axis.y * axis.y));
    const double ballDist = glm::length(center - p);
    const double ballFar = ballDist + radius_;
    const double hTol = apexInPlaneTolerance(cone);
    if (std::abs(h) <= hTol) return apexInPlaneClass(cone, range, hTol, ballFar);
    const PlaneCrossing crossing = planeCrossing(range, h);
    if (!crossing.any) return missClass();
    const double tLo = std::max({crossing.tNear, ballDist - radius_, std::abs(h)});
    const double tHi = std::min(crossing.tFar, ballFar);
    if (cone.surelyAfter(tLo) || cone.surelyBefore(tHi)) return missClass();

    // The edges against the cone.
    int meeting = 0;
    bool endpointInside = false;
    std::uint32_t begin = 0;
    for (const std::uint32_t end : loopEnds_) {
        const ConePoint first = conePoint(cone, Vec3(vertices_[begin], 0.0) - p);
        ConePoint prev = first;
        for (std::uint32_t i = begin + 1; i <= end; ++i) {
            const ConePoint cur = i < end ? conePoint(cone, Vec3(vertices_[i], 0.0) - p) : first;
            if (segmentMeetsCone(cone, prev, cur)) {
                ++meeting;
                endpointInside = endpointInside || prev.inside || cur.inside;
            }
            prev = cur;
        }
        begin = end;
    }
    if (meeting > 0) {
        const bool single = meeting == 1 && !endpointInside && cone.surelyWithin(tLo, tHi);
        return marginalClass(cone, tLo, tHi, single);
    }
    // No edge in the cone: the footprint is wholly in or out. An unbounded
    // footprint cannot be inside the polygon.
    if (!crossing.all) return missClass();
    const double tAxis = h / axis.z;
    if (!contains(p.x + tAxis * axis.x, p.y + tAxis * axis.y)) return missClass();
    if (cone.surelyWithin(crossing.tNear, crossing.tFar))
        return fullClass(crossing.tNear, crossing.tFar);
    return marginalClass(cone, crossing.tNear, crossing.tFar);
}

std::vector<ShapeIssue> validate(const PolygonShape& record) {
    const std::vector<Vec3>& points = record.points;
    IssueList issues;
    // The point count is argument 0, the list of points argument 1.
    if (points.size() < 3) {
        issues.add(0, "a polygon needs at least 3 points, not " + std::to_string(points.size()));
        return issues.take();
    }
    for (std::size_t i = 0; i < points.size(); ++i)
        if (!isFinite(points[i]))
            issues.add(1, "point " + std::to_string(i + 1) + " of the polygon must be finite, not " +
                              formatVector(points[i]), static_cast<int>(i));
    if (!issues.empty()) return issues.take();
    const PointsPlane plane = pointsPlane(points);
    if (!plane.normal) {
        issues.add(0, "the points of the polygon are all on one line");
        return issues.take();
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
        const double off = std::abs(glm::dot(points[i] - plane.origin, *plane.normal));
        if (off > kFlatness * plane.extent) {
            issues.add(1, "the points of the polygon are not in one plane: point " + std::to_string(i + 1) + " is " +
                              formatNumber(off) + " away from the plane of the first ones",
                       static_cast<int>(i));
            break;
        }
    }
    return issues.take();
}

Placed<Polygon> place(const PolygonShape& record, const Transform& worldFromObject) {
    const std::vector<Vec3>& points = record.points;
    const PointsPlane plane = pointsPlane(points);  // with a normal: validate
    const Mat3 objectFromLocal = frameAroundAxis(*plane.normal);
    const Vec3 e1 = objectFromLocal[0], e2 = objectFromLocal[1];
    // Sub-polygons close when their first point repeats (within kPovEpsilon
    // in each coordinate, as the language's `=` compares numbers); the last
    // one is closed if it is not (POV-Ray warns and closes it).
    std::vector<Vec2> vertices;
    std::vector<std::uint32_t> loopEnds;
    std::size_t start = 0;
    for (std::size_t k = 0; k < points.size(); ++k) {
        const Vec3 gap = glm::abs(points[k] - points[start]);
        const bool closes = k > start && glm::all(glm::lessThan(gap, Vec3(kPovEpsilon)));
        if (closes) {
            loopEnds.push_back(static_cast<std::uint32_t>(vertices.size()));
            start = k + 1;
            continue;
        }
        const Vec3 d = points[k] - plane.origin;
        vertices.emplace_back(glm::dot(d, e1), glm::dot(d, e2));
    }
    if (start < points.size()) loopEnds.push_back(static_cast<std::uint32_t>(vertices.size()));
    LocalFrame frame = LocalFrame::make(worldFromObject, objectFromLocal, plane.origin);
    if (frame.kind == LocalFrame::Kind::General) {
        // An affine image of a planar polygon is a planar polygon: in a
        // rigid frame its cones stay circular and are classified exactly.
        const LocalFrame::Flattened flat = frame.flattened();
        for (Vec2& v : vertices) v = flat.inPlane * v;
        frame = flat.frame;
    }
    return {Polygon(std::move(vertices), std::move(loopEnds)), frame, Polygon::kName};
}

}  // namespace asos
