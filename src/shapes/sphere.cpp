#include "asos/shapes/sphere.hpp"

#include <cmath>

#include "asos/shapes/cone_geometry.hpp"

namespace asos {

using namespace conegeom;

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

}  // namespace asos
