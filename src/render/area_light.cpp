#include "asos/render/area_light.hpp"

#include "asos/render/area_light_shadow.hpp"
#include "asos/render/grid_light.hpp"
#include "asos/render/transparent_shadow.hpp"

namespace asos {

namespace {

// POV-Ray's emitter, by the lights' method: the fraction of the light that
// reaches the point, and the samples it makes.
std::span<const LightSample> povraySamples(const Scene& scene, const SceneLights& lights,
                                           const AreaLightQuery& query, AreaLightScratch& scratch,
                                           RenderCounters& counters) {
    const LightModel& model = lights[query.lightIndex];
    if (!povrayLightsPoint(model, query)) {
        scratch.samples.clear();
        return scratch.samples;
    }
    const LightSetup& setup = lights.setup();
    const double visible =
        model.shadowless ? 1.0
        : setup.method == LightMethod::Asos
            ? asosVisibleFraction(scene, model, setup.apex, query, scratch, counters)
            : gridVisibleFraction(scene, model, query, scratch, counters);
    return povrayAreaLightSamples(model, query, visible, scratch);
}

}  // namespace

std::span<const LightSample> areaLightSamples(const Scene& scene, const SceneLights& lights,
                                              const AreaLightQuery& query, AreaLightScratch& scratch,
                                              RenderCounters& counters) {
    const LightModel& model = lights[query.lightIndex];
    const LightSetup& setup = lights.setup();
    const std::span<const LightSample> samples =
        setup.sampler                             ? setup.sampler(scene, model, query, scratch, counters)
        : model.emitter == LightEmitter::Povray   ? povraySamples(scene, lights, query, scratch, counters)
        : setup.method == LightMethod::Asos       ? asosAreaLightSamples(scene, model, setup.apex, query, scratch, counters)
                                                  : gridAreaLightSamples(scene, model, query, scratch, counters);
    // Transparent occluders filter each sample along its own ray (the
    // methods above pass them: Scene::occluded and the beams' candidates).
    std::span<const LightSample> seen = samples;
    if (scene.anyTransparent() && !model.shadowless) {
        scratch.filtered.assign(samples.begin(), samples.end());
        for (LightSample& s : scratch.filtered)
            s.color *= transparentShadowFilter(scene, query.point, query.point + s.direction * s.distance, counters,
                                               query.inside ? *query.inside : InteriorList{});
        seen = scratch.filtered;
    }
    if (!query.diffuseOnly || seen.size() < 2) return seen;
    return mergeDiffuse(seen, scratch.merged);
}

bool povrayLightsPoint(const LightModel& model, const AreaLightQuery& query) {
    if (model.areaIllumination) return true;
    const Vec3 toCentre = model.position - query.point;
    const double distance = glm::length(toCentre);
    return distance > 0.0 && glm::dot(query.normal, toCentre / distance) >= kPovEpsilon;
}

std::span<const LightSample> povrayAreaLightSamples(const LightModel& model, const AreaLightQuery& query,
                                                    double visible, AreaLightScratch& scratch) {
    scratch.samples.clear();
    if (!(visible > 0.0)) return scratch.samples;
    if (!model.areaIllumination) {
        scratch.samples.push_back(pointLightSample(model.position, model.color, query.point, visible));
        return scratch.samples;
    }
    // POV-Ray's full area lighting (trace.cpp, ComputeFullAreaDiffuseLight):
    // every point of its lattice, equally weighted, jittered anew, each
    // faded by its own distance; those behind the surface light nothing.
    const int n1 = std::max(model.count1, 1), n2 = std::max(model.count2, 1);
    const Vec3 colour = model.color * (visible / (double(n1) * double(n2)));
    const std::uint64_t key = mix64(query.key ^ mix64(0x5ade0u + query.lightIndex));
    withAreaForm(model.form, [&](const auto& form) {
        const auto light = form.gridFrom(query.point);
        if (!light) return;
        for (int j = 0; j < n2; ++j)
            for (int i = 0; i < n1; ++i) {
                const Vec2 xi =
                    model.jitter ? query.rng.uniform2(SampleStream::LightJitter,
                                                      mix64(key ^ (std::uint64_t(j) << 32 | std::uint32_t(i)))) -
                                       0.5
                                 : Vec2(0.0);
                const BeamRay ray =
                    light->toward(povrayLatticeFraction(i + xi.x, n1), povrayLatticeFraction(j + xi.y, n2));
                if (glm::dot(query.normal, ray.ray.dir) < kPovEpsilon) continue;
                scratch.samples.push_back({ray.ray.dir, ray.distance, colour});
            }
    });
    return scratch.samples;
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
