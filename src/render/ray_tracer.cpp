#include "asos/render/ray_tracer.hpp"

namespace asos {

Vec3 RayTracer::radiance(const Ray& ray, int depth, double weight, RenderCounters& counters) const {
    const std::optional<SurfaceHit> hit = nearestHit(ray);
    if (!hit) return backgroundColor(description());
    return shade(*hit, ray, depth, weight, counters);
}

Vec3 RayTracer::shade(const SurfaceHit& hit, const Ray& ray, int depth, double weight,
                      RenderCounters& counters) const {
    LightSample storage;
    return shadeWith(
        hit, ray, depth, weight,
        [&](const ShadingPoint& p) { return plainLightSample(p, storage, counters); }, counters);
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

std::span<const LightSample> RayTracer::plainLightSample(const ShadingPoint& point,
                                                         LightSample& storage,
                                                         RenderCounters& counters) const {
    const Light& light = *point.light;
    if (!facesLight(point.position, point.normal, light.position)) return {};
    if (!light.shadowless && shadowRayBlocked(point.position, light.position, counters)) return {};
    storage = pointLightSample(light.position, light.color, point.position);
    return {&storage, 1};
}

}  // namespace asos
