#include "asos/testing/culled_grid_light.hpp"

#include <cstdint>

#include "asos/render/grid_light.hpp"
#include "asos/shapes/local_cone.hpp"

namespace asos {

namespace {

// POV-Ray's emitter: the share of n1 x n2 stratified points of the light's
// square (one uniform in each cell) that plain shadow rays reach; the grid's
// answer where the point sees no beam (in the light's plane or line).
double stratifiedFraction(const Scene& scene, const LightModel& model, const AreaLightQuery& q,
                          AreaLightScratch& scratch, RenderCounters& counters) {
    const int n1 = std::max(model.count1, 1), n2 = std::max(model.count2, 1);
    const std::uint64_t key = mix64(q.key ^ mix64(0x57a7u + q.lightIndex));
    std::optional<double> visible;
    withAreaForm(model.form, [&](const auto& light) {
        const auto beams = light.beamFrom(q.point, kPovShadowTolerance);
        if (!beams) return;
        const LightPiece root = beams->root();
        std::uint64_t lit = 0;
        for (int j = 0; j < n2; ++j)
            for (int i = 0; i < n1; ++i) {
                const Vec2 xi = q.rng.uniform2(SampleStream::LightJitter,
                                               mix64(key ^ (std::uint64_t(j) << 32 | std::uint32_t(i))));
                const BeamRay ray = beams->sample(root, Vec2((i + xi.x) / n1, (j + xi.y) / n2));
                if (!(ray.distance > 2.0 * kPovShadowTolerance)) {
                    ++lit;
                    continue;
                }
                ++counters.shadowRays;
                if (!scene.occluded(ray.ray, kPovShadowTolerance, ray.distance - kPovShadowTolerance)) ++lit;
            }
        visible = double(lit) / (double(n1) * double(n2));
    });
    return visible ? *visible : gridVisibleFraction(scene, model, q, scratch, counters);
}

}  // namespace

WholeLight wholeLightVisibility(const Scene& scene, const LightModel& model, const AreaLightQuery& q,
                                RenderCounters& counters) {
    WholeLight answer = WholeLight::Partial;
    withAreaForm(model.form, [&](const auto& light) {
        const auto beams = light.beamFrom(q.point, kPovShadowTolerance);
        if (!beams) return;
        const LightPiece root = beams->root();
        // The shaded object cannot shadow light above its horizon; with
        // POV-Ray's emitter, light below it counts, and the object may block it.
        if (model.emitter == LightEmitter::Povray &&
            !(angleBetween(q.normal, root.cone.axis) + root.cone.halfAngle < 0.5 * kPi - 1e-9))
            return;
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
    if (model.emitter == LightEmitter::Povray) {
        if (!povrayLightsPoint(model, query)) {
            scratch.samples.clear();
            return scratch.samples;
        }
        double visible = 1.0;
        if (!model.shadowless) {
            switch (wholeLightVisibility(scene, model, query, counters)) {
                case WholeLight::Lit: break;
                case WholeLight::Blocked: visible = 0.0; break;
                case WholeLight::Partial: visible = stratifiedFraction(scene, model, query, scratch, counters); break;
            }
        }
        return povrayAreaLightSamples(model, query, visible, scratch);
    }
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
