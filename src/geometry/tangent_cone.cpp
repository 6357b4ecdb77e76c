#include "asos/geometry/tangent_cone.hpp"

#include "asos/geometry/margins.hpp"

namespace asos {

TangentCone TangentCone::make(const Vec3& point, const Vec3& centre, double radius) {
    TangentCone c;
    const Vec3 toCentre = centre - point;
    c.distance = glm::length(toCentre);
    c.radius = radius;
    c.frame = Frame::around(toCentre / c.distance);
    c.sinAlpha = std::min(1.0, radius / c.distance);
    c.tanAlpha = std::tan(std::asin(c.sinAlpha));
    c.cos2Alpha = std::max(0.0, (c.distance - radius) * (c.distance + radius)) / (c.distance * c.distance);
    return c;
}

double TangentCone::distanceAtRadius(double r, double widen) const {
    const double tanPsi = tanAlpha * r;
    const double cosPsi = 1.0 / std::sqrt(1.0 + tanPsi * tanPsi);
    const double sinPsi = tanPsi * cosPsi;
    const double inside =
        radius * radius - distance * distance * sinPsi * sinPsi - widen * kTensOfUlps * distance * distance;
    return distance * cosPsi - std::sqrt(std::max(0.0, inside));
}

}  // namespace asos
