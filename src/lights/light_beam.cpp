#include "asos/lights/light_beam.hpp"

#include <cmath>

#include "asos/scene/pov_tolerances.hpp"

namespace asos {

double povCubicSpline(double low, double high, double pos) {
    if (pos < low) return 0.0;
    if (pos >= high) return 1.0;
    const double t = (pos - low) / (high - low);
    return (3.0 - 2.0 * t) * t * t;
}

double spotlightFactor(double cosTheta, double cosRadius, double cosFalloff, double tightness) {
    if (!(cosTheta > 0.0)) return 0.0;
    double f = std::pow(cosTheta, tightness);
    if (cosRadius > 0.0 && cosTheta < cosRadius) f *= povCubicSpline(cosFalloff, cosRadius, cosTheta);
    return f;
}

double cylinderFactor(double d, double radius, double falloff, double tightness) {
    if (!(d < falloff)) return 0.0;
    const double inside = 1.0 - d / falloff;
    double f = std::pow(inside, tightness);
    if (radius > 0.0 && d > radius) f *= povCubicSpline(0.0, 1.0 - radius / falloff, inside);
    return f;
}

LightBeam LightBeam::of(const Light& light) {
    LightBeam b;
    b.type = light.type;
    b.parallel = light.parallel || light.type == LightType::Cylinder;
    b.position = light.position;
    const Vec3 d = light.pointAt - light.position;
    const double length = glm::length(d);
    b.axis = length > kPovEpsilon ? d / length : d;  // POV-Ray leaves a tiny axis unnormalised
    b.tightness = light.tightness;
    if (light.type == LightType::Spot) {
        constexpr double kDegree = 3.14159265358979323846 / 180.0;
        b.radius = std::cos(light.radius * kDegree);
        b.falloff = std::cos(light.falloff * kDegree);
    } else {
        b.radius = light.radius;
        b.falloff = light.falloff;
    }
    return b;
}

std::optional<LightBeam::Source> LightBeam::sourceFor(const Vec3& point) const {
    if (!parallel) return Source{position, false};
    const double depth = glm::dot(point - position, axis);
    if (depth > 0.0) return Source{point - depth * axis, false};
    if (type != LightType::Point) return std::nullopt;
    return Source{point - axis, true};
}

double LightBeam::factor(const Vec3& point, const Vec3& toLight) const {
    switch (type) {
    case LightType::Point: return 1.0;
    case LightType::Spot: return spotlightFactor(-glm::dot(toLight, axis), radius, falloff, tightness);
    case LightType::Cylinder: {
        const Vec3 v = point - position;
        const double k = glm::dot(v, axis);
        if (!(k > 0.0)) return 0.0;
        return cylinderFactor(glm::length(v - k * axis), radius, falloff, tightness);
    }
    }
    return 1.0;
}

}  // namespace asos
