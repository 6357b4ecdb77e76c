#include "asos/lights/oriented_disc_light.hpp"

namespace asos {

Frame povrayOrientFrame(const Vec3& w) {
    // POV-Ray's choice: the horizon's z unless w is too close to it.
    const Vec3 other = std::abs(std::abs(w.z) - 1.0) < 0.01 ? Vec3(0.0, 1.0, 0.0) : Vec3(0.0, 0.0, 1.0);
    const Vec3 u = glm::normalize(glm::cross(w, other));
    const Vec3 v = glm::normalize(glm::cross(w, u));
    return {u, v, w};
}

bool OrientedDiscLight::beamHolds(const Vec3& apex, const Vec3& p) const {
    const Vec3 toCentre = centre - apex;
    const double distance = glm::length(toCentre);
    if (!(distance > 0.0)) return false;
    return angleBetween(p - apex, toCentre) <= std::atan(radius / distance);
}

std::optional<OrientedDiscLight::Beam> OrientedDiscLight::beamFrom(const Vec3& apex, double tMin) const {
    const Vec3 toCentre = centre - apex;
    const double distance = glm::length(toCentre);
    if (!(distance > 0.0) || !(radius > 0.0)) return std::nullopt;
    const Frame frame = povrayOrientFrame(toCentre / distance);
    return Beam::make(apex, tMin, FacingDisc::make(frame, distance, radius));
}

std::optional<OrientedDiscLight::GridPoints> OrientedDiscLight::gridFrom(const Vec3& point) const {
    const Vec3 toCentre = centre - point;
    const double distance = glm::length(toCentre);
    if (!(distance > 0.0)) return std::nullopt;
    return GridPoints(*this, point, povrayOrientFrame(toCentre / distance));
}

}  // namespace asos
