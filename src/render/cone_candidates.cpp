#include "asos/render/cone_candidates.hpp"

#include <cmath>

#include "asos/geometry/beam.hpp"
#include "asos/geometry/margins.hpp"

namespace asos {

namespace {
// Wider cones than this are not remembered: their lists would be long and
// their containment tests loose.
constexpr double kWidestRemembered = 0.25 * kPi;

// An angle widened as PreparedCone widens every half-angle (kConeAngleMargin
// radians plus that fraction of the angle), written a (1 + m) + m.
double widened(double angle) { return angle * (1.0 + kConeAngleMargin) + kConeAngleMargin; }
}  // namespace

bool ConeCandidateCache::holds(const Cone& cone) const {
    if (!valid_ || cone.apex != wide_.apex || cone.tMin < wide_.tMin || cone.tMax > wide_.tMax)
        return false;
    // Every ray of the cone lies within angle(axes) + halfAngle of the wide
    // axis; the margin covers rounding here and the classifiers' own
    // widening of cones (kConeAngleMargin).
    const double reach = angleBetween(cone.axis, wide_.axis) + cone.halfAngle;
    return widened(reach) <= wide_.halfAngle;
}

void ConeCandidateCache::remember(const Scene& scene, const Cone& cone) {
    valid_ = false;
    // Plus more than `widened` adds, so that a ray's cone is held by its own.
    const double halfAngle = cone.halfAngle * widen_ + 1e-8;
    if (!(halfAngle < kWidestRemembered) || !std::isfinite(cone.tMin)) return;
    wide_ = cone;
    wide_.halfAngle = halfAngle;
    wide_.tMin = cone.tMin / deepen_;
    wide_.tMax = cone.tMax * deepen_;
    objects_.clear();
    scene.coneCandidates(wide_, [&](std::uint32_t object) { objects_.push_back(object); });
    valid_ = objects_.size() <= maxObjects_;
}

bool BeamCandidateCache::sphereMayMeet(const PreparedCone& cone, const Vec3& center, double radius) {
    // In the plane of the axis and the centre, the cone's lateral boundary is
    // the ray at the half-angle; the centre's distance from the solid is its
    // distance from that ray (or from the apex, behind it). A margin covers
    // rounding, relative to the distances involved (as the classifiers'
    // distance tolerance is).
    const Vec3 v = center - cone.apex;
    const double d2 = glm::dot(v, v);
    const double d = std::sqrt(d2);
    const double margin =
        radius * (1.0 + kConeDistanceTolerance) + kConeDistanceTolerance * (d + l1Norm(cone.apex) + radius);
    if (d - margin > cone.tMax) return false;
    if (d + margin < cone.tMin) return false;
    if (!(cone.cosHalf > 0.0)) return true;  // a half-angle of a right angle or more
    const double along = glm::dot(v, cone.axis);
    const double perp = std::sqrt(std::max(0.0, d2 - along * along));
    const double lateral = perp * cone.cosHalf - along * cone.sinHalf;  // > 0: outside the infinite cone
    const double distance = along * cone.cosHalf + perp * cone.sinHalf >= 0.0 ? lateral : d;
    return distance <= margin;
}

bool BeamCandidateCache::holds(const Cone& cone, const PreparedCone& prepared) const {
    if (!valid_ || !prepared.valid || !(prepared.cosHalf > 0.0)) return false;
    // The beam is a convex cone's part: it lies in the remembered (convex)
    // cone when its apex does, every direction of it is a direction of the
    // remembered cone (angle(axes) + halfAngle <= the remembered one), and it
    // ends within the remembered reach.
    const Vec3 offset = cone.apex - apex_;
    const double distance = glm::length(offset);
    if (!(distance + prepared.tMax <= reach_)) return false;
    if (!(glm::dot(offset, axis_) >= distance * cos_)) return false;
    // cos(remembered - halfAngle), the beam's half-angle widened as the
    // primitives widen it.
    const double least = cos_ * prepared.cosHalf + sin_ * prepared.sinHalf;
    return prepared.sinHalf <= sin_ && glm::dot(prepared.axis, axis_) >= least;
}

void BeamCandidateCache::remember(const Scene& scene, const Cone& cone) {
    valid_ = false;
    scene_ = &scene;
    if (!(cone.halfAngle >= 0.0) || !std::isfinite(cone.tMax)) return;
    // Twice as wide (at least 0.05 more), with the apex set back so that the
    // beams of points within a quarter of the spare angle times the reach
    // (rho) fit: such a point's beam turns by about rho / reach.
    const double halfAngle = cone.halfAngle + std::max(cone.halfAngle, 0.05);
    if (!(halfAngle < kWidestRemembered)) return;
    const double spare = halfAngle - cone.halfAngle;
    const double rho = 0.25 * spare * cone.tMax;
    const double setBack = rho / std::tan(0.5 * halfAngle) + rho;
    axis_ = glm::normalize(cone.axis);
    apex_ = cone.apex - setBack * axis_;
    reach_ = setBack + rho + 1.05 * (cone.tMax + rho);
    cos_ = std::cos(halfAngle);
    sin_ = std::sin(halfAngle);
    // The BVH is asked for a slightly larger cone than the one `holds` tests.
    const Cone wide{apex_, axis_, widened(halfAngle), 0.0, reach_ * (1.0 + kConeDistanceTolerance)};
    entries_.clear();
    bool tooMany = false;
    scene.coneCandidates(wide, [&](std::uint32_t object) {
        if (entries_.size() >= kMaxObjects) {
            tooMany = true;
            return;
        }
        const Primitive& p = scene.primitive(object);
        Entry e{object, p.bounded(), Vec3(0.0), 0.0};
        if (e.bounded) {
            const Bounds3 b = p.worldBounds();
            e.center = 0.5 * (b.lo + b.hi);
            e.radius = 0.5 * glm::length(b.hi - b.lo);
            if (!std::isfinite(e.radius)) e.bounded = false;
        }
        entries_.push_back(e);
    });
    valid_ = !tooMany;
}

}  // namespace asos
