#pragma once
// Shadow rays from one origin against a capped cylinder or cone (an area
// light's point samples, docs/lights.md "Speed"): what does not depend on
// the direction is computed once per origin, and each ray solves the side's
// quadratic about the origin itself (no shift to the axis), a few dozen
// operations. The answer is Frustum::intersectAny's (Cylinder's test is the
// same solid's): a hit where the solid's entry or exit along the line lies
// in [tMin, tMax]. Rounding may place those points differently from the
// exact test's shifted solution, so decide() answers only where every
// comparison clears a margin far above both tests' rounding (1e-7 of the
// shape's scale, against errors of about 1e-11 once the near-tangent and
// near-degenerate cases are left out) and returns kUndecided otherwise: the
// caller then asks the exact test.
#include <algorithm>
#include <cmath>

#include "asos/geometry/vec.hpp"
#include "asos/shapes/frustum.hpp"
#include "asos/shapes/local_rays.hpp"

namespace asos {

class FrustumFromOrigin {
public:
    static constexpr int kUndecided = -1;

    // `origin` in the frustum's local frame. Only a capped, non-empty
    // frustum is decided here (usable()).
    FrustumFromOrigin(const Frustum& f, const Vec3& origin)
        : o_(origin),
          k_((f.r1() - f.r0()) / f.length()),
          length_(f.length()),
          usable_(f.capped() && !f.empty()) {
        rho_ = f.r0() + k_ * origin.z;
        c_ = origin.x * origin.x + origin.y * origin.y - rho_ * rho_;
        const double scale = std::abs(origin.x) + std::abs(origin.y) + std::abs(origin.z) + f.length() +
                             std::max(f.r0(), f.r1());
        margin2_ = kMargin * kMargin * scale * scale;
    }

    bool usable() const { return usable_; }

    // 1 for a hit, 0 for none, kUndecided near a boundary. `d` is the local
    // direction of any length; t counts along it.
    __attribute__((always_inline)) int decide(const Vec3& d, double tMin, double tMax) const {
        const double dd = d.x * d.x + d.y * d.y + d.z * d.z;
        // A length along t clears the margin when its square times |d|^2
        // exceeds the margin's (no division).
        const auto clear = [&](double t) { return t * t * dd > margin2_; };
        // Nearly across the axis (|d.z| <= kIllConditioned |d|): the slab's
        // bounds are ill-conditioned.
        if (!(d.z * d.z > kIllConditioned * kIllConditioned * dd)) return kUndecided;
        const double radial = d.x * d.x + d.y * d.y, axial = k_ * k_ * d.z * d.z;
        const double a = radial - axial;
        // Nearly along a generator of the side's cone: one root runs away.
        if (!(std::abs(a) > kIllConditioned * (radial + axial))) return kUndecided;
        const double b = o_.x * d.x + o_.y * d.y - k_ * d.z * rho_;
        const double disc = b * b - a * c_;
        // Nearly tangent to the side: the roots are ill-conditioned.
        if (!(std::abs(disc) > kIllConditioned * (b * b + std::abs(a * c_)))) return kUndecided;
        if (disc < 0.0 && a > 0.0) return 0;  // the line misses the side's cone
        const double inv = 1.0 / d.z;
        const double z0 = -o_.z * inv, z1 = (length_ - o_.z) * inv;
        const double slabLo = std::min(z0, z1), slabHi = std::max(z0, z1);
        double lo, hi;
        if (disc < 0.0) {
            lo = slabLo;  // wholly inside the double cone: the slab's part
            hi = slabHi;
        } else {
            const double q = -(b + std::copysign(std::sqrt(disc), b));
            const double r0 = q / a, r1 = c_ / q;
            const double ra = std::min(r0, r1), rb = std::max(r0, r1);
            if (a > 0.0) {
                lo = std::max(slabLo, ra);
                hi = std::min(slabHi, rb);
            } else {
                // Outside the roots: the slab holds one nappe's part.
                const double first = std::min(slabHi, ra) - slabLo, second = slabHi - std::max(slabLo, rb);
                const bool firstIn = first > 0.0 && clear(first), firstOut = first < 0.0 && clear(first);
                const bool secondIn = second > 0.0 && clear(second), secondOut = second < 0.0 && clear(second);
                if (firstIn && secondOut) {
                    lo = slabLo;
                    hi = std::min(slabHi, ra);
                } else if (secondIn && firstOut) {
                    lo = std::max(slabLo, rb);
                    hi = slabHi;
                } else if (firstOut && secondOut) {
                    return 0;
                } else {
                    return kUndecided;
                }
            }
        }
        if (!clear(hi - lo)) return kUndecided;
        if (hi < lo) return 0;  // the line misses the solid
        if (!clear(lo - tMin) || !clear(hi - tMin) || !clear(lo - tMax) || !clear(hi - tMax)) return kUndecided;
        return ((lo >= tMin && lo <= tMax) || (hi >= tMin && hi <= tMax)) ? 1 : 0;
    }

private:
    static constexpr double kMargin = 1e-7;
    // A ray is left to the exact test where a quantity is below this
    // fraction of its terms (the direction's part along the axis, the side's
    // leading coefficient, its discriminant): the slab's bounds or the roots
    // are ill-conditioned there. A modelling choice, which keeps the errors
    // far below kMargin elsewhere.
    static constexpr double kIllConditioned = 1e-3;

    Vec3 o_;
    double k_, length_;
    double rho_ = 0.0, c_ = 0.0;  // the radius at the origin's z; the side's C
    double margin2_ = 0.0;        // (the margin, 1e-7 of the shape's scale)^2
    bool usable_;
};

// withAnyTestFrom of a shape whose solid is `frustum` (Cylinder,
// TruncatedCone): user(test) with FrustumFromOrigin's test, asking the
// shape's own ray test where it leaves a ray undecided, or with the shape's
// own test alone where it cannot decide (an open or empty frustum).
template <class S, class User>
decltype(auto) frustumAnyTestFrom(const Frustum& frustum, const S& shape, const Vec3& origin, User&& user) {
    const auto exact = exactAnyTestFrom(shape, origin);
    const FrustumFromOrigin fast(frustum, origin);
    if (fast.usable()) {
        return user([&fast, &exact](const Vec3& dir, double tMin, double tMax) {
            const int answer = fast.decide(dir, tMin, tMax);
            return answer == FrustumFromOrigin::kUndecided ? exact(dir, tMin, tMax) : answer != 0;
        });
    }
    return user(exact);
}

}  // namespace asos
