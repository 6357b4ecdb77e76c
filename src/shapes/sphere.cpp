#include "asos/shapes/sphere.hpp"

#include <cmath>

#include "asos/shapes/cone_geometry.hpp"

namespace asos {

using namespace conegeom;

namespace {
// Sphere::classifyAcrossScale answers Marginal itself for cones narrower
// than this (sine of the half-angle).
constexpr double kAcrossScaleMarginalSin = 0.02;
}  // namespace

Bounds3 Sphere::worldBounds(const Mat3& m, const Vec3& offset) const {
    // The image of a ball is an ellipsoid; its extent along world axis i is
    // radius * |row i of m|.
    Vec3 half;
    for (int i = 0; i < 3; ++i) half[i] = radius_ * glm::length(Vec3(m[0][i], m[1][i], m[2][i]));
    return {offset - half, offset + half};
}

ConeClass Sphere::classify(const LocalCone& cone) const {
    if (!(radius_ > 0.0)) return missClass();
    const double r = radius_, r2 = r * r;
    const Vec3 w = -cone.apex;  // centre - apex
    const double d2 = glm::dot(w, w);
    const double c = cone.cosHalf, s = cone.sinHalf;
    // How far d2 - r2 may be from its sign: the apex is "on" the sphere within.
    const double band = 4e-15 * (d2 + r2) + 2.0 * r * cone.absTol;
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
            if (cone.surelyWithin(tNear, tFar)) return fullClass(tNear, tFar);
        }
        // Angular miss: the ball lies outside the cone.
        if (c >= 0.0) {
            if (sigma < 0.0 && sigma * sigma * c * c > p2 * s * s) return missClass();
            const double rhs = sigma * s + r;
            if (rhs < 0.0 || p2 * c * c > rhs * rhs) return missClass();
        } else {
            const double dp = std::sqrt(p2);
            if (s * sigma < c * dp && (sigma * c + dp * s < 0.0 || dp * c - sigma * s > r))
                return missClass();
        }
        // The silhouette is inside the cone (or the range cuts the hits).
        // Every front hit lies in [D - r, T]; a ray whose front hit is before
        // the range may still hit the back, up to D + r.
        const double dist = std::sqrt(d2), tangent = std::sqrt(t2);
        const double nearest = t2 / (dist + r);  // dist - r
        if (cone.surelyAfter(nearest) || cone.surelyBefore(dist + r)) return missClass();
        return marginalClass(cone, nearest, nearest >= cone.tMinInner ? tangent : dist + r);
    }

    const double dist = std::sqrt(d2);
    const double dp = std::sqrt(p2);
    if (r2 - d2 > band) {
        // Apex inside: every ray leaves at t(x) = x + sqrt(h + x^2), h = r^2 - D^2,
        // increasing in x = w.d in [D cos(beta + theta), D cos(beta - theta)].
        const double h = r2 - d2;
        const double xLo = -s * sigma >= c * dp ? -dist : sigma * c - dp * s;
        const double xHi = s * sigma >= c * dp ? dist : sigma * c + dp * s;
        auto exitAt = [&](double x) {
            const double root = std::sqrt(h + x * x);
            return x >= 0.0 ? x + root : h / (root - x);
        };
        const double tNear = exitAt(xLo), tFar = exitAt(xHi);
        if (cone.surelyAfter(tNear) || cone.surelyBefore(tFar)) return missClass();
        if (cone.surelyWithin(tNear, tFar)) return fullClass(tNear, tFar);
        return marginalClass(cone, tNear, tFar);
    }

    // Apex on the sphere (to rounding). Rays leaving through the tangent
    // plane can only meet the sphere again within t <= band / (2 D m.d).
    if (!(dist > 0.0)) return marginalClass(cone, cone.tMin, 2.0 * r);
    const DotRange out = dotRange(cone, -w / dist);
    if (out.lo > 0.0) {
        const double tHit = (band + std::max(0.0, r2 - d2)) / (2.0 * dist * out.lo);
        if (cone.surelyBefore(tHit)) return missClass();
        return marginalClass(cone, cone.tMin, tHit);
    }
    if (out.hi < 0.0) {
        // Every ray goes in and leaves at the far end of its chord, t near
        // 2 |w.d| with |w.d| in [D (-hi), D (-lo)].
        const double gLo = -dist * out.hi, gHi = -dist * out.lo;
        const double exitLo = gLo + std::sqrt(std::max(0.0, gLo * gLo - band));
        const double exitHi = gHi + std::sqrt(gHi * gHi + band);
        if (cone.surelyBefore(exitHi)) return missClass();
        // Full only when each ray surely enters (at t <= band / (2 g)) before it leaves.
        if (gLo * gLo > 4.0 * band && cone.surelyWithin(exitLo, exitHi))
            return fullClass(cone.tMin, exitHi);
        return marginalClass(cone, cone.tMin, exitHi);
    }
    return marginalClass(cone, cone.tMin, dist + r);
}

std::optional<ConeClass> Sphere::classifyAcrossScale(const PreparedCone& cone,
                                                     const LocalFrame& frame) const {
    if (!(radius_ > 0.0)) return missClass();
    const double c = cone.cosHalf, s = cone.sinHalf;
    if (!(c > 0.0 && s > 0.0)) return std::nullopt;
    const Mat3& m = frame.localFromWorld;
    const Mat3& gm = frame.gram;
    const Vec3& o = cone.apex;
    const Vec3& a = cone.axis;
    const Vec3& off = frame.localOffset;
    // The local apex p, written out (glm's product is a call).
    const Vec3 p(m[0][0] * o.x + m[1][0] * o.y + m[2][0] * o.z + off.x,
                 m[0][1] * o.x + m[1][1] * o.y + m[2][1] * o.z + off.y,
                 m[0][2] * o.x + m[1][2] * o.y + m[2][2] * o.z + off.z);
    // A world ray o + t d (d unit) is the local ray p + t A d with the same t
    // (A = localFromWorld): it meets the sphere where g t^2 - 2 x t + h = 0,
    // with x = u.d for the world vector u = A^T (-p), g = d^T G d (G = A^T A)
    // and h = |p|^2 - r^2. Its line meets the sphere iff
    // f(d) = x^2 - h g = d^T (u u^T - h G) d >= 0.
    const Vec3 u(-(m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z), -(m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z),
                 -(m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z));
    const Vec3 ga(gm[0][0] * a.x + gm[1][0] * a.y + gm[2][0] * a.z, gm[0][1] * a.x + gm[1][1] * a.y + gm[2][1] * a.z,
                  gm[0][2] * a.x + gm[1][2] * a.y + gm[2][2] * a.z);
    const double r = radius_, r2 = r * r;
    const double d2 = glm::dot(p, p), h = d2 - r2;
    const double l1p = std::abs(p.x) + std::abs(p.y) + std::abs(p.z);
    const double l1u = std::abs(u.x) + std::abs(u.y) + std::abs(u.z);
    // p is known to absTol (classifyGeneral's tolerance), so h to `band` (its
    // rounding and that tolerance, |p| <= l1p) and u to ue (A^T's rounding
    // and the tolerance carried by it).
    const double absTol = 1e-11 * (l1p + r);
    const double band = 4e-15 * (d2 + r2) + absTol * (2.0 * (l1p + r) + absTol);
    const double hLo = h - band, hHi = h + band;
    if (!(hLo > 0.0)) return std::nullopt;  // apex inside or on the sphere: the local path
    const double ue = frame.sigmaMax * (2e-15 * l1p + absTol) + 1e-15 * l1u;
    const double ua = glm::dot(u, a), la2 = glm::dot(a, ga);
    const Vec3 uAcross = u - ua * a;  // as a vector: no cancellation near the axis
    const double uPerp2 = glm::dot(uAcross, uAcross), u2 = glm::dot(u, u);
    // f along the axis, and its gradient's part across the axis: Q a = u ua - h G a.
    const double fa = ua * ua - h * la2;
    const Vec3 qa = ua * u - h * ga;
    const Vec3 qPerp = qa - fa * a;
    const double sigma2 = frame.sigmaMax * frame.sigmaMax;
    const double fTol = 2.0 * std::abs(ua) * ue + ue * ue + band * la2 + 1e-15 * (u2 + std::abs(h) * la2);
    const double qTol = 2.0 * l1u * ue + band * sigma2 + 1e-15 * (u2 + std::abs(h) * sigma2);
    // For d = a + e in the cone: e.a in [c - 1, 0] and |e across a| <= s, so
    // f(d) = f(a) + 2 Q a.e + e^T Q e lies within `lin` of f(a) and, Q being
    // u u^T - h G, e^T Q e between -h e^T G e and (u.e)^2. With (x + y)^2 <=
    // (1 + s) x^2 + (1 + 1/s) y^2 for the parts across and along the axis:
    // (u.e)^2 <= (1 + s) s^2 |u across a|^2 + (1 + 1/s)(1 - c)^2 ua^2, and
    // e^T G e the same with G's largest value across the axis (at most its
    // trace there, tr G - a.Ga, and at most sigmaMax^2) and a.Ga.
    const double qPerpLen = std::sqrt(glm::dot(qPerp, qPerp)) * (1.0 + 1e-14) + qTol;
    const double lin = 2.0 * (qPerpLen * s + (std::abs(fa) + fTol) * (1.0 - c)) + fTol;
    // (1 - c) / s <= s for c >= 0: no division.
    const double along = (1.0 - c) * ((1.0 - c) + s), across = (1.0 + s) * s * s;
    const double gAcross = std::min(sigma2, frame.gramTrace - la2 + 1e-14 * frame.gramTrace);
    const double uTol = 2.0 * l1u * ue + ue * ue;
    const double fHi = fa + lin + ((uPerp2 + uTol) * across + (ua * ua + uTol) * along) * (1.0 + 1e-14);
    const double fLo = fa - lin - hHi * (gAcross * across + la2 * along) * (1.0 + 1e-13);
    // Miss: no ray's line meets the sphere, or every ray leaves the apex away
    // from it (x < 0 over the cone: both roots negative).
    const double away = -ua * c - ue;
    if (fHi < 0.0 || (away > 0.0 && away * away > uPerp2 * (s * s) * (1.0 + 1e-14))) return missClass();
    // Every ray ahead of the apex (x > 0 over the cone): its front hit
    // h / (x + sqrt(f)) against the bounds on x, f and h.
    const double uPerp = std::sqrt(uPerp2), uLen = std::sqrt(u2);
    const double xMin = ua * c - uPerp * s - ue;
    if (!(xMin > 0.0)) return std::nullopt;
    const double xMax = (s * ua >= c * uPerp ? uLen : ua * c + uPerp * s) + ue;
    const double tNear = hLo / (xMax + std::sqrt(fHi)) * (1.0 - 1e-12);
    LocalCone world;
    world.setRange(cone.tMin, cone.tMax, absTol / frame.sigmaMin);
    if (world.surelyAfter(tNear)) return missClass();
    const RigidBounds back{world.absTol, 1.0, cone.tMin, cone.tMax};
    if (fLo >= 0.0) {
        // Full: every ray's line meets the sphere, and every front hit is in range.
        const double tFar = hHi / (xMin + std::sqrt(fLo)) * (1.0 + 1e-12);
        if (!world.surelyWithin(tNear, tFar)) return std::nullopt;
        return back(fullClass(tNear, tFar));
    }
    // The silhouette may be in the cone. A narrow cone's bounds on f are as
    // good as the bounding cone's; a wider one is surely Marginal when its
    // axis hits and it is wider than the ellipsoid's bounding ball (radius
    // r / sigmaMin about the centre) seen from the apex. Marginal then, when
    // every front hit (at most h / x, where a ray grazes) is in range, so
    // that it is each ray's first.
    const Vec3 toCentre = frame.worldOffset - o;
    const double ballSpan = s * frame.sigmaMin;
    const bool wider = ballSpan * ballSpan * glm::dot(toCentre, toCentre) > r2 * (1.0 + 1e-12);
    if (!(s < kAcrossScaleMarginalSin || (fa > fTol && wider))) return std::nullopt;
    const double tFar = hHi / xMin * (1.0 + 1e-12);
    if (!world.surelyWithin(tNear, tFar)) return std::nullopt;
    return back(marginalClass(world, tNear, tFar));
}

}  // namespace asos
