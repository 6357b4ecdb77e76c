#include "asos/shapes/primitive.hpp"

#include <algorithm>
#include <cmath>

namespace asos {

namespace {

double l1(const Vec3& v) { return std::abs(v.x) + std::abs(v.y) + std::abs(v.z); }

// Rounding can move a computed bound by a few ulps; pad so the box stays
// conservative for the BVH.
Bounds3 padded(Bounds3 b) {
    if (b.empty()) return b;
    const Vec3 pad = 1e-12 * (glm::abs(b.lo) + glm::abs(b.hi) + (b.hi - b.lo));
    return {b.lo - pad, b.hi + pad};
}

}  // namespace

Primitive::Primitive(LocalShape shape, LocalFrame frame, const char* name)
    : shape_(std::move(shape)), frame_(frame), name_(name) {
    localSphere_ = visit([](const auto& s) { return s.boundingSphere(); });
    worldBounds_ = padded(
        visit([&](const auto& s) { return s.worldBounds(frame_.worldFromLocal, frame_.worldOffset); }));
    sphereTolerance_ = l1(localSphere_.center) +
                       (std::isfinite(localSphere_.radius) ? localSphere_.radius : 0.0);
}

bool Primitive::bounded() const { return std::isfinite(localSphere_.radius); }

Bounds3 Primitive::worldBounds() const { return worldBounds_; }

std::optional<SurfaceHit> Primitive::intersect(const Ray& worldRay, double tMin,
                                               double tMax) const {
    const std::optional<LocalHit> hit = intersectLocal(worldRay, tMin, tMax);
    if (!hit) return std::nullopt;
    return surfaceHit(worldRay, *hit);
}

SurfaceHit Primitive::surfaceHit(const Ray& worldRay, const LocalHit& hit) const {
    SurfaceHit out;
    out.t = hit.t;
    out.position = worldRay.at(hit.t);
    out.normal = frame_.normalToWorld(hit.normal);
    out.objectPoint = frame_.pointToObject(hit.point);
    return out;
}

bool Primitive::intersectAny(const Ray& worldRay, double tMin, double tMax) const {
    const Ray ray = frame_.rayToLocal(worldRay);
    return visit([&](const auto& s) { return s.intersectAny(ray, tMin, tMax); });
}

ConeClass Primitive::classify(const Cone& worldCone) const {
    return classify(PreparedCone(worldCone));
}

ConeClass Primitive::classify(const PreparedCone& cone) const {
    if (!cone.valid) return {Coverage::Marginal, 0.0, kInfinity, false};
    if (cone.tMin > cone.tMax) return {};
    if (frame_.kind == LocalFrame::Kind::General) return classifyGeneral(cone);
    LocalCone local;
    double worldPerLocal = 1.0;
    if (frame_.kind == LocalFrame::Kind::Translate) {
        local.apex = cone.apex + frame_.localOffset;
        local.axis = cone.axis;
    } else {
        local.apex = frame_.localFromWorld * cone.apex + frame_.localOffset;
        // localFromWorld is a rotation over worldPerLocal: the image of a unit
        // axis is unit after the scale.
        worldPerLocal = frame_.worldPerLocal;
        local.axis = (frame_.localFromWorld * cone.axis) * worldPerLocal;
    }
    local.cosHalf = cone.cosHalf;
    local.sinHalf = cone.sinHalf;
    const double absTol = 1e-11 * (l1(local.apex) + sphereTolerance_);
    const double localPerWorld = 1.0 / worldPerLocal;
    local.setRange(cone.tMin * localPerWorld, cone.tMax * localPerWorld, absTol);
    ConeClass out = visit([&](const auto& s) { return s.classify(local); });
    if (out.coverage == Coverage::Miss) return out;
    const double slack = absTol * worldPerLocal;
    out.tNear = std::max(cone.tMin,
                         out.tNear * worldPerLocal * (1.0 - kConeDistanceTolerance) - slack);
    out.tFar = std::min(cone.tMax,
                        out.tFar * worldPerLocal * (1.0 + kConeDistanceTolerance) + slack);
    return out;
}

// Under a non-uniform scale or a shear the cone becomes elliptic in the local
// frame. It is bounded there by a circular cone around the image of its axis,
// and since t is no longer a local distance, each world ray's local range is
// [tMin L, tMax L] with L = |A d| between Lmin and Lmax: the shape classifies
// the union of those ranges, and a Full answer stands only if its depth bounds
// fall in every ray's own range.
ConeClass Primitive::classifyGeneral(const PreparedCone& cone) const {
    const Mat3& a = frame_.localFromWorld;
    const Vec3 aAxis = a * cone.axis;
    const double la = glm::length(aAxis);
    const Vec3 axis = aAxis / la;
    const Mat3 basis = frameAroundAxis(cone.axis);
    const Vec3 au = a * basis[0], av = a * basis[1];
    const double pu = glm::dot(au, axis), pv = glm::dot(av, axis);
    const double tau = std::sqrt(pu * pu + pv * pv);
    const Vec3 qu = au - pu * axis, qv = av - pv * axis;
    const double g11 = glm::dot(qu, qu), g22 = glm::dot(qv, qv), g12 = glm::dot(qu, qv);
    const double half = 0.5 * (g11 - g22);
    const double sigmaPerp = std::sqrt(0.5 * (g11 + g22) + std::sqrt(half * half + g12 * g12));
    const double c = cone.cosHalf, s = cone.sinHalf;

    LocalCone local;
    local.apex = a * cone.apex + frame_.localOffset;
    local.axis = axis;
    // A direction at angle phi <= theta from the axis maps to one whose
    // tangent from the new axis is at most tan(phi) sigmaPerp / (la - tan(phi) tau).
    local.cosHalf = -1.0;
    local.sinHalf = 0.0;
    if (c > 0.0) {
        const double t = s / c;
        const double den = la - t * tau;
        if (den > 0.0) {
            const double tl = t * sigmaPerp / den * (1.0 + 1e-12) + 1e-300;
            local.cosHalf = 1.0 / std::sqrt(1.0 + tl * tl);
            local.sinHalf = tl * local.cosHalf;
        }
    }
    // Bounds on L = |A d| over the cone: |A(d - axis)| <= 2 sin(theta/2) sigmaMax.
    const double chord = c > -1.0 ? s / std::sqrt(0.5 * (1.0 + c)) : 2.0;
    double lMin = std::max(frame_.sigmaMin, la - chord * frame_.sigmaMax);
    if (c > 0.0) lMin = std::max(lMin, c * la - s * tau);
    const double lMax = std::min(frame_.sigmaMax, la + chord * frame_.sigmaMax);
    const double absTol = 1e-11 * (l1(local.apex) + sphereTolerance_);
    local.setRange(cone.tMin * lMin, cone.tMax * lMax, absTol);

    ConeClass out = visit([&](const auto& s) { return s.classify(local); });
    if (out.coverage == Coverage::Miss) return out;
    const double tolNear = out.tNear * kConeDistanceTolerance + absTol;
    const double tolFar = out.tFar * kConeDistanceTolerance + absTol;
    // Every ray's first hit in its own range is the shape's first hit in the
    // union only if that lies past the latest start of a ray's own range.
    const bool firstHitKept = out.tNear - tolNear >= cone.tMin * lMax;
    if (out.coverage == Coverage::Full) {
        const bool inEveryRange =
            firstHitKept && (!std::isfinite(cone.tMax) || out.tFar + tolFar <= cone.tMax * lMin);
        if (!inEveryRange) {
            out.coverage = Coverage::Marginal;
            out.singleEdge = false;
        }
    }
    double farBound = kInfinity;
    if (firstHitKept) farBound = (out.tFar + tolFar) / lMin;
    else if (bounded())
        farBound = (glm::length(local.apex - localSphere_.center) + localSphere_.radius) / lMin;
    out.tNear = std::max(cone.tMin, (out.tNear - tolNear) / lMax);
    out.tFar = std::min(cone.tMax, farBound);
    return out;
}

std::optional<TranslatedSphere> Primitive::translatedSphere() const {
    const Sphere* sphere = std::get_if<Sphere>(&shape_);
    if (!sphere || frame_.kind != LocalFrame::Kind::Translate) return std::nullopt;
    return TranslatedSphere{frame_.localOffset, sphere->radius()};
}

const char* Primitive::kindName() const { return name_; }

}  // namespace asos
