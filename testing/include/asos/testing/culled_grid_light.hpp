#pragma once
// The classic grid of an area light (render/grid_light.hpp) with the shadow
// rays that one cone test over the whole light decides left out: where
// nothing is in the way of the whole light every point is lit, where one
// object blocks all of it none is. The same samples in less time, for
// references: `asos bench lights` renders its converged references with it,
// plugged in through RenderSettings::areaLightSampler. The renderer's grid
// traces every ray, as POV-Ray does, so that its figures are the method's.
#include <span>

#include "asos/render/area_light.hpp"

namespace asos {

// What one cone test over the whole light (from the point, as the ASOS
// beam's detection phase) says of every ray toward it: none is blocked, all
// are, or it cannot tell.
enum class WholeLight { Lit, Blocked, Partial };
WholeLight wholeLightVisibility(const Scene& scene, const LightModel& model, const AreaLightQuery& query,
                                RenderCounters& counters);

// gridAreaLightSamples' samples, without the rays wholeLightVisibility
// decides (adaptive sampling, whose choices depend on the rays, traces them
// all). An AreaLightSampler.
std::span<const LightSample> culledGridAreaLightSamples(const Scene& scene, const LightModel& model,
                                                        const AreaLightQuery& query, AreaLightScratch& scratch,
                                                        RenderCounters& counters);

}  // namespace asos
