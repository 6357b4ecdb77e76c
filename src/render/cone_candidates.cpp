#include "asos/render/cone_candidates.hpp"

#include <cmath>

#include "asos/geometry/beam.hpp"

namespace asos {

namespace {
// Wider cones than this are not remembered: their lists would be long and
// their containment tests loose.
constexpr double kWidestRemembered = 0.25 * kPi;
}  // namespace

bool ConeCandidateCache::holds(const Cone& cone) const {
    if (!valid_ || cone.apex != wide_.apex || cone.tMin < wide_.tMin || cone.tMax > wide_.tMax)
        return false;
    // Every ray of the cone lies within angle(axes) + halfAngle of the wide
    // axis; the margin covers rounding here and the classifiers' own
    // widening of cones (kConeAngleMargin).
    const double reach = angleBetween(cone.axis, wide_.axis) + cone.halfAngle;
    return reach * (1.0 + 1e-9) + 1e-9 <= wide_.halfAngle;
}

void ConeCandidateCache::remember(const Scene& scene, const Cone& cone) {
    valid_ = false;
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

}  // namespace asos
