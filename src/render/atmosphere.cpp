#include "asos/render/atmosphere.hpp"

#include <algorithm>
#include <cmath>

#include "asos/render/pov_noise.hpp"
#include "asos/render/shading.hpp"
#include "asos/scene/pov_tolerances.hpp"

namespace asos {

namespace {

// The fraction of `depth` that turbulence leaves of a fog's width: POV-Ray
// moves nothing, it thins the fog by its turbulence at one point (the
// middle of the ray's stretch), the less the deeper the fog.
double turbulentWidth(const Fog& fog, const Vec3& middle, double width, int generator) {
    if (!fog.turbulent) return width;
    const Vec3 p = middle * fog.turbulence;
    const double k = std::exp(-width / fog.distance);
    const double t = PovNoise::tables().turbulence(p, fog.octaves, fog.omega, fog.lambda, generator);
    return width * (1.0 - k * std::min(1.0, t * fog.turbDepth));
}

// The mean density of POV-Ray's ground fog between heights `start` and
// `end` (in units of fog_alt above fog_offset): 1 below 0, 1 / (1 + h^2)
// above, whose integral is atan.
double groundFogDensity(double start, double end) {
    if (start <= 0.0) return end <= 0.0 ? 1.0 : (std::atan(end) - start) / (end - start);
    if (end <= 0.0) return (std::atan(start) - end) / (start - end);
    const double delta = start - end;
    if (std::fabs(delta) > kPovEpsilon) return (std::atan(start) - std::atan(end)) / delta;
    return 1.0 / (start * start + 1.0);
}

}  // namespace

double fogTransmittance(const Fog& fog, const Ray& ray, double depth, int generator) {
    if (fog.type != 2) {
        const double width = turbulentWidth(fog, ray.origin + ray.dir * (0.5 * depth), depth, generator);
        return std::exp(-width / fog.distance);
    }
    const Vec3 p1 = ray.origin;
    const Vec3 p2 = p1 + ray.dir * depth;
    const double start = (glm::dot(p1, fog.up) - fog.offset) / fog.alt;
    const double end = (glm::dot(p2, fog.up) - fog.offset) / fog.alt;
    const double density = groundFogDensity(start, end);
    const double width = turbulentWidth(fog, 0.5 * (p1 + p2), depth, generator);
    return std::exp(-width * density / fog.distance);
}

Atmosphere::Atmosphere(const SceneDescription& scene) : scene_(scene), background_(backgroundColor(scene)) {
    for (const Fog& f : scene.fogs)
        if (std::fabs(f.distance) > kPovEpsilon) fogs_.push_back(f);
    if (scene.skySphere)
        for (const Pigment& p : scene.skySphere->pigments) skyVaries_ = skyVaries_ || p.kind != Pigment::Kind::Solid;
    for (const Fog& f : fogs_) skyVaries_ = skyVaries_ || f.type == 2;
}

Vec3 Atmosphere::sky(const Vec3& unitDirection) const {
    if (!scene_.skySphere) return background_;
    const SkySphere& s = *scene_.skySphere;
    // The direction as a point on the unit sphere, taken back through the
    // sphere's transform (translation included, as POV-Ray's MInvTransPoint).
    const Vec3 p(s.worldFromSky.inverseMatrix() * Vec4(unitDirection, 1.0));
    Vec3 col(0.0);
    if (scene_.version >= 3.7) {
        // 3.7: the pigments layered as a layered texture on a real sphere,
        // the last written on top, each letting through its filtered and
        // transmitted light; the background under them all.
        Vec3 through(1.0);
        for (auto it = s.pigments.rbegin(); it != s.pigments.rend(); ++it) {
            const Color c = evaluatePigment(*it, p);
            col += c.rgb * (1.0 - c.filter - c.transmit) * through * s.emission;
            through *= c.rgb * c.filter + Vec3(c.transmit);
        }
        return col + background_ * through;
    }
    // Before 3.7 (POV-Ray 3.6's arithmetic, which 3.7 keeps for such scenes):
    // each layer weighted by what the layers above let through in all, the
    // filter of their product tinting the background.
    Vec3 filterRgb(1.0);
    double filter = 1.0, transmit = 1.0, trans = 1.0;
    for (auto it = s.pigments.rbegin(); it != s.pigments.rend(); ++it) {
        const Color c = evaluatePigment(*it, p);
        col += c.rgb * (trans * (1.0 - c.filter - c.transmit));
        filterRgb *= c.rgb;
        filter *= c.filter;
        transmit *= c.transmit;
        trans = std::fabs(filter) + std::fabs(transmit);
    }
    return col * s.emission + background_ * (filterRgb * filter + Vec3(transmit));
}

Vec3 Atmosphere::fogged(const Vec3& colour, const Ray& ray, double depth) const {
    if (fogs_.empty()) return colour;
    Vec3 attenuation(1.0), added(0.0);
    for (const Fog& fog : fogs_) {
        // Its colour's transmit is the least it lets through.
        const double att = std::max(fogTransmittance(fog, ray, depth, scene_.globals.noiseGenerator), fog.color.transmit);
        attenuation *= att * ((1.0 - fog.color.filter) + fog.color.filter * fog.color.rgb);
        added += (1.0 - att) * fog.color.rgb;
    }
    return added + attenuation * colour;
}

}  // namespace asos
