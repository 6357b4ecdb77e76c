#include "asos/shapes/primitive.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "asos/geometry/margins.hpp"
#include "asos/shapes/csg_clip.hpp"

namespace asos {

namespace {

// Rounding can move a computed bound by a few ulps; pad so the box stays
// conservative for the BVH.
Bounds3 padded(Bounds3 b) {
    if (b.empty()) return b;
    const Vec3 pad = kThousandsOfUlps * (glm::abs(b.lo) + glm::abs(b.hi) + (b.hi - b.lo));
    return {b.lo - pad, b.hi + pad};
}

// The depths within which every ray of the cone that meets the box leaves
// it: a ray leaves a box through the nearest of its three far slab planes,
// at (face - a) / v along a local axis where its local direction has the
// component v (the face ahead of v's sign), and each component's range over
// the cone is the row's projection's. Empty (lo > hi) where that is not
// bounded (a cone over a half-space and more).
// The range over a cone's unit directions of their local component along
// axis i (the row of localFromWorld), padded.
std::pair<double, double> localSpeeds(const LocalFrame& frame, const PreparedCone& cone, int i) {
    const Vec3 row = frame.kind == LocalFrame::Kind::Translate
                         ? Vec3(i == 0, i == 1, i == 2)
                         : Vec3(frame.localFromWorld[0][i], frame.localFromWorld[1][i], frame.localFromWorld[2][i]);
    const double len = glm::length(row), along = glm::dot(row, cone.axis);
    const double across = glm::length(glm::cross(row, cone.axis));
    const double pad = kThousandsOfUlps * len;
    const double hiV = along >= len * cone.cosHalf ? len : along * cone.cosHalf + across * cone.sinHalf + pad;
    const double loV = along <= -len * cone.cosHalf ? -len : along * cone.cosHalf - across * cone.sinHalf - pad;
    return {loV, hiV};
}

std::pair<double, double> boxExits(const Box& box, const LocalFrame& frame, const PreparedCone& cone) {
    if (!(cone.cosHalf > 0.0)) return {kInfinity, -kInfinity};
    const Vec3 a = frame.pointToLocal(cone.apex);
    double lower = kInfinity, upper = kInfinity;
    for (int i = 0; i < 3; ++i) {
        const auto [loV, hiV] = localSpeeds(frame, cone, i);
        // A ray that meets the box lies within the slab behind the face it
        // heads for.
        const double toHi = std::max(box.hi()[i] - a[i], 0.0), toLo = std::max(a[i] - box.lo()[i], 0.0);
        if (hiV > 0.0) lower = std::min(lower, toHi / hiV);
        if (loV < 0.0) lower = std::min(lower, toLo / -loV);
        if (loV > 0.0) upper = std::min(upper, toHi / loV);
        if (hiV < 0.0) upper = std::min(upper, toLo / -hiV);
    }
    const double tol = kPositionTolerance * (1.0 + l1Norm(cone.apex) + l1Norm(box.lo()) + l1Norm(box.hi()));
    return {lower * (1.0 - kThousandsOfUlps) - tol, upper * (1.0 + kThousandsOfUlps) + tol};
}

}  // namespace

Primitive::Primitive(LocalShape shape, LocalFrame frame, const char* name)
    : shape_(std::move(shape)), frame_(frame), name_(name) {
    localSphere_ = visit([](const auto& s) { return s.boundingSphere(); });
    worldBounds_ = padded(
        visit([&](const auto& s) { return s.worldBounds(frame_.worldFromLocal, frame_.worldOffset); }));
    sphereTolerance_ = l1Norm(localSphere_.center) +
                       (std::isfinite(localSphere_.radius) ? localSphere_.radius : 0.0);
    bounded_ = std::isfinite(localSphere_.radius);
}

Primitive Primitive::makeCsgLeaf(const CsgShape& shape, const Transform& worldFromObject,
                                 CsgSolidCache& solids) {
    // The tree is checked once for all its leaves (makeCsgSolid), each leaf's
    // index here.
    if (!shape.tree || shape.leaf >= shape.tree->leaves.size())
        throw std::invalid_argument(std::move(validate(shape).front().message));
    std::shared_ptr<const CsgSolid> solid = solids.solidFor(shape, worldFromObject);
    const CsgTree::Leaf& leaf = shape.tree->leaves[shape.leaf];
    Primitive p = make(leaf.shape, csgLeafTransform(worldFromObject, leaf.worldFromObject));
    auto clip = std::make_shared<CsgClip>(makeCsgClip(shape, std::move(solid)));
    clip->flat = p.visit([](const auto& s) { return s.holdingPlanes(Vec3(0.0)).flat; });
    // Its box: the leaf's, within every subtree a kept hit must be inside
    // (an intersection's members, a difference's first); left as the
    // leaf's where that leaves nothing (no hit is kept then anyway).
    const Bounds3 kept = padded(clip->keptBounds);
    const Bounds3 own = p.bounded_ ? p.worldBounds_ : Bounds3{Vec3(-kInfinity), Vec3(kInfinity)};
    const Bounds3 both{glm::max(own.lo, kept.lo), glm::min(own.hi, kept.hi)};
    if (!both.empty()) {
        p.worldBounds_ = both;
        p.bounded_ = std::isfinite(both.lo.x) && std::isfinite(both.lo.y) && std::isfinite(both.lo.z) &&
                     std::isfinite(both.hi.x) && std::isfinite(both.hi.y) && std::isfinite(both.hi.z);
    }
    p.clip_ = std::move(clip);
    return p;
}

std::optional<LocalHit> Primitive::clippedHit(const Ray& worldRay, double tMin, double tMax) const {
    const Crossings all = crossings(worldRay, tMin, tMax);
    for (int i = 0; i < all.count; ++i)
        if (clip_->keeps(worldRay.at(all.hits[i].t))) return all.hits[i];
    return std::nullopt;
}

bool Primitive::clippedAny(const Ray& worldRay, double tMin, double tMax) const {
    return clippedHit(worldRay, tMin, tMax).has_value();
}

Crossings Primitive::crossings(const Ray& worldRay, double tMin, double tMax) const {
    const Ray ray = frame_.rayToLocal(worldRay);
    Crossings out;
    double from = tMin;
    while (out.count < Crossings::kMax) {
        const std::optional<LocalHit> hit = visit([&](const auto& s) { return s.intersect(ray, from, tMax); });
        if (!hit) break;
        out.hits[static_cast<std::size_t>(out.count++)] = *hit;
        from = std::nextafter(hit->t, kInfinity);
    }
    return out;
}

bool Primitive::inside(const Vec3& worldPoint) const {
    const Vec3 local = frame_.pointToLocal(worldPoint);
    return visit([&](const auto& s) { return s.inside(local); });
}

bool Primitive::bounded() const { return bounded_; }

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
    out.part = hit.part;
    return out;
}

bool Primitive::intersectAny(const Ray& worldRay, double tMin, double tMax) const {
    if (clip_) [[unlikely]]
        return clippedAny(worldRay, tMin, tMax);
    const Ray ray = frame_.rayToLocal(worldRay);
    return visit([&](const auto& s) { return s.intersectAny(ray, tMin, tMax); });
}

bool Primitive::intersectAnyFrom(const Vec3& localOrigin, const Vec3& worldDir, double tMin, double tMax) const {
    if (clip_) [[unlikely]]
        return clippedAny(Ray{frame_.pointToWorld(localOrigin), worldDir}, tMin, tMax);
    const Ray ray{localOrigin, frame_.kind == LocalFrame::Kind::Translate ? worldDir : frame_.localFromWorld * worldDir};
    return visit([&](const auto& s) { return s.intersectAny(ray, tMin, tMax); });
}

ConeClass Primitive::classify(const Cone& worldCone) const {
    return classify(PreparedCone(worldCone));
}

ConeClass Primitive::classify(const PreparedCone& cone) const {
    if (!clip_) [[likely]]
        return classifyOwn(cone);
    // From within a convex leaf's solid: its exits alone, which may show a
    // Miss; otherwise both answers hold, the narrower depths with them.
    const std::optional<ConeClass> exits = exitsClass(cone);
    if (exits && exits->coverage == Coverage::Miss) return *exits;
    ConeClass k = clippedClass(cone);
    if (!exits || k.coverage != Coverage::Marginal) return k;
    k.tNear = std::max(k.tNear, exits->tNear);
    k.tFar = std::min(k.tFar, exits->tFar);
    if (!(k.tNear <= k.tFar)) return {};
    return k;
}

ConeClass Primitive::clippedClass(const PreparedCone& cone) const {
    const ConeClass own = classifyOwn(cone);
    if (own.coverage == Coverage::Miss) return own;
    // Every crossing of the leaf in the cone: its first within own's
    // depths; a shape other than a torus, a poly or an extrusion meets a line at most twice, so a
    // curved leaf's second lies within them too, or among the nearest
    // crossings past own.tFar (a flat leaf has none).
    ConeClass second;
    if (std::holds_alternative<Torus>(shape_) || std::holds_alternative<Extrusion>(shape_) ||
        std::holds_alternative<Poly>(shape_)) {
        // Up to four crossings (a poly: its order; an extrusion: any number): every one past own's lies in the world box.
        const Vec3 far = glm::max(glm::abs(worldBounds_.lo - cone.apex), glm::abs(worldBounds_.hi - cone.apex));
        second = {Coverage::Marginal, std::max(cone.tMin, own.tFar), std::min(cone.tMax, padUp(glm::length(far))),
                  false};
    } else if (!clip_->flat) {
        PreparedCone beyond = cone;
        beyond.tMin = std::max(cone.tMin, own.tFar);
        second = classifyOwn(beyond);
        // A box's later crossings are where the rays leave it: its answer
        // from inside says only Marginal over its whole depth.
        if (const Box* box = std::get_if<Box>(&shape_); box && second.coverage == Coverage::Marginal) {
            const auto [lower, upper] = boxExits(*box, frame_, cone);
            if (lower <= upper) {
                second.tNear = std::max(second.tNear, lower);
                second.tFar = std::min(second.tFar, upper);
                if (second.tNear > second.tFar) second = {};
            }
        }
    }
    return clip_->restrict(own, second, cone, [this](const PreparedCone& part) { return classifyOwn(part); });
}

ConeClass Primitive::classifyOwn(const PreparedCone& cone) const {
    if (!cone.valid) [[unlikely]]
        return {Coverage::Marginal, 0.0, kInfinity, false};
    if (cone.tMin > cone.tMax) [[unlikely]]
        return {};
    if (frame_.kind == LocalFrame::Kind::Translate) return classifyRigid<false>(cone);
    if (frame_.kind == LocalFrame::Kind::Similarity) return classifyRigid<true>(cone);
    return classifyGeneral(cone);
}

// Translations and similarities carry the cone over exactly: the apex and
// the axis are mapped (the axis by the rotation alone), the half-angle is
// kept and distances scale by localPerWorld.
template <bool kScaled>
ConeClass Primitive::classifyRigid(const PreparedCone& cone) const {
    LocalCone local;
    if constexpr (kScaled) {
        local.apex = frame_.localFromWorld * cone.apex + frame_.localOffset;
        local.axis = frame_.localRotation * cone.axis;
    } else {
        local.apex = cone.apex + frame_.localOffset;
        local.axis = cone.axis;
    }
    local.cosHalf = cone.cosHalf;
    local.sinHalf = cone.sinHalf;
    local.creases = cone.creases;
    const double absTol = kPositionTolerance * (l1Norm(local.apex) + sphereTolerance_);
    local.absTol = absTol;  // the range is set by the shape (classifyRanging)
    const double t0 = kScaled ? cone.tMin * frame_.localPerWorld : cone.tMin;
    const double t1 = kScaled ? cone.tMax * frame_.localPerWorld : cone.tMax;
    const RigidBounds back{absTol, kScaled ? frame_.worldPerLocal : 1.0, cone.tMin, cone.tMax};
    // One jump on the shape. Each shape sets the local range [t0, t1]
    // itself: a fast path that needs none (the box's, the flat shapes')
    // answers through `back` in world units first (classifyRanging).
    const auto ranging = [&](const auto& shape) { return shape.classifyRanging(local, t0, t1, back); };
    return primitive_detail::jump<ConeClass>(shape_, ranging);
}

// Under a non-uniform scale or a shear the cone becomes elliptic in the local
// frame. It is bounded there by a circular cone around the image of its axis,
// and since t is no longer a local distance, each world ray's local range is
// [tMin L, tMax L] with L = |A d| between Lmin and Lmax: the shape classifies
// the union of those ranges, and a Full answer stands only if its depth bounds
// fall in every ray's own range (docs/geometry.md).
ConeClass Primitive::classifyGeneral(const PreparedCone& cone) const {
    // An ellipsoid's commonest answers need no bounding cone either (Sphere).
    if (const Sphere* sphere = std::get_if<Sphere>(&shape_))
        if (const auto out = sphere->classifyAcrossScale(cone, frame_)) return *out;
    const Mat3& a = frame_.localFromWorld;
    const Vec3 aAxis = a * cone.axis;
    const double la2 = glm::dot(aAxis, aAxis);
    // The root and the reciprocal side by side, not one after the other.
    const double la = std::sqrt(la2);
    const double invLa2 = 1.0 / la2;
    const double invLa = la * invLa2;
    const Vec3 axis = aAxis * invLa;
    // With u, v unit across the world axis, A u = qu + pu axis and
    // A v = qv + pv axis: tau = |(pu, pv)| is the length of A^T axis off the
    // world axis, i.e. |G a - la^2 a| / la (G = A^T A, kept with the frame;
    // computed as a vector, without cancellation), and the Gram matrix of
    // (qu, qv) has trace tr(G) - la^2 - tau^2 and determinant
    // det(A)^2 / la^2, so its larger eigenvalue sigmaPerp^2 needs no basis.
    // All of it is kept multiplied by la^2 (tau la = |G a - la^2 a|), so that
    // the chain to the local angle is two roots and a division.
    const Vec3 back = frame_.gram * cone.axis - la2 * cone.axis;  // la A^T axis, off the world axis
    const double back2 = glm::dot(back, back);                   // (tau la)^2
    const double tauLa = std::sqrt(back2);
    const double trace = frame_.gramTrace;
    // Rounding: the trace's difference is off by a few ulps of trace la^2,
    // the discriminant by a few ulps of trace la^2 sum; both are padded upward.
    const double sum = std::max(0.0, (trace - la2) * la2 - back2) + kTensOfUlps * trace * la2;  // la^2 (...)
    const double product = frame_.gramDeterminant * la2;                                          // la^4 (...)
    const double spread = std::max(0.0, sum * sum - 4.0 * product) + kHundredsOfUlps * trace * la2 * sum;
    const double sigmaPerp2 = 0.5 * (sum + std::sqrt(spread));  // la^2 sigmaPerp^2
    const double c = cone.cosHalf, s = cone.sinHalf;

    LocalCone local;
    local.apex = a * cone.apex + frame_.localOffset;
    local.axis = axis;
    local.creases = cone.creases;
    // A direction at angle phi <= theta from the axis maps to one whose
    // tangent from the new axis is at most tan(phi) sigmaPerp / (la - tan(phi) tau),
    // tl = s sigmaPerp / den: cos = den / |(den, s sigmaPerp)|, sin = tl cos
    // (den and s sigmaPerp times la here; the norm's square from sigmaPerp^2,
    // so that its root does not wait for sigmaPerp's).
    const double den = c * la2 - s * tauLa;  // la (c la - s tau)
    local.cosHalf = -1.0;
    local.sinHalf = 0.0;
    if (c > 0.0 && den > 0.0) {
        const double pad = 1.0 + kThousandsOfUlps;  // as padUp, squared below
        const double lift = s * std::sqrt(sigmaPerp2) * pad + kPositiveFloor * den;
        const double norm = std::sqrt(den * den + (s * s) * sigmaPerp2 * (pad * pad));
        local.cosHalf = den / norm;
        local.sinHalf = lift / norm;
    }
    // Bounds on L = |A d| over the cone: |A(d - axis)| <= 2 sin(theta/2) sigmaMax,
    // and 2 sin(theta/2) = s / sqrt((1 + c) / 2) <= s (1 + (sqrt(2) - 1)(1 - c))
    // for c >= 0 (the reciprocal root is convex).
    const double chord = c >= 0.0 ? s * (1.0 + 0.41421356237309515 * (1.0 - c)) * (1.0 + kFewUlps)
                         : c > -1.0 ? s / std::sqrt(0.5 * (1.0 + c))
                                    : 2.0;
    double lMin = std::max(frame_.sigmaMin, la - chord * frame_.sigmaMax);
    if (c > 0.0) lMin = std::max(lMin, den * invLa);
    const double lMax = std::min(frame_.sigmaMax, la + chord * frame_.sigmaMax);
    // Divided by below; the reciprocals are ready while the shape works.
    const double invLMin = 1.0 / lMin, invLMax = 1.0 / lMax;
    const double absTol = kPositionTolerance * (l1Norm(local.apex) + sphereTolerance_);
    local.setRange(cone.tMin * lMin, cone.tMax * lMax, absTol);

    ConeClass out = visit([&](const auto& shape) { return shape.classify(local); });
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
            out.creaseParts = 0;
        }
    }
    double farBound = kInfinity;
    if (firstHitKept) farBound = (out.tFar + tolFar) * invLMin;
    else if (bounded())
        farBound = (glm::length(local.apex - localSphere_.center) + localSphere_.radius) * invLMin;
    out.tNear = std::max(cone.tMin, (out.tNear - tolNear) * invLMax);
    out.tFar = std::min(cone.tMax, farBound);
    return out;
}

std::optional<TranslatedSphere> Primitive::translatedSphere() const {
    const Sphere* sphere = std::get_if<Sphere>(&shape_);
    if (!sphere || frame_.kind != LocalFrame::Kind::Translate || clip_) return std::nullopt;
    return TranslatedSphere{frame_.localOffset, sphere->radius()};
}

bool Primitive::convex() const {
    if (clip_) return false;  // a part of a surface
    return visit([](const auto& shape) { return shape.convex(); });
}

bool Primitive::raysLeave(const Vec3& worldOrigin, const Vec3* directions, int count) const {
    if (count < 1 || count > LocalRays::kMaxDirections) return false;
    LocalRays rays;
    rays.origin = frame_.pointToLocal(worldOrigin);
    rays.count = count;
    for (int i = 0; i < count; ++i)
        rays.directions[i] =
            frame_.kind == LocalFrame::Kind::Translate ? directions[i] : frame_.localFromWorld * directions[i];
    return visit([&](const auto& shape) { return shape.raysLeave(rays); });
}

bool Primitive::outside(const BeamHull& hull) const {
    if (bounded()) return hull.missesBox(worldBounds_);
    return visit([&]<class S>(const S& shape) {
        if constexpr (std::is_same_v<S, Plane>) {
            return hull.missesPlane(frame_.normalToWorld(shape.normal()),
                                    frame_.pointToWorld(shape.distance() * shape.normal()));
        } else {
            return false;
        }
    });
}

bool Primitive::keptWithin(const Primitive& solid, const PreparedCone& cone) const {
    // Leaves of one object (made with or without a shared solid).
    if (!clip_ || !solid.clip_ || clip_->solid->tree != solid.clip_->solid->tree ||
        !(clip_->solid->worldFromObject == solid.clip_->solid->worldFromObject))
        return false;
    const CsgSolid& whole = *clip_->solid;
    const std::uint32_t node = solid.clip_->leafNode;
    const CsgSolid::Node& leaf = whole.nodes[node];
    // The region is the leaf's own closed convex surface (not an open tube),
    // not inverted.
    if (leaf.flip || leaf.region < 0 || !solid.visit([](const auto& s) { return s.convex(); })) return false;
    const Primitive& region = whole.regions[static_cast<std::size_t>(leaf.region)];
    if (!region.bounded()) return false;
    // No point of the cone before tMin (a ray starting inside the solid)
    // lies in the solid's box.
    const Bounds3 b = region.worldBounds();
    const Vec3 pad(std::max(cone.tMin, 0.0) + kPositionTolerance * (1.0 + l1Norm(cone.apex)));
    const Vec3 lo = b.lo - pad, hi = b.hi + pad;
    if (cone.apex.x >= lo.x && cone.apex.x <= hi.x && cone.apex.y >= lo.y && cone.apex.y <= hi.y &&
        cone.apex.z >= lo.z && cone.apex.z <= hi.z)
        return false;
    for (const CsgClip::Test& t : clip_->tests)
        if (t.wanted && t.except != node && whole.nodes[t.node].all)
            for (std::uint32_t c : whole.nodes[t.node].children)
                if (c == node) return true;
    return false;
}

namespace {

// Over the directions d of a cone, the range of u.d for a unit u, padded.
std::pair<double, double> dotRange(const Vec3& u, const PreparedCone& cone) {
    const double c = glm::dot(u, cone.axis), s = glm::length(glm::cross(u, cone.axis));
    const double pad = kThousandsOfUlps;
    // cos(psi + h) and cos(max(psi - h, 0)), psi the angle from u to the axis.
    const double lo = c * cone.cosHalf - s * cone.sinHalf;
    const double wider = c * cone.cosHalf + s * cone.sinHalf;
    const bool throughU = c >= 0.0 && s * cone.cosHalf <= c * cone.sinHalf;  // psi <= h
    const bool throughMinusU = c <= 0.0 && s * cone.cosHalf <= -c * cone.sinHalf;  // pi - psi <= h
    return {throughMinusU ? -1.0 : lo - pad, throughU ? 1.0 : wider + pad};
}

// The least depth at which a ray from `apex` along a direction d with
// w.d >= b (w = centre - apex, |w| = rho) leaves the ball of radius r about
// `centre` (a sphere, or a cylinder's cross-section with w across its axis):
// the larger root of t^2 - 2 (w.d) t + rho^2 - r^2 = 0, which grows with
// w.d, at least b + sqrt(b^2 - (rho^2 - r^2)) (a cylinder's side: the
// larger root of |d_across|^2 t^2 - 2 (w.d) t + rho^2 - r^2, with
// |d_across| <= 1, is larger still). 0 where the apex is outside and b <= 0.
double leastExit(double b, double rho, double r) {
    const double k = (rho - r) * (rho + r);
    if (k < 0.0) return b + std::sqrt(b * b - k);  // from inside: every ray leaves
    if (!(b > 0.0)) return 0.0;
    const double q = b * b - k;
    return q > 0.0 ? b + std::sqrt(q) : b;
}

// How far a ray must head away from the centre (the cosine to the plane
// holding the ball at the apex) to be taken as leaving it.
constexpr double kAway = 1e-6;

// Whether an apex at `rho` from the centre (or axis) lies on the surface of
// radius r closely enough for the sphere's or side's bounds: k = rho^2 - r^2
// so small that a ray heading in crosses the surface first (outside) before
// tMin / 2 (t <= k / (w.d), and w.d >= tMin / 2 wherever the exits' bound
// passes tMin), and one heading away (w.d <= -kAway rho) leaves it (inside)
// within tMin / 2 (t <= |k| / (2 kAway rho)).
bool onSurface(double rho, double r, double tMin) {
    const double k = std::abs((rho - r) * (rho + r));
    return k <= 0.25 * tMin * tMin && k <= kAway * rho * tMin;
}

}  // namespace

std::optional<ConeClass> Primitive::exitsClass(const PreparedCone& cone) const {
    if (!cone.valid || !bounded_) return std::nullopt;
    const Vec3& apex = cone.apex;
    const double scale = 1.0 + l1Norm(apex) + l1Norm(worldBounds_.lo) + l1Norm(worldBounds_.hi);
    const double tol = kPositionTolerance * scale;
    // A ray counted from the apex itself would meet the surface there.
    if (!(cone.tMin > 1e3 * tol)) return std::nullopt;
    const bool rigid = frame_.kind != LocalFrame::Kind::General;
    const double worldPerLocal = frame_.kind == LocalFrame::Kind::Similarity ? frame_.worldPerLocal : 1.0;
    // The exits' depths: [lower, upper] (lower = -inf where unknown).
    double lower = -kInfinity, upper = kInfinity;
    bool known = false;
    if (const Box* box = std::get_if<Box>(&shape_)) {
        // An apex outside the box (by rounding) may see a ray enter it: only
        // before tMin, where every ray heading in along an axis it lies
        // outside of gains the gap by then.
        if (!(cone.cosHalf > 0.0)) return std::nullopt;
        const Vec3 a = frame_.pointToLocal(apex);
        for (int i = 0; i < 3; ++i) {
            const double below = box->lo()[i] - a[i], above = a[i] - box->hi()[i];
            if (!(below > 0.0) && !(above > 0.0)) continue;
            const auto [loV, hiV] = localSpeeds(frame_, cone, i);
            const double gap = std::max(below, above) * (1.0 + 1e-9);
            const double needed = gap / (0.5 * cone.tMin);
            const bool entersSoon = below > 0.0 ? (hiV <= 0.0 || loV >= needed) : (loV >= 0.0 || hiV <= -needed);
            if (!entersSoon) return std::nullopt;
        }
        const auto [lo, hi] = boxExits(*box, frame_, cone);
        if (lo > hi) return std::nullopt;
        lower = lo;
        upper = hi;
        known = true;
    } else if (const Sphere* sphere = std::get_if<Sphere>(&shape_); sphere && rigid) {
        const Vec3 w = frame_.pointToWorld(Vec3(0.0)) - apex;
        const double rho = glm::length(w), r = sphere->radius() * worldPerLocal;
        const bool surface = onSurface(rho, r, cone.tMin);
        if (!(rho > 0.0) || !(surface || rho < r)) return std::nullopt;
        const auto [dLo, dHi] = dotRange(w / rho, cone);
        // Every ray heads out of the ball (away from the centre past the
        // plane that holds it at the apex): it never meets the sphere.
        if (surface && dHi < -kAway) return ConeClass{};
        lower = leastExit(rho * dLo, rho, r) * (1.0 - 1e-9) - tol;
        known = true;
    } else if (const Cylinder* cylinder = std::get_if<Cylinder>(&shape_);
               cylinder && rigid && !cylinder->canShadowItself()) {
        const Vec3 p0 = frame_.pointToWorld(Vec3(0.0));
        const Vec3 p1 = frame_.pointToWorld(Vec3(0.0, 0.0, cylinder->frustum().length()));
        const double length = glm::length(p1 - p0);
        if (!(length > 0.0)) return std::nullopt;
        const Vec3 e = (p1 - p0) / length;
        const double along = glm::dot(apex - p0, e);
        const Vec3 w = p0 + along * e - apex;  // to the axis, across it
        const double rho = glm::length(w), r = cylinder->frustum().radiusAt(0.0) * worldPerLocal;
        const bool surface = onSurface(rho, r, cone.tMin);
        if (!(rho > 0.0) || !(surface || rho < r)) return std::nullopt;
        const auto [dLo, dHi] = dotRange(w / rho, cone);
        // The caps: a ray reaches a cap's plane no nearer than the apex's
        // distance to it; a cap the apex lies on (or near) bounds nothing.
        const double toCap = std::min(along, length - along);
        const double side = leastExit(rho * dLo, rho, r);
        // Above the plane holding the cylinder at a point of its side (the
        // side's tangent plane; the apex within the caps' slab).
        if (surface && dHi < -kAway && toCap > tol) return ConeClass{};
        lower = std::min(side, std::max(toCap, 0.0)) * (1.0 - 1e-9) - tol;
        known = true;
    }
    if (!known) return std::nullopt;
    // Every kept crossing lies in the kept part's box.
    const Vec3 far = glm::max(glm::abs(worldBounds_.lo - apex), glm::abs(worldBounds_.hi - apex));
    upper = std::min(upper, padUp(glm::length(far)) + tol);
    lower = std::max(lower, cone.tMin);
    upper = std::min(upper, cone.tMax);
    if (!(lower <= upper)) return ConeClass{};
    const CsgClip::Verdict v = clip_->verdict(lower, upper, cone,
                                              [this](const PreparedCone& part) { return classifyOwn(part); },
                                              CsgClip::kSpanSplits);
    if (v == CsgClip::Verdict::Dropped || v == CsgClip::Verdict::None) return ConeClass{};
    return ConeClass{Coverage::Marginal, lower, upper, false};
}

bool Primitive::canShadowItself() const {
    // An inverted curved leaf's kept part (a hole's wall) faces itself.
    if (clip_ && clip_->inverted && !clip_->flat) return true;
    return visit([](const auto& shape) { return shape.canShadowItself(); });
}

Primitive::SelfOcclusion Primitive::selfOcclusion() const {
    return visit([](const auto& shape) {
        using S = std::decay_t<decltype(shape)>;
        if constexpr (std::is_same_v<S, Plane> || std::is_same_v<S, Disc> || std::is_same_v<S, Polygon> ||
                      std::is_same_v<S, EllipticDisc> || std::is_same_v<S, SmoothTriangle>) {
            return SelfOcclusion::None;
        } else if constexpr (std::is_same_v<S, Sphere> || std::is_same_v<S, Box> ||
                             std::is_same_v<S, Cylinder> || std::is_same_v<S, TruncatedCone>) {
            // Closed (capped), a convex solid; open, a surface that shadows itself.
            return shape.canShadowItself() ? SelfOcclusion::Any : SelfOcclusion::Interior;
        } else {
            return SelfOcclusion::Any;
        }
    });
}

HoldingPlanes Primitive::holdingPlanes(const Vec3& worldPoint) const {
    HoldingPlanes h = visit([&](const auto& shape) { return shape.holdingPlanes(frame_.pointToLocal(worldPoint)); });
    // A part of a solid's surface may show a face that the whole hides.
    if (clip_) h.thinContact = false;
    // local n.x <= d with x = L w + o (L = localFromWorld) is (L^T n).w <= d - n.o.
    for (int i = 0; i < h.count; ++i) {
        HalfSpace& p = h.planes[i];
        const Vec3 n = frame_.kind == LocalFrame::Kind::Translate ? p.normal : p.normal * frame_.localFromWorld;
        const double d = p.offset - glm::dot(p.normal, frame_.localOffset);
        const double len = glm::length(n);
        p = {n / len, d / len};
    }
    return h;
}

double Primitive::support(const Vec3& worldDir) const {
    // max over world x = W y + o of n.x is n.o + the local support along W^T n.
    const Vec3 local =
        frame_.kind == LocalFrame::Kind::Translate ? worldDir : worldDir * frame_.worldFromLocal;
    const double s = visit([&](const auto& shape) { return shape.support(local); });
    return glm::dot(worldDir, frame_.pointToWorld(Vec3(0.0))) + s;
}

const char* Primitive::kindName() const { return name_; }

}  // namespace asos
