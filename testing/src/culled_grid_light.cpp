#include "asos/testing/culled_grid_light.hpp"

#include <cstdint>

#include "asos/render/grid_light.hpp"
#include "asos/shapes/local_cone.hpp"

namespace asos {

WholeLight wholeLightVisibility(const Scene& scene, const LightModel& model, const AreaLightQuery& q,
                                RenderCounters& counters) {
    WholeLight answer = WholeLight::Partial;
    withAreaForm(model.form, [&](const auto& light) {
        const auto beams = light.beamFrom(q.point, kPovShadowTolerance);
        if (!beams) return;
        const LightPiece root = beams->root();
        const PreparedCone prepared(root.cone);
        const double nearestLight = beams->nearestLightDistance(root) - kPovShadowTolerance;
        bool any = false, blocked = false;
        scene.coneCandidates(root.cone, [&](std::uint32_t object) {
            if (blocked || scene.object(object).noShadow) return;
            if (object == q.shadedObject && !q.shadedCanSelfShadow) return;
            ++counters.coneTests;
            const ConeClass k = scene.primitive(object).classify(prepared);
            if (k.coverage == Coverage::Miss) return;
            any = true;
            blocked = k.coverage == Coverage::Full && k.tFar < nearestLight;
        });
        answer = blocked ? WholeLight::Blocked : (any ? WholeLight::Partial : WholeLight::Lit);
    });
    return answer;
}

std::span<const LightSample> culledGridAreaLightSamples(const Scene& scene, const LightModel& model,
                                                        const AreaLightQuery& query, AreaLightScratch& scratch,
                                                        RenderCounters& counters) {
    if (!model.shadowless && !model.adaptive) {
        switch (wholeLightVisibility(scene, model, query, counters)) {
            case WholeLight::Lit: {
                // Nothing shadows the light here: its samples are a
                // shadowless light's, without a ray.
                LightModel unshadowed = model;
                unshadowed.shadowless = true;
                return gridAreaLightSamples(scene, unshadowed, query, scratch, counters);
            }
            case WholeLight::Blocked: scratch.samples.clear(); return scratch.samples;
            case WholeLight::Partial: break;
        }
    }
    return gridAreaLightSamples(scene, model, query, scratch, counters);
}

}  // namespace asos
