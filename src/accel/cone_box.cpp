#include "asos/accel/cone_box.hpp"

#include <algorithm>
#include <cmath>

#include "asos/geometry/margins.hpp"

// Why this test never rejects a box that the cone touches.
//
// Let K be the cone's solid: {a + t u : |u| = 1, angle(u, w) <= θ, tMin <= t <= tMax},
// B the closed box, S its bounding sphere (centre c, radius r = half diagonal).
// The test rejects B only when one of these holds (each by more than a slack s
// that is far larger than the rounding error of the quantity compared):
//   1. B misses the axis-aligned bounds of K (computed exactly below).
//      K lies inside its bounds, so K and B are disjoint.
//   2. B misses the slab {x : axialLo <= (x - a).w <= axialHi}. Every point of
//      K has (x - a).w = t cos ψ with ψ <= θ and t in [tMin, tMax], which lies
//      in that slab, so K is in the slab and B is not.
//   3. B misses the spherical shell tMin <= |x - a| <= tMax, which holds K.
//   4. The distance from c to K exceeds r. distanceTo() computes that
//      distance exactly: K is symmetric about its axis, so for any point x of
//      K, turning x about the axis into the half-plane through c keeps x in
//      K and does not increase |x - c|; in that half-plane K is the set of
//      points at polar radius t in [tMin, tMax] and polar angle (from the
//      axis) in [0, θ]. If c's polar angle φ <= θ the nearest point is on
//      c's own ray: distance max(0, tMin - |c - a|, |c - a| - tMax). Otherwise
//      the polar angle of any point differs from φ by at least φ - θ (in
//      [0, π]), and the distance to a point at radius t and angle difference
//      δ, sqrt(d² + t² - 2dt cos δ), grows with δ, so the nearest point lies
//      on the boundary ray at angle θ: the distance to a segment. Hence
//      distance(c, K) > r means S, and so B ⊂ S, misses K.
//   5. For θ < π/2, a plane through the apex tangent to the cone separates
//      them: with e a unit vector orthogonal to w (toward c) and
//      n = cos θ e - sin θ w, every unit ray u of the cone has
//      n.u <= sin(ψ - θ) <= 0 (ψ <= θ <= π/2), so all of K has n.(x - a) <= 0;
//      B is rejected only if min over B of n.(x - a) > 0.
// None of these tests rejects on a guess: each is a proof of disjointness.
// The slack s = 1e-9 * (the scale of the coordinates and distances involved)
// covers rounding (each quantity is a few operations, error ~1e-15 relative).

namespace asos {
namespace {

constexpr double kSlackRelative = 1e-9;
// Angles that decide a sign of an infinite extent (a ray direction whose
// component is +1e-17 still reaches +inf) are widened by this much, far above
// the rounding of atan2 and cos.
constexpr double kAngleSlack = kThousandsOfUlps;
// The cosines of widened angles, computed by angle-sum formulas, are moved
// outward by this much, far above their rounding (a few 1e-16).
constexpr double kValueSlack = kFewUlps;

// t * u over the cone's distances, where t may be infinite and u zero.
double extremeProduct(double t, double u) { return u == 0.0 ? 0.0 : t * u; }

}  // namespace

ConeBoxTest::ConeBoxTest(const Cone& cone) : cone_(cone) {
    const double axisLength = glm::length(cone.axis);
    valid_ = std::isfinite(axisLength) && axisLength > 0.0 && !std::isnan(cone.halfAngle) &&
             !std::isnan(cone.tMin) && !std::isnan(cone.tMax) && std::isfinite(cone.apex.x) &&
             std::isfinite(cone.apex.y) && std::isfinite(cone.apex.z);
    if (!valid_) return;
    cone_.axis = cone.axis / axisLength;
    cone_.halfAngle = std::clamp(cone.halfAngle, 0.0, kPi);
    cone_.tMin = std::max(cone.tMin, 0.0);
    cos_ = std::cos(cone_.halfAngle);
    sin_ = std::sin(cone_.halfAngle);
    apexScale_ = maxNorm(cone_.apex);
    const Vec3& w = cone_.axis;
    // A unit vector orthogonal to w: the cross product with the coordinate
    // axis least aligned with w is well conditioned.
    const Vec3 least = std::abs(w.x) <= std::abs(w.y) && std::abs(w.x) <= std::abs(w.z)
                           ? Vec3(1, 0, 0)
                           : (std::abs(w.y) <= std::abs(w.z) ? Vec3(0, 1, 0) : Vec3(0, 0, 1));
    orthogonal_ = glm::normalize(glm::cross(w, least));
    // θ' = θ + kAngleSlack, by its cosine and sine (cos of the slack is 1 in
    // doubles, its sine the slack itself): no trigonometry per axis.
    const bool whole = cone_.halfAngle + kAngleSlack >= kPi;
    const double cosWide = cos_ - kAngleSlack * sin_;
    const double sinWide = sin_ + kAngleSlack * cos_;
    cosWide_ = whole ? -1.0 : std::max(-1.0, cosWide - kValueSlack);
    for (int i = 0; i < 3; ++i) {
        // α: the angle between the axis and coordinate axis i, cos α = w_i,
        // sin α = |w with w_i left out| (>= 0). The rays of the cone make
        // angles with e_i that fill [α - θ', α + θ'] clipped to [0, π], so u_i
        // lies between cos(min(π, α + θ')) and cos(max(0, α - θ')). Both are
        // the angle-sum formulas; which clip applies is the sign of
        // sin(α - θ') (α <= θ' iff it is <= 0, both angles in [0, π]) and of
        // sin(α + θ') (α + θ' >= π iff it is <= 0). Near a switch the formula
        // is continuous with the clipped value, so rounding on either side
        // costs a few ulps, which kValueSlack covers.
        const int j = (i + 1) % 3;
        const int k = (i + 2) % 3;
        const double cosA = w[i];
        const double sinA = std::hypot(w[j], w[k]);
        if (whole) {
            dirHi_[i] = 1.0;
            dirLo_[i] = -1.0;
            continue;
        }
        const bool nearClip = sinA * cosWide - cosA * sinWide <= 0.0;
        const bool farClip = sinA * cosWide + cosA * sinWide <= 0.0;
        dirHi_[i] = nearClip ? 1.0 : std::min(1.0, cosA * cosWide + sinA * sinWide + kValueSlack);
        dirLo_[i] = farClip ? -1.0 : std::max(-1.0, cosA * cosWide - sinA * sinWide - kValueSlack);
    }
    updateFarEnd();
}

void ConeBoxTest::setTMax(double tMax) {
    if (!valid_ || std::isnan(tMax)) return;
    cone_.tMax = tMax;
    updateFarEnd();
}

void ConeBoxTest::updateFarEnd() {
    const double tMin = cone_.tMin;
    const double tMax = cone_.tMax;
    empty_ = tMin > tMax;
    for (int i = 0; i < 3; ++i) {
        const double hi = dirHi_[i] >= 0.0 ? extremeProduct(tMax, dirHi_[i]) : tMin * dirHi_[i];
        const double lo = dirLo_[i] <= 0.0 ? extremeProduct(tMax, dirLo_[i]) : tMin * dirLo_[i];
        coneBounds_.lo[i] = cone_.apex[i] + lo;
        coneBounds_.hi[i] = cone_.apex[i] + hi;
    }
    axialHi_ = tMax;
    axialLo_ = cosWide_ >= 0.0 ? tMin * cosWide_ : extremeProduct(tMax, cosWide_);
}

bool ConeBoxTest::contains(const Vec3& point) const {
    const Vec3 v = point - cone_.apex;
    const double d = glm::length(v);
    return d >= cone_.tMin && d <= cone_.tMax && glm::dot(v, cone_.axis) >= d * cos_;
}

double ConeBoxTest::distanceTo(const Vec3& point) const {
    const Vec3 v = point - cone_.apex;
    const double p = glm::dot(v, cone_.axis);
    const double q = glm::length(v - p * cone_.axis);
    const double d = std::sqrt(p * p + q * q);
    if (p >= d * cos_) {
        // Within the angular range: the nearest point is on the point's own ray.
        return std::max({0.0, cone_.tMin - d, d - cone_.tMax});
    }
    // Outside it: the nearest point is on the boundary ray at angle θ in the
    // point's half-plane, at distance s along it (clamped to the t-range).
    const double s = p * cos_ + q * sin_;
    const double h = q * cos_ - p * sin_;
    const double along = s - std::clamp(s, cone_.tMin, cone_.tMax);
    return std::sqrt(h * h + along * along);
}

double ConeBoxTest::entryDistance(const Bounds3& box) const {
    if (box.empty()) return kInfinity;
    if (!valid_) return 0.0;
    if (empty_) return kInfinity;
    const double tScale = std::isfinite(cone_.tMax) ? cone_.tMax : cone_.tMin;
    const double slack =
        kSlackRelative * (apexScale_ + std::max(maxNorm(box.lo), maxNorm(box.hi)) + tScale) +
        kPositiveFloor;

    // 1. The cone's axis-aligned bounds.
    for (int i = 0; i < 3; ++i) {
        if (box.lo[i] > coneBounds_.hi[i] + slack || box.hi[i] < coneBounds_.lo[i] - slack)
            return kInfinity;
    }

    const Vec3& w = cone_.axis;
    const Vec3 halfExtent = 0.5 * (box.hi - box.lo);
    const Vec3 centre = box.center();
    const Vec3 v = centre - cone_.apex;

    // 2. The slab of the cone's axial extent.
    const double p = glm::dot(v, w);
    const double axialHalf = glm::dot(glm::abs(w), halfExtent);
    if (p - axialHalf > axialHi_ + slack || p + axialHalf < axialLo_ - slack) return kInfinity;

    // 3. The spherical shell tMin <= |x - apex| <= tMax (compared squared).
    const Vec3 nearest = glm::max(glm::max(box.lo - cone_.apex, Vec3(0.0)), cone_.apex - box.hi);
    const double nearestSquared = glm::dot(nearest, nearest);
    if (std::isfinite(cone_.tMax) && nearestSquared > (cone_.tMax + slack) * (cone_.tMax + slack))
        return kInfinity;
    if (cone_.tMin > slack) {
        const Vec3 farthest = glm::max(glm::abs(box.lo - cone_.apex), glm::abs(box.hi - cone_.apex));
        if (glm::dot(farthest, farthest) < (cone_.tMin - slack) * (cone_.tMin - slack)) return kInfinity;
    }

    // 4. The bounding sphere against the exact cone (as distanceTo, inlined
    // so that the pieces serve test 5 too).
    const double radius = glm::length(halfExtent);
    const double q = glm::length(glm::cross(v, w));  // distance of the centre from the axis line
    const double d = std::sqrt(p * p + q * q);
    if (p >= d * cos_) {
        // The centre is within the angular range: only the t-range can
        // separate, and no tangent plane can (the centre is on the cone's side).
        if (std::max({0.0, cone_.tMin - d, d - cone_.tMax}) > radius + slack) return kInfinity;
    } else {
        const double s = p * cos_ + q * sin_;
        const double h = q * cos_ - p * sin_;
        const double along = s - std::clamp(s, cone_.tMin, cone_.tMax);
        if (h * h + along * along > (radius + slack) * (radius + slack)) return kInfinity;

        // 5. A tangent plane through the apex, facing the box's centre. The
        // plane is valid for any unit e orthogonal to w, so where the centre
        // is too near the axis for its offset to give a reliable direction,
        // a fixed e orthogonal to w serves.
        if (cos_ > 0.0) {
            const Vec3 e = q > 1e-3 * d ? (v - p * w) / q : orthogonal_;
            const Vec3 n = cos_ * e - sin_ * w;
            const double lowest = glm::dot(n, v) - glm::dot(glm::abs(n), halfExtent);
            if (lowest > slack) return kInfinity;
        }
    }
    const double nearestDistance = std::sqrt(nearestSquared);
    return std::max(0.0, std::max(nearestDistance, cone_.tMin) - slack);
}

}  // namespace asos
