#include "asos/render/area_light.hpp"

#include "asos/render/area_light_shadow.hpp"
#include "asos/render/grid_light.hpp"

namespace asos {

std::span<const LightSample> areaLightSamples(const Scene& scene, const SceneLights& lights,
                                              const AreaLightQuery& query, AreaLightScratch& scratch,
                                              RenderCounters& counters) {
    const LightModel& model = lights[query.lightIndex];
    if (lights.setup().method == LightMethod::Asos)
        return asosAreaLightSamples(scene, model, lights.setup().apex, query, scratch, counters);
    return gridAreaLightSamples(scene, model, query, scratch, counters, lights.setup().gridCulling);
}

Vec3 diffuseIrradiance(std::span<const LightSample> samples, const Vec3& normal) {
    Vec3 sum(0.0);
    for (const LightSample& s : samples) sum += s.color * std::max(0.0, glm::dot(normal, s.direction));
    return sum;
}

}  // namespace asos
