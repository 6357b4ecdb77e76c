#include "asos/shapes/quadric.hpp"

#include <array>
#include <cmath>
#include <utility>

#include "asos/diag/format_number.hpp"
#include "asos/shapes/cone_geometry.hpp"
#include "asos/shapes/local_frame.hpp"

namespace asos {

using namespace conegeom;

namespace {

// The relative rounding allowed for f and its gradient at a point: far above
// the few ulps a quadratic form's sum of nine products loses, so that a
// proven sign is one f really has.
constexpr double kValueRounding = 1e-12;

// Cone pieces at most 2^kMaxSplits per classification.
constexpr int kMaxSplits = 6;

double frobenius(const Mat3& m) {
    double s = 0.0;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) s += m[c][r] * m[c][r];
    return std::sqrt(s);
}

// Whether the symmetric q is positive definite (Sylvester's criterion).
bool positiveDefinite(const Mat3& q) {
    const double m1 = q[0][0];
    const double m2 = q[0][0] * q[1][1] - q[0][1] * q[1][0];
    return m1 > 0.0 && m2 > 0.0 && glm::determinant(q) > 0.0;
}

}  // namespace

Quadric::Quadric(const Mat3& q, const Vec3& g, double j)
    : q_(q), g_(g), j_(j), qNorm_(frobenius(q)), gNorm_(glm::length(g)),
      sphere_{Vec3(0.0), kInfinity} {
    // An ellipsoid: Q definite (its sign does not change the surface). Its
    // centre c = -Q^-1 g / 2 and f(c) give the extents: along axis i,
    // sqrt(-f(c) (Q^-1)_ii).
    const double s = positiveDefinite(q) ? 1.0 : positiveDefinite(-q) ? -1.0 : 0.0;
    if (s == 0.0) return;
    const Mat3 inverse = glm::inverse(s * q);
    const Vec3 centre = -0.5 * (inverse * (s * g));
    const double lowest = s * value(centre);
    // A small margin for the rounding of the centre and the extents.
    const double depth = std::max(0.0, -lowest) * (1.0 + 1e-9);
    const Vec3 extent(std::sqrt(depth * inverse[0][0]), std::sqrt(depth * inverse[1][1]),
                      std::sqrt(depth * inverse[2][2]));
    const Vec3 padded = extent * (1.0 + 1e-9) + Vec3(1e-12 * (glm::length(centre) + glm::length(extent)));
    box_ = {centre - padded, centre + padded};
    sphere_ = {centre, glm::length(padded)};
}

Bounds3 Quadric::worldBounds(const Mat3& worldFromLocal, const Vec3& offset) const {
    if (!std::isfinite(sphere_.radius)) return {Vec3(-kInfinity), Vec3(kInfinity)};
    Bounds3 out;
    for (int corner = 0; corner < 8; ++corner) {
        const Vec3 p((corner & 1) ? box_.hi.x : box_.lo.x, (corner & 2) ? box_.hi.y : box_.lo.y,
                     (corner & 4) ? box_.hi.z : box_.lo.z);
        out.extend(worldFromLocal * p + offset);
    }
    return out;
}

std::optional<LocalHit> Quadric::intersect(const Ray& ray, double tMin, double tMax) const {
    // f(o + t d) = a t^2 + b t + c.
    const double a = glm::dot(ray.dir, q_ * ray.dir);
    const double b = glm::dot(gradient(ray.origin), ray.dir);
    const double c = value(ray.origin);
    std::array<double, 2> roots{kInfinity, kInfinity};
    if (a == 0.0) {
        if (b == 0.0) return std::nullopt;
        roots[0] = -c / b;
    } else {
        const double disc = b * b - 4.0 * a * c;
        if (disc < 0.0) return std::nullopt;
        const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
        roots[0] = q / a;
        roots[1] = q != 0.0 ? c / q : roots[0];
        if (roots[1] < roots[0]) std::swap(roots[0], roots[1]);
    }
    for (const double t : roots) {
        if (!(t >= tMin && t <= tMax)) continue;
        const Vec3 p = ray.at(t);
        const Vec3 n = gradient(p);
        return LocalHit{t, p, n == Vec3(0.0) ? Vec3(0.0, 1.0, 0.0) : n};
    }
    return std::nullopt;
}

double Quadric::valueSlack(double reach) const {
    return kValueRounding * (3.0 * qNorm_ * reach * reach + gNorm_ * reach + std::abs(j_));
}

// f(c + u) = f(c) + grad f(c).u + u.Q u, so over |u| <= r it strays from
// f(c) by at most |grad f(c)| r + |Q| r^2.
int Quadric::signOver(const Vec3& centre, double radius) const {
    const double f = value(centre);
    const double spread = glm::length(gradient(centre)) * radius + qNorm_ * radius * radius +
                          valueSlack(glm::length(centre) + radius);
    return f > spread ? 1 : f < -spread ? -1 : 0;
}

// grad f(c + u) = grad f(c) + 2 Q u.
bool Quadric::regularOver(const Vec3& centre, double radius) const {
    const double slack = kValueRounding * (2.0 * qNorm_ * (glm::length(centre) + radius) + gNorm_);
    return glm::length(gradient(centre)) > 2.0 * qNorm_ * radius + slack;
}

ConeClass Quadric::classify(const LocalCone& cone) const {
    if (cone.rangeEmpty()) return missClass();
    // A cone of half-angle 90 degrees or more: no pieces to bound.
    if (!(cone.cosHalf > 0.0)) return marginalClass(cone, cone.tMin, cone.tMax);
    const double lo = std::max(0.0, cone.tMinOuter);
    const double chord = std::sqrt(2.0 * (1.0 - cone.cosHalf));  // |d - axis| for any ray's d

    // An unbounded range: beyond some T every ray keeps the sign of d.Q d
    // when that sign is the same for every ray's d (s f >= qm t^2 + lm t + fm).
    double end = cone.tMaxOuter;
    int farSign = 0;
    if (!std::isfinite(end)) {
        const Vec3 qAxis = q_ * cone.axis;
        const double qa = glm::dot(cone.axis, qAxis);
        const double qSlack = 2.0 * glm::length(qAxis) * chord + qNorm_ * chord * chord +
                              kValueRounding * qNorm_;
        const double reach = glm::length(cone.apex);
        if (std::abs(qa) > qSlack) {
            farSign = qa > 0.0 ? 1 : -1;
            const double qm = std::abs(qa) - qSlack;
            const Vec3 grad = gradient(cone.apex);
            const double lm = farSign * glm::dot(grad, cone.axis) - glm::length(grad) * chord -
                              kValueRounding * (2.0 * qNorm_ * reach + gNorm_);
            const double fm = farSign * value(cone.apex) - valueSlack(reach);
            const double disc = lm * lm - 4.0 * qm * fm;
            const double far = disc > 0.0 ? (-lm + std::sqrt(disc)) / (2.0 * qm) : 0.0;
            end = std::max(lo, far * (1.0 + 1e-9) + 1e-9);
        } else {
            // No sign far away: the pieces up to a few times the apex's reach
            // bound the first hits from below only.
            end = 2.0 * lo + 4.0 * (reach + 1.0);
        }
    }

    // Pieces of [lo, end] in order, split in halves until f's sign over each
    // is known (or kMaxSplits deep). A piece [ta, tb] of every ray lies in the
    // ball about the axis point at m = cosHalf (ta + tb) / 2 of radius the
    // largest distance of its ends' rims.
    struct Piece {
        double ta, tb;
        int sign;
        bool regular;
    };
    std::array<Piece, (1 << kMaxSplits)> pieces{};
    int count = 0;
    struct Span {
        double ta, tb;
        int depth;
    };
    std::array<Span, 2 * kMaxSplits + 2> stack{};
    int top = 0;
    stack[top++] = {lo, end, 0};
    while (top > 0) {
        const Span s = stack[--top];
        const double m = 0.5 * (s.ta + s.tb) * cone.cosHalf;
        auto rim = [&](double t) { return t * t + m * m - 2.0 * t * m * cone.cosHalf; };
        const double radius = std::sqrt(std::max(0.0, std::max(rim(s.ta), rim(s.tb)))) * (1.0 + 1e-12) + cone.absTol;
        const Vec3 centre = cone.apex + m * cone.axis;
        const int sign = signOver(centre, radius);
        if (sign == 0 && s.depth < kMaxSplits) {
            const double mid = 0.5 * (s.ta + s.tb);
            stack[top++] = {mid, s.tb, s.depth + 1};
            stack[top++] = {s.ta, mid, s.depth + 1};
            continue;
        }
        pieces[count++] = {s.ta, s.tb, sign, regularOver(centre, radius)};
    }

    const int first = pieces[0].sign;
    if (first == 0) return marginalClass(cone, cone.tMin, cone.tMax);
    int i = 0;
    while (i < count && pieces[i].sign == first) ++i;
    if (i == count) {
        // One sign over [lo, end]: no hit there; none beyond either where
        // the range ends there or f keeps that sign past it.
        if (std::isfinite(cone.tMaxOuter) || farSign == first) return missClass();
        return marginalClass(cone, end, cone.tMax);
    }
    const double tNear = pieces[i].ta;
    // Every ray crosses the surface before the first piece of the other
    // sign; the first hits lie in the pieces before it, where f's sign is
    // not known. Where the gradient cannot vanish there, the surface is
    // smooth over them: no edge, no crease.
    bool regular = true;
    for (int k = i; k < count; ++k) {
        if (pieces[k].sign == -first) {
            const double tFar = pieces[k].ta;
            if (regular && cone.surelyWithin(tNear, tFar)) return fullClass(tNear, tFar);
            return marginalClass(cone, tNear, tFar);
        }
        if (pieces[k].sign == 0) regular = regular && pieces[k].regular;
    }
    return marginalClass(cone, tNear, cone.tMax);
}

std::vector<ShapeIssue> validate(const QuadricShape& record) {
    IssueList issues;
    const bool finite = issues.finite(0, record.squares, "the quadric's <A, B, C>") &
                        issues.finite(1, record.mixed, "the quadric's <D, E, F>") &
                        issues.finite(2, record.linear, "the quadric's <G, H, I>");
    if (!std::isfinite(record.constant))
        issues.add(3, "the quadric's constant J must be finite, not " + formatNumber(record.constant));
    else if (finite && record.squares == Vec3(0.0) && record.mixed == Vec3(0.0) && record.linear == Vec3(0.0))
        issues.add(0, "a quadric without a term in x, y or z has no surface");
    return issues.take();
}

Placed<Quadric> place(const QuadricShape& record, const Transform& worldFromObject) {
    const Vec3& s = record.squares;
    const Vec3& m = record.mixed;  // the xy, xz and yz terms, each split over two entries
    const Mat3 q(s.x, 0.5 * m.x, 0.5 * m.y,  //
                 0.5 * m.x, s.y, 0.5 * m.z,  //
                 0.5 * m.y, 0.5 * m.z, s.z);
    return {Quadric(q, record.linear, record.constant), LocalFrame::make(worldFromObject, Mat3(1.0), Vec3(0.0)),
            Quadric::kName};
}

}  // namespace asos
