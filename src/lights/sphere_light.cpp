#include "asos/lights/sphere_light.hpp"

namespace asos {

namespace {

// Whether `point` lies outside the sphere, past rounding: only then does it
// see a tangent cone.
bool outside(const SphereLight& light, const Vec3& point) {
    return light.radius > 0.0 && glm::length(light.centre - point) > padUp(light.radius);
}

}  // namespace

bool SphereLight::beamHolds(const Vec3& apex, const Vec3& p) const {
    const Vec3 d = p - apex;
    const Vec3 toCentre = centre - apex;
    const double distance = glm::length(toCentre);
    if (!(distance > radius)) return false;
    return angleBetween(d, toCentre) <= std::asin(radius / distance);
}

std::optional<SphereLight::Beam> SphereLight::beamFrom(const Vec3& apex, double tMin) const {
    if (!outside(*this, apex)) return std::nullopt;
    return Beam::make(apex, tMin, TangentCone::make(apex, centre, radius));
}

std::optional<SphereLight::GridPoints> SphereLight::gridFrom(const Vec3& point) const {
    if (!outside(*this, point)) return std::nullopt;
    return GridPoints(TangentCone::make(point, centre, radius), point);
}

}  // namespace asos
