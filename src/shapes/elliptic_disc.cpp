#include "asos/shapes/elliptic_disc.hpp"

#include <algorithm>
#include <cmath>

#include "asos/geometry/margins.hpp"
#include "asos/shapes/cone_geometry.hpp"

namespace asos {

using namespace conegeom;

namespace {

// The footprint ellipse f stretched by diag(dx, dy): its centre maps, its
// matrix M = a^2 u u^T + b^2 v v^T becomes D M D, whose axes come from a
// 2x2 eigen-decomposition. `pad` bounds how far the computed ellipse may lie
// from the exact image (the decomposition's rounding: a distance of at most
// sqrt(|error of D M D|), a few ulps of its larger eigenvalue).
struct Stretched {
    Footprint f;
    double pad;
};

Stretched stretch(const Footprint& f, double dx, double dy) {
    Stretched out;
    out.f = f;
    out.f.center = Vec2(f.center.x * dx, f.center.y * dy);
    const Vec2 u = f.major;
    const double a2 = f.a * f.a, b2 = f.b * f.b;
    const double m00 = (a2 * u.x * u.x + b2 * u.y * u.y) * (dx * dx);
    const double m11 = (a2 * u.y * u.y + b2 * u.x * u.x) * (dy * dy);
    const double m01 = (a2 - b2) * u.x * u.y * (dx * dy);
    const double mean = 0.5 * (m00 + m11), diff = 0.5 * (m00 - m11);
    const double spread = std::sqrt(diff * diff + m01 * m01);
    const double l1 = mean + spread;
    // The smaller eigenvalue from the determinant, (dx dy a b)^2, without
    // the cancellation of mean - spread.
    const double det = dx * dy * f.a * f.b;
    const double l2 = l1 > 0.0 ? det * det / l1 : 0.0;
    Vec2 major = diff >= 0.0 ? Vec2(diff + spread, m01) : Vec2(m01, spread - diff);
    const double len = glm::length(major);
    out.f.major = len > 0.0 ? major / len : Vec2(1.0, 0.0);
    out.f.a = std::sqrt(l1);
    out.f.b = std::sqrt(l2);
    out.pad = 1e-7 * out.f.a;  // the root of a few ulps (sqrt(kFewUlps) = 3.2e-8), tripled
    return out;
}

}  // namespace

EllipticDisc::EllipticDisc(double ax, double ay, double holeRatio)
    : ax_(ax), ay_(ay), dx_(1.0 / ax), dy_(1.0 / ay), hole_(holeRatio), reach_(std::max(ax, ay)) {
    // Bounds on the stretch, past the rounding of its one division.
    dMax_ = std::max(dx_, dy_) * (1.0 + kFewUlps);
    dMin_ = std::min(dx_, dy_) * (1.0 - kFewUlps);
}

Bounds3 EllipticDisc::worldBounds(const Mat3& m, const Vec3& offset) const {
    // The ellipse spanned by ax u and ay v (columns 0 and 1) reaches
    // sqrt((ax u_i)^2 + (ay v_i)^2) along world axis i.
    Vec3 half;
    for (int i = 0; i < 3; ++i) half[i] = length2d(ax_ * m[0][i], ay_ * m[1][i]);
    return {offset - half, offset + half};
}

ConeClass EllipticDisc::classify(const LocalCone& cone) const {
    return classifyWith(cone, [] {}, LocalFinish{cone});
}

ConeClass EllipticDisc::classifyRanging(LocalCone& cone, double t0, double t1,
                                        const RigidBounds& back) const {
    return classifyWith(cone, [&] { cone.setRange(t0, t1, cone.absTol); }, back);
}

template <class SetRange, class Finish>
ConeClass EllipticDisc::classifyWith(const LocalCone& cone, SetRange&& setRange, Finish&& finish) const {
    // The disc's fast path (Disc::classifyWith) in the stretched plane,
    // where the outer circle is the unit one.
    const ZPlaneApproach z = zPlaneApproach(cone);
    const auto f = annulusFastPath(cone, z, 1.0, hole_, {dx_, dy_, dMax_, dMin_});
    // As the disc's: no local range for these answers, set past them.
    if (f.settled) return rangedClass(finish, f.miss, f.full, f.tNear, f.tFar);
    if (!z.crosses && turnedAwayFromPlane(cone, z.h, z.g2)) return missClass();
    setRange();
    // A circle near q: the stretched footprint itself against both circles.
    if (z.crosses)
        if (const auto out = bandClass(cone, z.depth, z.an, z.k, f.tNear, f.tFar)) return finish(*out);
    return finish(classifyExactly(cone));
}

std::optional<ConeClass> EllipticDisc::bandClass(const LocalCone& cone, double depth, double an,
                                                 double k, double tNear, double tFar) const {
    // The footprint is {m + y : y^T M^-1 y <= 1}, M = e^2 (k I + a a^T) (e =
    // depth s / k, a the axis' (x, y); FootprintQuadric); stretched by D, its
    // centre is m' = D m and its matrix D M D = e^2 (k D^2 + b b^T), b = D a.
    // With n = m' / d (d = |m'|) and n' across it, every point x of it has
    // n.x in [d - S, d + S] and |n'.x| <= S', S and S' its supports along n
    // and n'; m' and m' - (D M D) n / S (where n.x = d - S) are in it, and
    // the point where n.x = d + S is at least that far from the origin.
    const Vec3& p = cone.apex;
    const Vec2 a(cone.axis.x, cone.axis.y);
    const double t = depth * an / k, e = depth * cone.sinHalf / k, e2 = e * e;
    const Vec2 m((p.x + t * a.x) * dx_, (p.y + t * a.y) * dy_);
    const Vec2 b(a.x * dx_, a.y * dy_);
    const double d2 = glm::dot(m, m);
    if (!(d2 > 0.0)) return std::nullopt;
    const auto apply = [&](const Vec2& v) {  // (D M D) v
        return e2 * (k * Vec2(v.x * dx_ * dx_, v.y * dy_ * dy_) + glm::dot(b, v) * b);
    };
    const Vec2 mm = apply(m), across(-m.y, m.x);
    const double d = std::sqrt(d2);
    const double sd = std::sqrt(glm::dot(m, mm));                    // S d
    const double acrossD = std::sqrt(std::max(0.0, glm::dot(across, apply(across))));  // S' d
    const double support = sd / d, side = acrossD / d;
    const Vec2 nearPoint = m - mm / support / d;
    // Rounding: the centre's and the supports' few ulps, generously (1e-10,
    // 10^5 times kFewUlps).
    const double tol = cone.absTol * dMax_ + 1e-10 * (d + support + side);
    const double low = d - support, high = d + support;
    const double reach2 = high * high + side * side;
    const double near2 = glm::dot(nearPoint, nearPoint);
    const auto relation = [&](double rho) {
        const double outer = rho + tol, inner = rho - tol;
        if (low > outer) return CircleRelation::EllipseOutside;
        if (inner > 0.0 && reach2 < inner * inner) return CircleRelation::EllipseInside;
        const bool pointIn = inner > 0.0 && (d < inner || near2 < inner * inner);
        return high > outer && pointIn ? CircleRelation::Crossing : CircleRelation::Unsure;
    };
    const CircleRelation outer = relation(1.0);
    // The hole matters only to an ellipse inside the outer circle.
    const CircleRelation inner = hole_ > 0.0 && outer == CircleRelation::EllipseInside
                                     ? relation(hole_)
                                     : CircleRelation::EllipseOutside;
    if ((outer == CircleRelation::Unsure) |
        ((outer == CircleRelation::EllipseInside) & (inner == CircleRelation::Unsure)))
        return std::nullopt;
    const bool miss = (outer == CircleRelation::EllipseOutside) |
                      ((outer == CircleRelation::EllipseInside) & (inner == CircleRelation::EllipseInside));
    const bool full = (outer == CircleRelation::EllipseInside) & (inner == CircleRelation::EllipseOutside);
    return rangedClass(cone, miss, full, tNear, tFar);
}

ConeClass EllipticDisc::classifyExactly(const LocalCone& cone) const {
    const Vec3& p = cone.apex;
    const double h = -p.z;
    // Depths of the annulus' points from the apex (within its bounding circle).
    const double rho = length2d(p.x, p.y);
    const double dNear = length2d(h, std::max(0.0, rho - reach_));
    const double dFar = length2d(h, rho + reach_);
    const PlaneBand band = exactPlaneBand(cone, reach_, dNear, dFar);
    if (band.answer) return *band.answer;
    const double tLo = band.tLo, tHi = band.tHi;

    const Footprint f = footprintOnZPlane(cone, 0.0);
    if (!f.bounded) return marginalClass(cone, tLo, tHi);
    // In the stretched plane the annulus is hole <= |x| <= 1.
    const Stretched g = stretch(f, dx_, dy_);
    const double tol = cone.absTol * dMax_ + g.pad;
    const DiscRelation outer = footprintVsDisc(g.f, Vec2(0.0), 1.0, tol);
    if (outer == DiscRelation::EllipseOutside) return missClass();
    if (outer == DiscRelation::Crossing) return marginalClass(cone, tLo, tHi);
    if (hole_ > 0.0) {
        const DiscRelation inner = footprintVsDisc(g.f, Vec2(0.0), hole_, tol);
        if (inner == DiscRelation::EllipseInside) return missClass();
        if (inner == DiscRelation::Crossing) return marginalClass(cone, tLo, tHi);
    }
    if (cone.surelyWithin(f.tNear, f.tFar)) return fullClass(f.tNear, f.tFar);
    return marginalClass(cone, f.tNear, f.tFar);
}

}  // namespace asos
