#include "asos/shapes/sphere.hpp"

#include <cmath>

#include "asos/geometry/margins.hpp"
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

ConeClass Sphere::classifyApexNear(const LocalCone& cone, double d2, double p2, double sigma,
                                   double band) const {
    const double r = radius_, r2 = r * r;
    const Vec3 w = -cone.apex;  // centre - apex
    const double c = cone.cosHalf, s = cone.sinHalf;
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
    // In world terms, with the apex w from the centre and the Gram matrix
    // G = A^T A of A = localFromWorld (symmetric; written out, as glm's
    // product is a call): a world ray apex + t d (d unit) is the local ray
    // A w + t A d, with the same t, so it meets the sphere where
    // g t^2 - 2 x t + h = 0, with x = u.d for u = -G w, g = d^T G d and
    // h = w^T G w - r^2. Its line meets the sphere iff
    // f(d) = x^2 - h g = d^T (u u^T - h G) d >= 0.
    const Mat3& gm = frame.gram;
    const Vec3& a = cone.axis;
    const Vec3& centre = frame.worldOffset;
    const Vec3 w = cone.apex - centre;
    const Vec3 u(-(gm[0][0] * w.x + gm[1][0] * w.y + gm[2][0] * w.z), -(gm[0][1] * w.x + gm[1][1] * w.y + gm[2][1] * w.z),
                 -(gm[0][2] * w.x + gm[1][2] * w.y + gm[2][2] * w.z));
    const Vec3 ga(gm[0][0] * a.x + gm[1][0] * a.y + gm[2][0] * a.z, gm[0][1] * a.x + gm[1][1] * a.y + gm[2][1] * a.z,
                  gm[0][2] * a.x + gm[1][2] * a.y + gm[2][2] * a.z);
    const double r2 = radius_ * radius_;
    const double uw = -glm::dot(u, w), h = uw - r2;
    const double ua = glm::dot(u, a), la2 = glm::dot(a, ga);
    const Vec3 uAcross = u - ua * a;  // as a vector: no cancellation near the axis
    const double uPerp2 = glm::dot(uAcross, uAcross), u2 = glm::dot(u, u);
    // f along the axis, and its gradient's part across the axis: Q a = u ua - h G a.
    const double fa = ua * ua - h * la2;
    const Vec3 qPerp = ua * u - h * ga - fa * a;
    const double qPerp2 = glm::dot(qPerp, qPerp);
    // Tolerances. The apex and the centre are known to tolW (their
    // coordinates' rounding, and the frame's offsets', far below it); so u to
    // ue, h to `band`, f(a) to fTol and |Q a| to qTol, rounding included.
    const double sigma2 = frame.sigmaMax * frame.sigmaMax;
    const double tolW = kPositionTolerance * (std::abs(w.x) + std::abs(w.y) + std::abs(w.z) +
                                              std::abs(centre.x) + std::abs(centre.y) + std::abs(centre.z));
    const double l1u = std::abs(u.x) + std::abs(u.y) + std::abs(u.z);
    const double ue = 1.001 * sigma2 * tolW;
    const double band = kFewUlps * (uw + r2) + tolW * (2.0 * l1u + sigma2 * tolW);
    const double hLo = h - band, hHi = h + band;
    if (!(hLo > 0.0)) return std::nullopt;  // apex inside or on the sphere: the local path
    const double fTol = (2.0 * l1u + ue) * ue + band * la2 + kFewUlps * (u2 + h * la2);
    const double qTol = (2.0 * l1u + ue) * ue + band * sigma2 + kFewUlps * (u2 + h * sigma2);
    // For d = a + e in the cone: e.a in [c - 1, 0] and |e across a| <= s, so
    // f(d) = f(a) + 2 Q a.e + e^T Q e lies within `lin` of f(a) and, Q being
    // u u^T - h G, e^T Q e between -h e^T G e and (u.e)^2. With (x + y)^2 <=
    // (1 + s) x^2 + (1 + 1/s) y^2 for the parts across and along the axis:
    // (u.e)^2 <= (1 + s) s^2 |u across a|^2 + (1 + 1/s)(1 - c)^2 ua^2, and
    // e^T G e the same with G's largest value across the axis (at most its
    // trace there, tr G - a.Ga, and at most sigmaMax^2) and a.Ga. And
    // (1 - c) / s <= s for c >= 0: no division.
    const double along = (1.0 - c) * ((1.0 - c) + s), across = (1.0 + s) * s * s;
    const double gAcross = std::min(sigma2, frame.gramTrace - la2 + kTensOfUlps * frame.gramTrace);
    const double uTol = (2.0 * l1u + ue) * ue;
    const double qPerpLen = std::sqrt(qPerp2) + qTol;
    const double lin = 2.0 * (qPerpLen * s + (std::abs(fa) + fTol) * (1.0 - c)) + fTol;
    const double fHi = (fa + lin + (uPerp2 + uTol) * across + (ua * ua + uTol) * along) * (1.0 + kTensOfUlps);
    const double fLo = fa - lin - hHi * (gAcross * across + la2 * along) * (1.0 + kHundredsOfUlps);
    // Miss: no ray's line meets the sphere, or every ray leaves the apex away
    // from it (x < 0 over the cone: both roots negative).
    const double away = -ua * c - ue;
    if (fHi < 0.0 || (away > 0.0 && away * away > uPerp2 * (s * s) * (1.0 + kTensOfUlps))) return missClass();
    // Every ray ahead of the apex (x > 0 over the cone): its front hit
    // h / (x + sqrt(f)) against the bounds on x, f and h.
    const double uPerp = std::sqrt(uPerp2), uLen = std::sqrt(u2);
    const double xMin = ua * c - uPerp * s - ue;
    if (!(xMin > 0.0)) return std::nullopt;
    const double xMax = (s * ua >= c * uPerp ? uLen : ua * c + uPerp * s) + ue;
    const double tNear = padDown(hLo / (xMax + std::sqrt(fHi)));
    LocalCone world;
    world.setRange(cone.tMin, cone.tMax, tolW);
    if (world.surelyAfter(tNear)) return missClass();
    const RigidBounds back{tolW, 1.0, cone.tMin, cone.tMax};
    if (fLo >= 0.0) {
        // Full: every ray's line meets the sphere, and every front hit is in range.
        const double tFar = padUp(hHi / (xMin + std::sqrt(fLo)));
        if (!world.surelyWithin(tNear, tFar)) return std::nullopt;
        return back(fullClass(tNear, tFar));
    }
    // The silhouette may be in the cone. A narrow cone's bounds on f are as
    // good as the bounding cone's; a wider one is surely Marginal when its
    // axis hits and it is wider than the ellipsoid's bounding ball (radius
    // r / sigmaMin about the centre) seen from the apex. Marginal then, when
    // every front hit (at most h / x, where a ray grazes) is in range, so
    // that it is each ray's first.
    const double ballSpan = s * frame.sigmaMin;
    const bool wider = ballSpan * ballSpan * glm::dot(w, w) > padUp(r2);
    if (!(s < kAcrossScaleMarginalSin || (fa > fTol && wider))) return std::nullopt;
    const double tFar = padUp(hHi / xMin);
    if (!world.surelyWithin(tNear, tFar)) return std::nullopt;
    return back(marginalClass(world, tNear, tFar));
}

std::vector<ShapeIssue> validate(const SphereShape& record) {
    IssueList issues;
    issues.finite(0, record.center, "the centre of a sphere");
    issues.positive(1, record.radius, "the radius of a sphere");
    return issues.take();
}

Placed<Sphere> place(const SphereShape& record, const Transform& worldFromObject) {
    return {Sphere(record.radius), LocalFrame::make(worldFromObject, Mat3(1.0), record.center), Sphere::kName};
}

}  // namespace asos
