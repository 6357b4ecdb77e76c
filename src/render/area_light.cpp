#include "asos/render/area_light.hpp"

#include "asos/render/area_light_shadow.hpp"
#include "asos/render/grid_light.hpp"

namespace asos {

std::span<const LightSample> areaLightSamples(const Scene& scene, const SceneLights& lights,
                                              const AreaLightQuery& query, AreaLightScratch& scratch,
                                              RenderCounters& counters) {
    const LightModel& model = lights[query.lightIndex];
    const LightSetup& setup = lights.setup();
    const std::span<const LightSample> samples =
        setup.sampler                      ? setup.sampler(scene, model, query, scratch, counters)
        : setup.method == LightMethod::Asos ? asosAreaLightSamples(scene, model, setup.apex, query, scratch, counters)
                                            : gridAreaLightSamples(scene, model, query, scratch, counters);
    if (!query.diffuseOnly || samples.size() < 2) return samples;
    return mergeDiffuse(samples, scratch.merged);
}

std::optional<LightSample> DiffuseSum::merged() const {
    const double length = glm::length(sum);
    if (!(length > 0.0) || !(total > 0.0)) return std::nullopt;
    // |sum| / total of the colour: the merged sample's cosine times its
    // colour is the sum of the samples' cosines times their colours.
    return LightSample{sum / length, distance / total, color * (length / total)};
}

std::optional<LightSample> WeightedDiffuseSum::merged(const Vec3& color) const {
    if (count == 1) return LightSample{firstDirection, firstDistance, color * firstWeight};
    // mergeDiffuse weighs by the colours' sums of channels, color-sum x k.
    const double length = glm::length(sum);
    const double channels = color.x + color.y + color.z;
    if (!(length > 0.0) || !(channels * total > 0.0)) return std::nullopt;
    return LightSample{sum / length, distance / total, color * length};
}

std::span<const LightSample> mergeDiffuse(std::span<const LightSample> samples, LightSample& storage) {
    DiffuseSum total;
    for (const LightSample& s : samples) total.add(s);
    const std::optional<LightSample> merged = total.merged();
    if (!merged) return samples;
    storage = *merged;
    return {&storage, 1};
}

Vec3 diffuseIrradiance(std::span<const LightSample> samples, const Vec3& normal) {
    Vec3 sum(0.0);
    for (const LightSample& s : samples) sum += s.color * std::max(0.0, glm::dot(normal, s.direction));
    return sum;
}

}  // namespace asos
