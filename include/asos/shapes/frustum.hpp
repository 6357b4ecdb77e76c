#pragma once
// The geometry shared by POV-Ray's cylinder and cone: in the local frame the
// axis runs along +z from 0 to length, the radius goes linearly from r0 at
// z = 0 to r1 at z = length, with caps (discs) at both ends unless open.
// Cylinder and TruncatedCone own their ray tests; the cone classification
// and the answers about rays from one origin, the same for both, live here.
#include <algorithm>
#include <cmath>
#include <optional>

#include "asos/geometry/bounds.hpp"
#include "asos/geometry/cone.hpp"
#include "asos/geometry/ray.hpp"
#include "asos/shapes/holding_planes.hpp"
#include "asos/shapes/local_cone.hpp"
#include "asos/shapes/local_hit.hpp"
#include "asos/shapes/local_rays.hpp"

namespace asos {

class Frustum {
public:
    Frustum(double r0, double r1, double length, bool capped);

    double r0() const { return r0_; }
    double r1() const { return r1_; }
    double length() const { return length_; }
    bool capped() const { return capped_; }
    bool empty() const { return !(r0_ > 0.0 || r1_ > 0.0); }
    double radiusAt(double z) const { return r0_ + slope_ * z; }
    // POV-Ray's inside of a cylinder or cone, open or not: the solid, its
    // surface left out when capped and counted when open (POV-Ray moves the
    // surface by 1e-10 of its unit shape either way).
    bool inside(const Vec3& p) const {
        const double r = radiusAt(p.z), rho2 = p.x * p.x + p.y * p.y;
        if (capped_) return p.z > 0.0 && p.z < length_ && rho2 < r * r;
        return p.z >= 0.0 && p.z <= length_ && rho2 <= r * r;
    }

    BoundingSphere boundingSphere() const { return ball_; }
    Bounds3 worldBounds(const Mat3& worldFromLocal, const Vec3& offset) const;

    // The nearest hit of the surface (side, and caps unless open) in [tMin, tMax].
    std::optional<LocalHit> intersect(const Ray& ray, double tMin, double tMax) const;
    // Whether intersect would find a hit, without making its record (shadow
    // rays).
    bool intersectAny(const Ray& ray, double tMin, double tMax) const;
    // Outside a capped solid: Full iff the cone avoids the silhouette (the two
    // contour generators and the rim arcs between a face turned to the apex and
    // one turned away) and its axis hits; an open surface counts both rims
    // whole. See docs/geometry.md.
    ConeClass classify(const LocalCone& cone) const;
    // The capped solid holds the open surface too: a cap's plane the origin
    // is beyond, or the plane tangent to the side along the generator
    // facing the origin.
    bool raysLeave(const LocalRays& rays) const;
    // The two cap planes (they hold an open surface too); an open surface
    // is curved, a capped one a solid seen from outside or not.
    HoldingPlanes holdingPlanes(const Vec3& point) const;
    // The solid is the hull of its rims.
    double support(const Vec3& dir) const {
        const double across = std::sqrt(dir.x * dir.x + dir.y * dir.y);
        return std::max(r0_ * across, dir.z * length_ + r1_ * across);
    }

private:
public:
    // The part of the line o + t d inside the capped solid, and which part
    // of the surface it enters and leaves through (0 side, 1 base, 2 cap).
    // Intersecting the slab's and the side's intervals leaves no crack at
    // the rims for a ray to slip through.
    struct Interval {
        bool hit = false;
        double enter = 0.0, exit = 0.0;
        int enterPart = 0, exitPart = 0;
    };
    Interval solidInterval(const Vec3& o, const Vec3& d) const {
        return solidInterval(profile(), o, d);
    }

private:
    // A solid of this family: radius r0 + slope z over z in [zLo, zHi].
    struct Profile {
        double r0, slope, zLo, zHi;
    };
    Profile profile() const { return {r0_, slope_, 0.0, length_}; }
    // The profile holding every point within `grow` of the solid: the side
    // pushed out by grow * slant (grow along its normal), the ends by grow.
    Profile grown(double grow) const {
        return {r0_ + grow * slant_, slope_, -grow, length_ + grow};
    }
    struct SideQuadratic {
        double centerZ;  // the centre on the axis the line is expanded about
        double shift;    // t of the line's point nearest it
        Vec3 o;          // that point, relative to the centre
        double a, b, c;  // the side: a u^2 + 2 b u + c = 0 at t = shift + u
        double roots[2];
        int count;
    };
    static SideQuadratic sideQuadratic(const Profile& f, const Vec3& origin, const Vec3& d);
    static Interval solidInterval(const Profile& f, const Vec3& origin, const Vec3& d);
    // Whether the ray o + t d, t >= 0, meets the side surface.
    bool sideHitAhead(const Vec3& o, const Vec3& d) const;
    // Distance from a point (rho, z) of a meridian half-plane to the solid
    // (capped) or to the side surface (open).
    double distanceTo(double rho, double z) const;
    // Distance from a point inside the solid to its boundary, from below.
    double depthInside(double rho, double z) const;

    ConeClass classifyInside(const LocalCone& cone, double rho, double dFar) const;
    // A Full answer with the creases the cone may hold: the rims of a
    // capped solid's caps it sees (where the side meets them), and a tip
    // not hidden behind a cap (from outside).
    ConeClass withCreases(const LocalCone& cone, ConeClass full, bool seesBase, bool seesTop,
                          bool inside = false) const;
    ConeClass classifyOnSurface(const LocalCone& cone, double rho, double tol, double dFar,
                                bool nearSide, bool nearBottom, bool nearTop) const;
    // far2: the squared distance to the farthest point of the object.
    ConeClass classifyOff(const LocalCone& cone, double rho, double tol, double far2) const;

    double r0_, r1_, length_;
    double slope_;  // dr/dz
    double slant_;  // sqrt(1 + slope^2)
    double invSlant_;
    double invSide2_;  // 1 / |(r1 - r0, length)|^2
    bool capped_;
    BoundingSphere ball_;
};

// The rigid placement of a frustum's local frame on the axis from `base` to
// `cap` (POV-Ray's cylinder and cone): local +z along it, from the base at
// the origin to the cap at z = length; none when the points coincide (to the
// rounding of their coordinates).
struct FrustumAxis {
    Mat3 objectFromLocal;
    double length;
};
std::optional<FrustumAxis> frustumAxis(const Vec3& base, const Vec3& cap);

}  // namespace asos
