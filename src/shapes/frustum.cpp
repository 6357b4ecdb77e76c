#include "asos/shapes/frustum.hpp"

#include <algorithm>
#include <cmath>

#include "asos/geometry/frame.hpp"
#include "asos/geometry/margins.hpp"
#include "asos/shapes/cone_geometry.hpp"
#include "asos/shapes/local_frame.hpp"

namespace asos {

using namespace conegeom;

namespace {

double sq(double x) { return x * x; }

// The real roots of A t^2 + 2 B t + C (A may be 0); returns how many.
int quadraticRoots(double a, double b, double c, double roots[2]) {
    if (a == 0.0) {
        if (b == 0.0) return 0;
        roots[0] = -c / (2.0 * b);
        return 1;
    }
    const double disc = b * b - a * c;
    if (disc < 0.0) return 0;
    const double q = -(b + std::copysign(std::sqrt(disc), b));
    roots[0] = q / a;
    roots[1] = q != 0.0 ? c / q : roots[0];
    if (roots[0] > roots[1]) std::swap(roots[0], roots[1]);
    return 2;
}

}  // namespace

// The side's quadratic along a line, set up about the point of the line
// nearest a centre on the axis: the tip of the side's cone when that is near
// (rays grazing a tip would otherwise lose half their digits to the double
// root there), else the middle of the axis (rays from far away).
Frustum::SideQuadratic Frustum::sideQuadratic(const Profile& f, const Vec3& origin,
                                               const Vec3& d) {
    SideQuadratic q;
    const double mid = 0.5 * (f.zLo + f.zHi);
    q.centerZ = mid;
    if (f.slope != 0.0) {
        const double tipZ = -f.r0 / f.slope;
        if (std::abs(tipZ - mid) <= 2.0 * (f.zHi - f.zLo)) q.centerZ = tipZ;
    }
    const Vec3 center(0.0, 0.0, q.centerZ);
    const double dd = glm::dot(d, d);
    q.shift = glm::dot(center - origin, d);
    if (dd != 1.0) q.shift /= dd;
    q.o = origin + q.shift * d - center;
    // C = |o.xy|^2 - r(o.z)^2 is only as good as the larger of its terms.
    const auto scale = [&](const Vec3& o) {
        const double r = f.r0 + f.slope * (q.centerZ + o.z);
        return o.x * o.x + o.y * o.y + r * r;
    };
    double best = scale(q.o);
    // On a steep slope (a short, wide frustum) r(o.z) at the nearest point
    // can dwarf the distance the answer depends on; there the line's
    // crossing of the plane z = centre, where r is the centre's own radius,
    // is better.
    if (f.slope != 0.0 && d.z != 0.0) {
        const double crossing = (q.centerZ - origin.z) / d.z;
        const Vec3 o = origin + crossing * d - center;
        const Vec3 onPlane(o.x, o.y, 0.0);
        if (const double s = scale(onPlane); s < best) {
            q.shift = crossing;
            q.o = onPlane;
            best = s;
        }
    }
    // A needle (r far below the distances above) needs the line's point
    // nearest the axis within the slab zLo..zHi: elsewhere |o.xy|^2 can
    // exceed r^2 by more than a double's digits, and a ray starting inside
    // the needle "left" it at once. Taken only where it conditions C at
    // least 16 times better, so that rays the points above resolve keep
    // their bits.
    if (const double across2 = d.x * d.x + d.y * d.y; across2 > 0.0) {
        double nearest = -(origin.x * d.x + origin.y * d.y) / across2;
        if (d.z != 0.0) {
            const double t0 = (f.zLo - origin.z) / d.z, t1 = (f.zHi - origin.z) / d.z;
            nearest = std::clamp(nearest, std::min(t0, t1), std::max(t0, t1));
        }
        const Vec3 o = origin + nearest * d - center;
        if (16.0 * scale(o) < best) {
            q.shift = nearest;
            q.o = o;
        }
    }
    const double k = f.slope;
    const double rz = f.r0 + k * (q.centerZ + q.o.z);
    q.a = d.x * d.x + d.y * d.y - k * k * d.z * d.z;
    q.b = q.o.x * d.x + q.o.y * d.y - k * d.z * rz;
    q.c = q.o.x * q.o.x + q.o.y * q.o.y - rz * rz;
    q.count = quadraticRoots(q.a, q.b, q.c, q.roots);
    return q;
}

Frustum::Frustum(double r0, double r1, double length, bool capped)
    : r0_(r0), r1_(r1), length_(length), slope_((r1 - r0) / length),
      slant_(std::sqrt(1.0 + sq((r1 - r0) / length))), invSlant_(1.0 / slant_),
      invSide2_(1.0 / (sq(r1 - r0) + length * length)), capped_(capped) {
    // The smallest sphere centred on the axis holding both rims.
    const double zc = std::clamp((r1 * r1 - r0 * r0 + length * length) / (2.0 * length), 0.0, length);
    ball_ = {Vec3(0.0, 0.0, zc), std::sqrt(std::max(r0 * r0 + zc * zc, r1 * r1 + sq(length - zc)))};
}

Bounds3 Frustum::worldBounds(const Mat3& m, const Vec3& offset) const {
    Bounds3 b;
    const double radii[2] = {r0_, r1_};
    for (int end = 0; end < 2; ++end) {
        const Vec3 c = m * Vec3(0.0, 0.0, end ? length_ : 0.0) + offset;
        Vec3 half;
        for (int i = 0; i < 3; ++i) half[i] = radii[end] * length2d(m[0][i], m[1][i]);
        b.extend(Bounds3{c - half, c + half});
    }
    return b;
}

bool Frustum::intersectAny(const Ray& ray, double tMin, double tMax) const {
    // intersect's choice of t, without the hit record.
    if (empty()) return false;
    if (capped_) {
        const Interval in = solidInterval(ray.origin, ray.dir);
        return in.hit && ((in.enter >= tMin && in.enter <= tMax) || (in.exit >= tMin && in.exit <= tMax));
    }
    const SideQuadratic q = sideQuadratic(profile(), ray.origin, ray.dir);
    for (int i = 0; i < q.count; ++i) {
        const double z = q.centerZ + q.o.z + q.roots[i] * ray.dir.z;
        const double tt = q.shift + q.roots[i];
        if (z >= 0.0 && z <= length_ && tt >= tMin && tt <= tMax && tt < kInfinity) return true;
    }
    return false;
}

std::optional<LocalHit> Frustum::intersect(const Ray& ray, double tMin, double tMax) const {
    if (empty()) return std::nullopt;
    double t;
    int part;
    if (capped_) {
        const Interval in = solidInterval(ray.origin, ray.dir);
        if (!in.hit) return std::nullopt;
        if (in.enter >= tMin && in.enter <= tMax) {
            t = in.enter;
            part = in.enterPart;
        } else if (in.exit >= tMin && in.exit <= tMax) {
            t = in.exit;
            part = in.exitPart;
        } else {
            return std::nullopt;
        }
    } else {
        // Open: the side alone, between the rims.
        const SideQuadratic q = sideQuadratic(profile(), ray.origin, ray.dir);
        t = kInfinity;
        for (int i = 0; i < q.count; ++i) {
            const double z = q.centerZ + q.o.z + q.roots[i] * ray.dir.z;
            const double tt = q.shift + q.roots[i];
            if (z >= 0.0 && z <= length_ && tt >= tMin && tt <= tMax && tt < t) t = tt;
        }
        if (t == kInfinity) return std::nullopt;
        part = 0;
    }
    Vec3 point = ray.at(t), normal;
    if (part == 0) {
        normal = Vec3(point.x, point.y, -slope_ * radiusAt(point.z));
        if (normal == Vec3(0.0)) normal = Vec3(0.0, 0.0, slope_ > 0.0 ? -1.0 : 1.0);  // the tip
    } else {
        point.z = part == 1 ? 0.0 : length_;
        normal = Vec3(0.0, 0.0, part == 1 ? -1.0 : 1.0);
    }
    return LocalHit{t, point, normal, static_cast<std::uint8_t>(part)};
}

Frustum::Interval Frustum::solidInterval(const Profile& f, const Vec3& origin, const Vec3& d) {
    const SideQuadratic side = sideQuadratic(f, origin, d);
    const double shift = side.shift;
    const double oz = side.centerZ + side.o.z;  // the line's z at the shifted origin
    double lo = -kInfinity, hi = kInfinity;
    int loPart = 0, hiPart = 0;
    if (d.z == 0.0) {
        if (oz < f.zLo || oz > f.zHi) return {};
    } else {
        const double inv = 1.0 / d.z;
        const double a = (f.zLo - oz) * inv, b = (f.zHi - oz) * inv;
        lo = std::min(a, b);
        hi = std::max(a, b);
        loPart = d.z > 0.0 ? 1 : 2;
        hiPart = d.z > 0.0 ? 2 : 1;
    }
    // Inside the (double) cone of the side: A t^2 + 2 B t + C <= 0.
    const double qa = side.a, qb = side.b, qc = side.c;
    const double* roots = side.roots;
    const int n = side.count;
    auto clipLo = [&](double t) {
        if (t > lo) {
            lo = t;
            loPart = 0;
        }
    };
    auto clipHi = [&](double t) {
        if (t < hi) {
            hi = t;
            hiPart = 0;
        }
    };
    if (qa > 0.0) {
        if (n < 2) return {};
        clipLo(roots[0]);
        clipHi(roots[1]);
    } else if (qa < 0.0) {
        if (n == 2) {
            // Outside the roots; the slab holds one nappe's part.
            const double loB = std::max(lo, roots[1]);
            if (std::min(hi, roots[0]) - lo >= hi - loB) clipHi(roots[0]);
            else clipLo(roots[1]);
        }
    } else if (n == 1) {
        if (qb > 0.0) clipHi(roots[0]);
        else clipLo(roots[0]);
    } else if (qc > 0.0) {
        return {};
    }
    if (!(lo <= hi)) return {};
    return {true, shift + lo, shift + hi, loPart, hiPart};
}

bool Frustum::sideHitAhead(const Vec3& origin, const Vec3& d) const {
    const SideQuadratic q = sideQuadratic(profile(), origin, d);
    for (int i = 0; i < q.count; ++i) {
        const double z = q.centerZ + q.o.z + q.roots[i] * d.z;
        if (z >= 0.0 && z <= length_ && q.shift + q.roots[i] >= 0.0) return true;
    }
    return false;
}

double Frustum::distanceTo(double rho, double z) const {
    // The nearest of the side segment (r0, 0)-(r1, length) and, when capped,
    // the two cap segments from the axis, in the meridian half-plane.
    const double dr = r1_ - r0_;
    const double u = std::clamp(((rho - r0_) * dr + z * length_) * invSide2_, 0.0, 1.0);
    double best = sq(rho - (r0_ + u * dr)) + sq(z - u * length_);
    if (capped_) {
        if (z >= 0.0 && z <= length_ && rho <= radiusAt(z)) return 0.0;
        best = std::min({best, sq(std::max(rho - r0_, 0.0)) + sq(z),
                         sq(std::max(rho - r1_, 0.0)) + sq(z - length_)});
    }
    return std::sqrt(best);
}

double Frustum::depthInside(double rho, double z) const {
    // The boundary lies on the planes z = 0, z = length and the side's cone.
    return std::min({z, length_ - z, (radiusAt(z) - rho) * invSlant_});
}

ConeClass Frustum::classify(const LocalCone& cone) const {
    if (empty()) return missClass();
    if (ballOutside(cone, ball_.center, ball_.radius)) return missClass();
    const Vec3& p = cone.apex;
    const double rho = length2d(p.x, p.y);
    // Every point of the object is within dFar: the farthest point is on a rim.
    const double far2 = std::max(sq(rho + r0_) + sq(p.z), sq(rho + r1_) + sq(p.z - length_));
    const double tol =
        kTensOfUlps * (std::abs(p.x) + std::abs(p.y) + std::abs(p.z) + ball_.radius + ball_.center.z) +
        cone.absTol;
    const double rp = radiusAt(p.z);
    const double sideGap = (rho - rp) * invSlant_;
    const bool nearSide = p.z >= -tol && p.z <= length_ + tol && std::abs(sideGap) <= tol;
    const bool nearBottom = capped_ && std::abs(p.z) <= tol && rho <= r0_ + tol;
    const bool nearTop = capped_ && std::abs(p.z - length_) <= tol && rho <= r1_ + tol;
    if (nearSide || nearBottom || nearTop)
        return classifyOnSurface(cone, rho, tol, std::sqrt(far2), nearSide, nearBottom, nearTop);
    if (capped_ && p.z > 0.0 && p.z < length_ && rho < rp)
        return classifyInside(cone, rho, std::sqrt(far2));
    if (cone.tMinOuter > 0.0 && far2 < cone.tMinOuter * cone.tMinOuter) return missClass();
    return classifyOff(cone, rho, tol, far2);
}

ConeClass Frustum::classifyInside(const LocalCone& cone, double rho, double dFar) const {
    // Every ray leaves, no sooner than the boundary's distance.
    const double exitNear = depthInside(rho, cone.apex.z);
    if (cone.surelyAfter(exitNear) || cone.surelyBefore(dFar)) return missClass();
    if (cone.surelyWithin(exitNear, dFar)) {
        // From inside, a cone may see every part; where a rim's test (not
        // exact) calls one in it, the rays' parts are not known better.
        ConeClass out = withCreases(cone, fullClass(exitNear, dFar), true, true, true);
        if (out.creaseParts & 0b110) out.creaseParts |= 0b111;
        return out;
    }
    return marginalClass(cone, exitNear, dFar);
}

ConeClass Frustum::withCreases(const LocalCone& cone, ConeClass full, bool seesBase, bool seesTop,
                               bool inside) const {
    if (!cone.creases) return full;
    constexpr std::uint8_t kSide = 1, kBase = 2, kTop = 4;  // SurfaceHit::part 0, 1, 2
    if (capped_ && seesBase && r0_ > 0.0 && circleMayMeetCone(cone, 0.0, r0_)) full.creaseParts |= kSide | kBase;
    if (capped_ && seesTop && r1_ > 0.0 && circleMayMeetCone(cone, length_, r1_)) full.creaseParts |= kSide | kTop;
    // A tip, unless a capped solid hides it behind the cap the apex faces
    // from outside (in a Full cone it cannot be on the silhouette).
    const double radii[2] = {r0_, r1_};
    const bool hidden[2] = {capped_ && !inside && seesTop, capped_ && !inside && seesBase};
    for (int end = 0; end < 2; ++end) {
        if (radii[end] > 0.0 || hidden[end]) continue;
        const ConePoint tip = conePoint(cone, Vec3(0.0, 0.0, end ? length_ : 0.0) - cone.apex);
        if (coneDistance(cone, tip) <= cone.absTol) full.creaseParts |= kSide | ConeClass::kTipCrease;
    }
    return full;
}

ConeClass Frustum::classifyOnSurface(const LocalCone& cone, double rho, double tol, double dFar,
                                     bool nearSide, bool nearBottom, bool nearTop) const {
    // The apex is on the surface (to rounding). The object lies behind the
    // tangent plane there (the side's, or a cap's): rays leaving through it
    // meet the object again only within t <= tol / (n.d).
    const Vec3& p = cone.apex;
    auto leaves = [&](const Vec3& n, double gapOut) {
        const DotRange r = dotRange(cone, n);
        return r.lo > 0.0 && cone.surelyBefore((tol + std::max(0.0, -gapOut)) / r.lo);
    };
    if (nearSide && rho > 0.0) {
        const Vec3 n = Vec3(p.x / rho, p.y / rho, -slope_) / slant_;
        if (leaves(n, (rho - radiusAt(p.z)) / slant_)) return missClass();
    }
    if (nearBottom && leaves(Vec3(0.0, 0.0, -1.0), -p.z)) return missClass();
    if (nearTop && leaves(Vec3(0.0, 0.0, 1.0), p.z - length_)) return missClass();
    if (cone.surelyBefore(dFar + tol)) return missClass();
    return marginalClass(cone, cone.tMin, dFar + tol);
}

ConeClass Frustum::classifyOff(const LocalCone& cone, double rho, double tol, double far2) const {
    const Vec3& p = cone.apex;
    const double c = cone.cosHalf, s = cone.sinHalf;
    const double rp = radiusAt(p.z);  // the side's radius at the apex's height (signed)
    const bool facesBottom = r0_ > 0.0 && p.z < 0.0;  // the cap's side of its plane
    const bool facesTop = r1_ > 0.0 && p.z > length_;
    // No hit is nearer than the solid.
    const double dNear = distanceTo(rho, p.z);
    if (cone.surelyAfter(dNear)) return missClass();

    // Fast path: a capped solid is hit by every ray that passes through a
    // ball inside it. One around the middle of the axis' chord, as deep as
    // that point, holds every ray when tm sin(theta) is smaller, and each
    // ray enters the solid no later than the ball, by tm - sqrt(depth^2 -
    // (tm sin(theta))^2).
    Interval axisChord;
    if (capped_) {
        axisChord = solidInterval(p, cone.axis);
        if (c > 0.0 && axisChord.hit && axisChord.exit >= 0.0) {
            const double tm = 0.5 * (std::max(axisChord.enter, 0.0) + axisChord.exit);
            const Vec3 q = p + tm * cone.axis;
            const double depth = depthInside(length2d(q.x, q.y), q.z);
            const double spread = tm * s;
            if (spread < depth - tol) {
                const double tFar = tm - std::sqrt((depth - spread) * (depth + spread));
                if (cone.surelyWithin(dNear, tFar))
                    return withCreases(cone, fullClass(dNear, tFar), facesBottom, facesTop);
            }
        }
    }
    const double dFar = std::sqrt(far2);
    // Depths of first hits: rays enter a capped solid through a face turned
    // to the apex: on a side generator turned to it (P.u > rp) the squared
    // distance at height z is at most rho^2 - 2 r(z) rp + r(z)^2 + (z - p.z)^2,
    // largest at an end; a cap is within its far rim point.
    double frontFar = dFar;
    if (capped_) {
        double front2 = 0.0;
        for (const double z : {0.0, length_})
            front2 = std::max(front2, rho * rho - 2.0 * radiusAt(z) * rp + sq(radiusAt(z)) + sq(z - p.z));
        if (facesBottom) front2 = std::max(front2, sq(rho + r0_) + sq(p.z));
        if (facesTop) front2 = std::max(front2, sq(rho + r1_) + sq(p.z - length_));
        frontFar = std::sqrt(front2);
    }
    const double firstFar = dNear >= cone.tMinInner ? frontFar : dFar;
    // Up to dFar the cone lies within r = dFar sin(theta) of its axis: if the
    // axis misses the solid grown by r, so does the cone.
    if (c > 0.0 && !(capped_ && axisChord.hit && axisChord.exit >= 0.0)) {
        const Interval grownChord = solidInterval(grown(dFar * s + tol), p, cone.axis);
        if (!grownChord.hit || grownChord.exit < 0.0 || grownChord.enter > dFar) return missClass();
    }

    // The boundary as seen from the apex.
    int meeting = 0;
    bool endpointInside = false;
    Vec2 er(1.0, 0.0);
    if (rho > 0.0) er = Vec2(p.x, p.y) / rho;
    const double tangency = rho * rho - rp * rp;
    if (std::abs(tangency) <= 1e-6 * std::max(rho * rho, rp * rp)) {
        // The apex is (nearly) on the side's cone extended: the contour
        // generators are ill-conditioned. Be safe.
        return marginalClass(cone, dNear, firstFar);
    }
    // The rims. Of a capped solid only the silhouette arcs count: where
    // exactly one of the cap and the side (turned to the apex where
    // P.y > rc rp) faces the apex. An open surface keeps those and adds the
    // edge of what is seen through both openings: a rim counts whole when
    // the cone also meets the other opening (or whenever the apex is inside
    // the tube).
    const bool insideTube = !capped_ && p.z > 0.0 && p.z < length_ && rho < rp;
    const double rims[2][2] = {{0.0, r0_}, {length_, r1_}};
    for (int end = 0; end < 2; ++end) {
        const double zc = rims[end][0], rc = rims[end][1];
        if (!(rc > 0.0)) continue;
        bool silhouette = true;
        Arc arc;  // the whole circle
        if (!insideTube) {
            const bool faces = end ? facesTop : facesBottom;
            if (rho > 0.0) {
                arc.nu = faces ? er : -er;
                arc.kappa = (faces ? 1.0 : -1.0) * rc * rp / rho;
            } else {
                silhouette = faces != (0.0 > rc * rp);
            }
        }
        // A curved boundary in the cone: Marginal, and not a single edge.
        if (silhouette && circleMayMeetCone(cone, zc, rc, arc))
            return marginalClass(cone, dNear, firstFar);
        if (!capped_ && !insideTube) {
            const double otherZ = rims[1 - end][0], otherR = rims[1 - end][1];
            if (otherR > 0.0 && discMayMeetCone(cone, otherZ, otherR) &&
                circleMayMeetCone(cone, zc, rc))
                return marginalClass(cone, dNear, firstFar);
        }
    }
    if (tangency > 0.0) {
        // The two contour generators: where the tangent plane holds the apex.
        const double ca = rp / rho, sa = std::sqrt(tangency) / rho;
        const Vec2 et(-er.y, er.x);
        for (const double sign : {-1.0, 1.0}) {
            const Vec2 u = ca * er + sign * sa * et;
            const ConePoint a = conePoint(cone, Vec3(r0_ * u, 0.0) - p);
            const ConePoint b = conePoint(cone, Vec3(r1_ * u, length_) - p);
            if (segmentMeetsCone(cone, a, b)) {
                ++meeting;
                endpointInside = endpointInside || a.inside || b.inside;
            }
        }
    }
    if (meeting > 0) {
        const bool single = meeting == 1 && !endpointInside && cone.surelyWithin(dNear, dFar);
        return marginalClass(cone, dNear, firstFar, single);
    }
    // No boundary in the cone: every ray hits or none does, as the axis.
    const bool axisHits =
        capped_ ? axisChord.hit && axisChord.exit >= 0.0 : sideHitAhead(p, cone.axis);
    if (!axisHits) return missClass();
    if (cone.surelyWithin(dNear, frontFar))
        return withCreases(cone, fullClass(dNear, frontFar), facesBottom, facesTop);
    return marginalClass(cone, dNear, firstFar);
}

HoldingPlanes Frustum::holdingPlanes(const Vec3& point) const {
    HoldingPlanes h;
    h.add(Vec3(0.0, 0.0, -1.0), 0.0);
    h.add(Vec3(0.0, 0.0, 1.0), length_);
    // Outside a capped solid (beyond classify's positional tolerance) a cap
    // on such a plane faces away from the point; an open surface has no flat
    // piece.
    const double tol = kTensOfUlps * (l1Norm(point) + ball_.radius + ball_.center.z);
    const double rho = length2d(point.x, point.y);
    h.thinContact = !capped_ || point.z < -tol || point.z > length_ + tol ||
                    (rho - radiusAt(point.z)) * invSlant_ > tol;
    return h;
}

bool Frustum::raysLeave(const LocalRays& rays) const {
    // n = (L cos phi, L sin phi, r0 - r1), at the origin's angle phi, has
    // n . x <= L r0 over the solid (at both rims, L r0).
    const Vec3& a = rays.origin;
    const Vec3 z(0.0, 0.0, 1.0);
    if (a.z <= 0.0 && rays.awayFrom(-z)) return true;
    if (a.z >= length_ && rays.awayFrom(z)) return true;
    const double rho = std::sqrt(a.x * a.x + a.y * a.y);
    if (!(rho > 0.0)) return false;
    const Vec3 n(length_ * a.x / rho, length_ * a.y / rho, r0_ - r1_);
    return glm::dot(n, a) >= length_ * r0_ && rays.awayFrom(n);
}

std::optional<FrustumAxis> frustumAxis(const Vec3& base, const Vec3& cap) {
    const Vec3 axis = cap - base;
    const double length = glm::length(axis);
    const double scale = std::abs(base.x) + std::abs(base.y) + std::abs(base.z) + std::abs(cap.x) +
                         std::abs(cap.y) + std::abs(cap.z);
    if (!(length > kThousandsOfUlps * scale) || length == 0.0) return std::nullopt;  // zero to rounding
    return FrustumAxis{frameAroundAxis(axis / length), length};
}

}  // namespace asos
