#include "asos/render/ray_tracer.hpp"

#include "asos/render/transparent_shadow.hpp"

#include <algorithm>
#include <cmath>

namespace asos {

Vec3 RayTracer::radiance(const Ray& ray, int depth, double weight, RenderCounters& counters,
                         const LightContext& context) const {
    return radiance(nearestHit(ray), ray, depth, weight, counters, context);
}

Vec3 RayTracer::radiance(const std::optional<SurfaceHit>& hit, const Ray& ray, int depth,
                         double weight, RenderCounters& counters, const LightContext& context) const {
    if (!hit) return atmosphere_.miss(ray);
    return atmosphere_.fogged(shade(*hit, ray, depth, weight, counters, context), ray, hit->t);
}

Transmitted RayTracer::transmitted(const SurfaceHit& hit, const Ray& ray, int depth, const Vec3& topNormal,
                                   double weight, RenderCounters& counters, const LightContext& context) const {
    const Object& object = scene_.object(static_cast<std::uint32_t>(hit.objectIndex));
    const Vec3 d = glm::normalize(ray.dir);
    const Crossing crossing = cross(context.inside, object);
    LightContext beyond = context.reflected(depth);
    beyond.inside = crossing.beyond;
    ++counters.reflectedRays;
    Transmitted out;
    // Refracted with the ior ratio `ior`, or reflected whole.
    const auto refract = [&](double ior, const LightContext& through) {
        Transmitted t;
        if (const std::optional<Vec3> refracted = refractedDirection(d, topNormal, ior)) {
            t.colour = radiance(Ray{hit.position, *refracted}, depth + 1, weight, counters, through);
        } else {
            // Total internal reflection: the mirror ray stays inside.
            const Vec3 mirror = mirrorDirection(d, topNormal, facingNormal(hit.normal, d));
            t.colour = radiance(Ray{hit.position, mirror}, depth + 1, weight, counters, context.reflected(depth));
            t.totalReflection = true;
        }
        return t;
    };
    const bool dispersive = std::fabs(crossing.dispersionRatio - 1.0) >= 1e-10;
    if (std::fabs(crossing.iorRatio - 1.0) < 1e-10 && !dispersive) {
        // The same ior on both sides: the ray goes on, at the same level
        // (POV-Ray's continued ray).
        out.colour = radiance(Ray{hit.position, d}, depth, weight, counters, beyond);
    } else if (!dispersive) {
        out = refract(crossing.iorRatio, beyond);
    } else if (context.band.wavelength != 0.0f) {
        // A ray of one band already: refracted with that band's ior.
        out = refract(context.band.ior(crossing.iorRatio, crossing.dispersionRatio), beyond);
    } else {
        // Dispersion: one refracted ray a band, each of its hue, averaged
        // (POV-Ray's ComputeRefraction); never a total reflection as a whole.
        const auto bands = static_cast<unsigned>(crossing.bands);
        for (unsigned i = 0; i < bands; ++i) {
            LightContext band = beyond;
            band.band = SpectralBand::of(i, bands);
            band.key = mix64(beyond.key ^ (std::uint64_t(i + 1) << 48));
            out.colour += refract(band.band.ior(crossing.iorRatio, crossing.dispersionRatio), band).colour *
                          band.band.hue();
        }
        out.colour /= static_cast<double>(bands);
    }
    // The fade of the inside the ray came through to this hit.
    if (context.inside.contains(interiorKey(object)))
        out.colour *= fadeThrough(interiorOf(object), hit.t * glm::length(ray.dir), true);
    return out;
}

Vec3 RayTracer::shade(const SurfaceHit& hit, const Ray& ray, int depth, double weight,
                      RenderCounters& counters, const LightContext& context) const {
    // Without the caller's buffers, area lights use some of their own here
    // (and in the reflections below).
    std::optional<AreaLightScratch> own;
    LightContext local = context;
    LightSample storage;
    return shadeWith(
        hit, ray, depth, weight,
        [&](const ShadingPoint& p) -> std::span<const LightSample> {
            if (!lights_[static_cast<std::size_t>(p.lightIndex)].isArea())
                return plainLightSample(p, storage, counters, local.inside);
            if (!local.scratch) local.scratch = &own.emplace();
            return areaLightSamples(p, local, counters);
        },
        counters, local);
}

std::span<const LightSample> RayTracer::areaLightSamples(const ShadingPoint& point,
                                                         const LightContext& context,
                                                         RenderCounters& counters) const {
    AreaLightQuery q;
    q.lightIndex = static_cast<std::size_t>(point.lightIndex);
    q.point = point.position;
    q.normal = point.normal;
    q.outward = point.hit->normal;
    q.shadedObject = static_cast<std::uint32_t>(point.hit->objectIndex);
    // As for point lights: only the inner side of an open tube (its normal
    // turned toward the viewer points inward) can be in its own shadow.
    q.shadedCanSelfShadow = scene_.primitive(q.shadedObject).canShadowItself() &&
                            glm::dot(point.normal, point.hit->normal) < 0.0;
    q.rng = context.rng;
    q.key = context.key;
    q.footprint = context.footprint;
    q.inside = &context.inside;
    // Diffuse only: every layer's finish (their samples are shared).
    const Texture& texture = textureOf(scene_.object(q.shadedObject));
    auto diffuseOnly = [](const Finish& f) {
        return f.brilliance == 1.0 && !(f.phong > 0.0) && !(f.specular > 0.0);
    };
    // A spotlight's samples are each narrowed by their own direction: not merged.
    q.diffuseOnly = diffuseOnly(texture.finish) && !(point.light->fadePower > 0.0) &&
                    point.light->type == LightType::Point;
    for (const TextureLayer& layer : texture.above) q.diffuseOnly = q.diffuseOnly && diffuseOnly(layer.finish);
    return asos::areaLightSamples(scene_, lights_, q, *context.scratch, counters);
}

bool RayTracer::shadowRayBlocked(const Vec3& point, const Vec3& lightPosition,
                                 RenderCounters& counters) const {
    const Vec3 d = lightPosition - point;
    const double distance = glm::length(d);
    if (!(distance > 2.0 * kPovShadowTolerance)) return false;
    ++counters.shadowRays;
    return scene_.occluded({point, d / distance}, kPovShadowTolerance,
                           distance - kPovShadowTolerance);
}

Vec3 RayTracer::shadowRayFilter(const Vec3& point, const Vec3& lightPosition,
                                RenderCounters& counters, const InteriorList& inside) const {
    if (shadowRayBlocked(point, lightPosition, counters)) return Vec3(0.0);
    return transparentShadowFilter(scene_, point, lightPosition, counters, inside);
}

std::span<const LightSample> RayTracer::plainLightSample(const ShadingPoint& point,
                                                         LightSample& storage,
                                                         RenderCounters& counters,
                                                         const InteriorList& inside) const {
    const Light& light = *point.light;
    // A parallel light stands where its beam enters for this point.
    const std::optional<LightBeam::Source> source = lightSourceFor(light, point.position);
    if (!source || !facesLight(point.position, point.normal, source->position)) return {};
    const Vec3 through = light.shadowless || source->unshadowed
                             ? Vec3(1.0)
                             : shadowRayFilter(point.position, source->position, counters, inside);
    if (through == Vec3(0.0)) return {};
    storage = pointLightSample(source->position, light.color * through, point.position);
    return {&storage, 1};
}

}  // namespace asos
