#include "asos/render/shading.hpp"

#include <cmath>

#include "asos/lights/light_model.hpp"
#include "asos/render/brick_pattern.hpp"
#include "asos/render/checker_pattern.hpp"
#include "asos/render/map_pattern.hpp"

namespace asos {

namespace {

Color mix(const Color& a, const Color& b, double f) {
    return Color{a.rgb + f * (b.rgb - a.rgb), a.filter + f * (b.filter - a.filter),
                 a.transmit + f * (b.transmit - a.transmit)};
}

// POV-Ray's pigment_map (PigmentBlendMap::Compute): the entries on either
// side of the value, found as a colour map's are (colourMapAt), each
// evaluated at the pattern-space point, blended linearly.
Color pigmentMapAt(const PigmentMap& map, double value, const Vec3& point) {
    if (value <= map.front().value) return evaluatePigment(*map.front().pigment, point);
    if (value >= map.back().value) return evaluatePigment(*map.back().pigment, point);
    std::size_t i = 1;
    while (value > map[i].value) ++i;
    const PigmentMapEntry& a = map[i - 1];
    const PigmentMapEntry& b = map[i];
    const double f = (value - a.value) / (b.value - a.value);
    return mix(evaluatePigment(*a.pigment, point), evaluatePigment(*b.pigment, point), f);
}

// POV-Ray's average (PigmentBlendMap::ComputeAverage): the entries'
// pigments at the point, weighted by their values, over the sum of the
// weights (which POV-Ray keeps in single precision).
Color pigmentMapAverage(const PigmentMap& map, const Vec3& point) {
    Color sum{};
    float total = 0.0f;
    for (const PigmentMapEntry& e : map) {
        const Color c = evaluatePigment(*e.pigment, point);
        sum.rgb += e.value * c.rgb;
        sum.filter += e.value * c.filter;
        sum.transmit += e.value * c.transmit;
        total += static_cast<float>(e.value);
    }
    const double t = total;
    return Color{sum.rgb / t, sum.filter / t, sum.transmit / t};
}

}  // namespace

Color evaluatePigment(const Pigment& pigment, const Vec3& worldPoint) {
    switch (pigment.kind) {
        case Pigment::Kind::Solid: return pigment.color1;
        case Pigment::Kind::Checker: {
            const Vec3 p(pigment.worldFromPattern.inverseMatrix() * Vec4(worldPoint, 1.0));
            const int index = CheckerPattern().value(p);
            // Of two pigments: the one of the cell, at the pattern-space point.
            if (pigment.pigmentMap) return evaluatePigment(*(*pigment.pigmentMap)[index].pigment, p);
            return index ? pigment.color2 : pigment.color1;
        }
        case Pigment::Kind::Brick: {
            const Vec3 p(pigment.worldFromPattern.inverseMatrix() * Vec4(worldPoint, 1.0));
            const int index = BrickPattern(pigment.brickSize, pigment.mortar).value(p);
            if (pigment.pigmentMap) return evaluatePigment(*(*pigment.pigmentMap)[index].pigment, p);
            return index ? pigment.color2 : pigment.color1;
        }
        case Pigment::Kind::Gradient: case Pigment::Kind::Radial: case Pigment::Kind::Onion:
        case Pigment::Kind::Marble: case Pigment::Kind::Wood: case Pigment::Kind::Leopard:
        case Pigment::Kind::Bozo: case Pigment::Kind::Spotted: case Pigment::Kind::Granite:
        case Pigment::Kind::Agate: case Pigment::Kind::Crackle: case Pigment::Kind::Bumps: case Pigment::Kind::Dents:
        case Pigment::Kind::Wrinkles: case Pigment::Kind::Ripples: case Pigment::Kind::Waves:
        case Pigment::Kind::Function: case Pigment::Kind::Average: {
            const Vec3 p(pigment.worldFromPattern.inverseMatrix() * Vec4(worldPoint, 1.0));
            if (!pigment.pigmentMap) return colourMapAt(colourMapOf(pigment), mapPatternValue(pigment, p));
            // The entries see the point as this pigment's pattern does: after
            // its transform and its turbulence (POV-Ray's Warp_EPoint).
            const Vec3 q = turbulatedPoint(pigment, p);
            if (pigment.kind == Pigment::Kind::Average) return pigmentMapAverage(*pigment.pigmentMap, q);
            return pigmentMapAt(*pigment.pigmentMap, mapPatternValueAt(pigment, q), q);
        }
    }
    return pigment.color1;
}

Vec3 ambientTerm(const Finish& finish, const Vec3& pigment, const Vec3& ambientLight) {
    return pigment * finish.ambient * ambientLight;
}

Vec3 directLight(const Finish& finish, const Vec3& pigment, const Vec3& normal, const Vec3& rayDir,
                 const Light& light, const LightSample& sample, double grain, const Vec3* colour) {
    const Vec3& toLight = sample.direction;
    // Light on the far side of the surface from the viewer lights nothing
    // (POV-Ray: cos_shadow_angle < EPSILON, no double_illuminate).
    const double cosIncidence = glm::dot(normal, toLight);
    if (cosIncidence < kPovEpsilon) return Vec3(0.0);
    const Vec3 lightColor = sample.color * lightFade(light.fadeDistance, light.fadePower, sample.distance);
    if (std::fabs(lightColor.x) <= kPovEpsilon && std::fabs(lightColor.y) <= kPovEpsilon &&
        std::fabs(lightColor.z) <= kPovEpsilon)
        return Vec3(0.0);

    Vec3 result(0.0);
    if (finish.diffuse > 0.0) {
        const double intensity =
            (finish.brilliance != 1.0 ? std::pow(cosIncidence, finish.brilliance) : cosIncidence) *
                finish.diffuse -
            grain;
        result += intensity * pigment * lightColor;
    }
    // POV-Ray's shadowless lights (FILL_LIGHT_SOURCE) give no highlights.
    if (light.shadowless) return result;
    // metallic: the highlights take the surface's colour, less so toward
    // grazing light (ComputePhongColour, ComputeSpecularColour).
    const Vec3 highlight = finish.metallic > 0.0
                               ? lightColor * metallicTint(finish.metallic, cosIncidence, colour ? *colour : pigment)
                               : lightColor;
    if (finish.phong > 0.0) {
        // Phong: the mirror of the eye ray against the light direction.
        const Vec3 mirror = rayDir - 2.0 * glm::dot(rayDir, normal) * normal;
        const double cosMirror = glm::dot(mirror, toLight);
        // POV-Ray skips tiny cosines for large exponents ("rgs" cut-off).
        if (cosMirror > 0.0 && (finish.phongSize < 60.0 || cosMirror > 0.0008))
            result += finish.phong * std::pow(cosMirror, finish.phongSize) * highlight;
    }
    if (finish.specular > 0.0) {
        // Blinn: the halfway vector between the eye and the light.
        const Vec3 halfway = 0.5 * (toLight - rayDir);
        const double length = glm::length(halfway);
        if (length > 0.0) {
            const double cosHalf = glm::dot(halfway, normal) / length;
            if (cosHalf > 0.0) {
                // POV-Ray stores 1/roughness as the exponent; a zero roughness
                // is kept as a zero exponent (it warns "Zero roughness used").
                const double exponent = finish.roughness != 0.0 ? 1.0 / finish.roughness : 0.0;
                result += finish.specular * std::pow(cosHalf, exponent) * highlight;
            }
        }
    }
    return result;
}

}  // namespace asos
