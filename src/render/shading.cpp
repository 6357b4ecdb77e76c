#include "asos/render/shading.hpp"

#include <cmath>

#include "asos/lights/light_model.hpp"
#include "asos/render/brick_pattern.hpp"
#include "asos/render/checker_pattern.hpp"
#include "asos/render/map_pattern.hpp"

namespace asos {

Color evaluatePigment(const Pigment& pigment, const Vec3& worldPoint) {
    switch (pigment.kind) {
        case Pigment::Kind::Solid: return pigment.color1;
        case Pigment::Kind::Checker: {
            const Vec3 p(pigment.worldFromPattern.inverseMatrix() * Vec4(worldPoint, 1.0));
            return CheckerPattern().value(p) ? pigment.color2 : pigment.color1;
        }
        case Pigment::Kind::Brick: {
            const Vec3 p(pigment.worldFromPattern.inverseMatrix() * Vec4(worldPoint, 1.0));
            return BrickPattern(pigment.brickSize, pigment.mortar).value(p) ? pigment.color2 : pigment.color1;
        }
        case Pigment::Kind::Gradient: case Pigment::Kind::Radial: case Pigment::Kind::Onion:
        case Pigment::Kind::Marble: case Pigment::Kind::Wood: case Pigment::Kind::Leopard:
        case Pigment::Kind::Bozo: case Pigment::Kind::Spotted: case Pigment::Kind::Granite:
        case Pigment::Kind::Agate: case Pigment::Kind::Crackle: case Pigment::Kind::Bumps: case Pigment::Kind::Dents:
        case Pigment::Kind::Wrinkles: case Pigment::Kind::Ripples: case Pigment::Kind::Waves:
        case Pigment::Kind::Function: {
            const Vec3 p(pigment.worldFromPattern.inverseMatrix() * Vec4(worldPoint, 1.0));
            return colourMapAt(colourMapOf(pigment), mapPatternValue(pigment, p));
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
